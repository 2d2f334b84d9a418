// The generic module form: widgets from FieldSpecs, named in the language in
// force, arranged to the form's width, the drawing and the line of help for
// the field being typed in. The values shown, parsed and checked:
// unit_form_values.cpp.
#include "ui/unit_form.h"

#include "ui/core_texts.h"

#include "ui/sketch_view.h"

#include "modules/registry.h"
#include "ui/profile_editor.h"

#include "ui/module_palette.h"

#include <QEvent>
#include <QComboBox>
#include <QCoreApplication>
#include <QKeyEvent>
#include <QGridLayout>
#include <QLabel>
#include <QLineEdit>
#include <QVBoxLayout>

#include <algorithm>

namespace taiwa::ui {

UnitForm::UnitForm(const ModuleKind& kind, QWidget* parent)
    : QWidget(parent), kind_(kind), fields_(fieldsFor(kind)), rows_(fields_.size())
{
    // The form takes the width its column gives it and arranges itself to
    // it (arrange(): labels above the fields when both do not fit beside).
    // Were its minimum the one of labels beside fields, the scroll area
    // would hold it wider than the view, and it would scroll sideways
    // instead of ever learning that it is narrow.
    setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    auto* outer = new QVBoxLayout(this);
    auto* drawing = new QLabel(this);
    const QString prefix = modulePrefix(kind);
    drawing->setObjectName(prefix + ".drawing");
    drawing->setAlignment(Qt::AlignCenter);
    // Never wider than the form: drawn at the width the form gets (resizeEvent).
    drawing->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    drawing->setMinimumWidth(0);
    outer->addWidget(drawing);
    drawing_ = drawing;
    drawDrawing();
    // What the field being typed in is: one line under the drawing.
    help_ = new QLabel(this);
    help_->setObjectName(prefix + ".help");
    help_->setWordWrap(true);
    help_->setStyleSheet("color: #444; font-style: italic;");
    outer->addWidget(help_);
    sketch_ = new SketchView(this);
    sketch_->setObjectName(prefix + ".sketch");
    outer->addWidget(sketch_);
    // Labels beside their fields, or above them when the form is too narrow
    // for both (a 1280-pixel screen, Japanese labels): nothing scrolls
    // sideways (arrange(); a grid, whose height follows wrapped error texts).
    grid_ = new QGridLayout;
    grid_->setColumnStretch(1, 1);
    outer->addLayout(grid_);
    // A turned profile's tables and view, under its few fields.
    if (kind.turnedProfile(kind.makeDefault({}))) {
        drawingWidth_ = 240;
        profile_ = new ProfileEditor(prefix, this);
        outer->addWidget(profile_);
        connect(profile_, &ProfileEditor::edited, this,
                [this](const turning::TurnedProfile& after, const QString& text, const QString& key) {
                    ModuleInput m = current_;
                    if (!kind_.setTurnedProfile(m, after)) return;
                    emit unitEdited(m, text, key);
                });
    }
    outer->addStretch(1);
    // The operator's name for the unit, shown in the unit list, the step list
    // and the sheet; a unit of any module has one.
    name_ = new QLineEdit(this);
    name_->setObjectName(prefix + ".name");
    addRow(QString(), name_, name_);
    connect(name_, &QLineEdit::textEdited, this, [this](const QString& t) { emit nameEdited(t); });
    connect(name_, &QLineEdit::returnPressed, this, [this] { focusNextChild(); });
    connect(name_, &QLineEdit::editingFinished, this, &UnitForm::fieldLeft);
    QWidget* previous = nullptr;
    for (std::size_t i = 0; i < fields_.size(); ++i) {
        const FieldSpec& f = fields_[i];
        const int index = static_cast<int>(i);
        auto* cell = new QWidget(this);
        auto* box = new QVBoxLayout(cell);
        box->setContentsMargins(0, 0, 0, 0);
        box->setSpacing(1);
        QWidget* editor = nullptr;
        Row& row = rows_[i];
        if (f.kind == FieldKind::Code) {
            row.combo = new QComboBox(cell);
            for (const auto& [value, meaning] : f.codes) row.combo->addItem(QString(), value);  // named by nameFields()
            // The meanings are long: the closed box shows their start, the list all of it.
            row.combo->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
            row.combo->setMinimumContentsLength(12);
            connect(row.combo, &QComboBox::activated, this, [this, index](int item) {
                emit edited(index, rows_[static_cast<std::size_t>(index)].combo->itemData(item).toDouble());
            });
            row.combo->installEventFilter(this);
            editor = row.combo;
        } else {
            row.edit = f.isText() ? makeNameEdit(f, cell) : new QLineEdit(cell);
            if (f.isText())  // typed, or a name the completer put in
                connect(row.edit, &QLineEdit::textChanged, this, [this, index](const QString& t) {
                    if (!updating_) emit textEdited(index, t);
                });
            else
                connect(row.edit, &QLineEdit::textEdited, this, [this, index](const QString& t) { onTextEdited(index, t); });
            connect(row.edit, &QLineEdit::returnPressed, this, [this, index] { enterPressed(index); });
            connect(row.edit, &QLineEdit::editingFinished, this, &UnitForm::fieldLeft);
            row.edit->installEventFilter(this);
            editor = row.edit;
        }
        editor->setObjectName(prefix + "." + f.key);
        row.message = new QLabel(cell);
        row.message->setObjectName(prefix + "." + f.key + ".error");
        row.message->setStyleSheet("color: #a00000;");
        row.message->setWordWrap(true);
        row.message->hide();
        box->addWidget(editor);
        box->addWidget(row.message);
        addRow(QString(), cell, editor);
        if (previous) setTabOrder(previous, editor);
        previous = editor;
    }
    nameFields();
}

void UnitForm::nameFields()
{
    const auto translated = [](const QString& source) {
        return QCoreApplication::translate("taiwa::ui::FieldSpec", source.toUtf8().constData());
    };
    name_->setPlaceholderText(tr("optional, e.g. Pocket A"));
    labelled_.front().first->setText(tr("Unit name"));
    for (std::size_t i = 0; i < fields_.size(); ++i) {
        const FieldSpec& f = fields_[i];
        labelled_[i + 1].first->setText(translated(f.label));
        if (QComboBox* combo = rows_[i].combo)
            for (int k = 0; k < static_cast<int>(f.codes.size()) && k < combo->count(); ++k) {
                // "1 – roughing, floor finishing and wall finishing": the code first, as on the drawing.
                const auto& [value, meaning] = f.codes[static_cast<std::size_t>(k)];
                const QString text = QStringLiteral("%1 – %2").arg(value).arg(codeMeaning(meaning.toStdString()));
                combo->setItemText(k, text);
                combo->setItemData(k, text, Qt::ToolTipRole);
            }
        else if (!f.placeholder.isEmpty())
            rows_[i].edit->setPlaceholderText(translated(f.placeholder));
    }
}

void UnitForm::changeEvent(QEvent* e)
{
    QWidget::changeEvent(e);
    if (e->type() != QEvent::LanguageChange || labelled_.empty()) return;
    nameFields();
    showHelp(helpField_);
    drawDrawing();  // its labels are the language's
    arranged_ = false;
    arrange();
}

void UnitForm::setSketch(std::optional<Sketch> sketch) { sketch_->setSketch(std::move(sketch)); }

QString UnitForm::helpText() const { return help_->text(); }

void UnitForm::enterPressed(int field)
{
    // The last field: the operator is done with this unit.
    if (field + 1 == static_cast<int>(rows_.size())) emit lastFieldDone();
    else focusNextChild();
}

void UnitForm::showHelp(int field)
{
    helpField_ = field;
    const FieldSpec* f = field >= 0 && field < static_cast<int>(fields_.size()) ? &fields_[static_cast<std::size_t>(field)] : nullptr;
    help_->setText(f && !f->help.isEmpty() ? QCoreApplication::translate("taiwa::ui::FieldSpec", f->help.toUtf8().constData())
                                           : QString());
    const QString symbol = f ? f->symbol : QString();
    if (symbol == highlighted_) return;
    highlighted_ = symbol;
    drawDrawing();
}

// The drawing's width: its own, at most the room inside the form's margins.
int UnitForm::drawingRoom() const
{
    const QMargins m = layout() ? layout()->contentsMargins() : QMargins();
    return std::max(120, std::min(drawingWidth_, width() - m.left() - m.right()));
}

void UnitForm::drawDrawing()
{
    const int width = drawingRoom();
    drawingShown_ = width;
    drawing_->setPixmap(moduleDrawing(QString::fromUtf8(kind_.drawing()), width, highlighted_));
}

void UnitForm::addRow(const QString& text, QWidget* field, QWidget* buddy)
{
    auto* label = new QLabel(text, this);
    label->setBuddy(buddy);
    labelled_.push_back({label, field});
    const int r = static_cast<int>(labelled_.size()) - 1;
    grid_->addWidget(label, r, 0, Qt::AlignTop | Qt::AlignLeft);
    grid_->addWidget(field, r, 1);
}

void UnitForm::arrange()
{
    int labels = 0, fields = 0;
    for (const auto& [label, field] : labelled_) {
        // The label's width on one line, whether it wraps now or not: a
        // wrapped label's size hint is narrower, and measuring that would
        // put the labels back beside the fields, then above, without end.
        const QMargins lm = label->contentsMargins();
        const int oneLine = label->fontMetrics().horizontalAdvance(label->text()) + 2 * label->margin() + lm.left() + lm.right();
        labels = std::max(labels, oneLine);
        fields = std::max(fields, field->minimumSizeHint().width());
    }
    const QMargins m = layout()->contentsMargins();
    const bool above = labels + grid_->horizontalSpacing() + fields > width() - m.left() - m.right();
    if (above == labelsAbove_ && grid_->count() > 0 && arranged_) return;
    labelsAbove_ = above;
    arranged_ = true;
    for (const auto& [label, field] : labelled_) {
        grid_->removeWidget(label);
        grid_->removeWidget(field);
    }
    for (std::size_t i = 0; i < labelled_.size(); ++i) {
        const int r = static_cast<int>(i);
        labelled_[i].first->setWordWrap(above);  // above its field, a long label wraps rather than widen the form
        if (above) {
            grid_->addWidget(labelled_[i].first, 2 * r, 0, 1, 2);  // a row of its own: its height for its width
            grid_->addWidget(labelled_[i].second, 2 * r + 1, 0, 1, 2);
        } else {
            grid_->addWidget(labelled_[i].first, r, 0, Qt::AlignTop | Qt::AlignLeft);
            grid_->addWidget(labelled_[i].second, r, 1);
        }
    }
}

void UnitForm::layOutNow()
{
    for (const Row& r : rows_)
        if (QLayout* cell = r.message->parentWidget()->layout()) cell->activate();
    for (QWidget* w = this; w; w = w->parentWidget())
        if (w->layout()) w->layout()->activate();
}

void UnitForm::resizeEvent(QResizeEvent* event)
{
    QWidget::resizeEvent(event);
    arrange();
    if (drawingRoom() != drawingShown_) drawDrawing();
}

bool UnitForm::eventFilter(QObject* watched, QEvent* event)
{
    if (event->type() == QEvent::FocusIn) {
        for (std::size_t i = 0; i < rows_.size(); ++i)
            if (watched == rows_[i].edit || watched == rows_[i].combo) showHelp(static_cast<int>(i));
    }
    if (event->type() == QEvent::KeyPress && qobject_cast<QComboBox*>(watched)) {
        const int key = static_cast<QKeyEvent*>(event)->key();
        if (key == Qt::Key_Return || key == Qt::Key_Enter) {  // Enter moves on, as in the line edits
            for (std::size_t r = 0; r < rows_.size(); ++r)
                if (rows_[r].combo == watched) enterPressed(static_cast<int>(r));
            return true;
        }
    }
    if (event->type() == QEvent::ShortcutOverride) {
        auto* key = static_cast<QKeyEvent*>(event);
        if (key->matches(QKeySequence::Undo) || key->matches(QKeySequence::Redo) ||
            key->keyCombination() == QKeyCombination(Qt::ControlModifier | Qt::ShiftModifier, Qt::Key_Z))
            return true;  // not accepted: the window's undo/redo shortcut runs
    }
    return QWidget::eventFilter(watched, event);
}

void UnitForm::focusFirstField()
{
    if (rows_.empty()) return;
    QWidget* first = rows_.front().edit ? static_cast<QWidget*>(rows_.front().edit) : rows_.front().combo;
    first->setFocus(Qt::OtherFocusReason);
    if (rows_.front().edit) rows_.front().edit->selectAll();
}

}  // namespace taiwa::ui
