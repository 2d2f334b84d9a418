// The figure panel (figure_panel.h): its widgets (the figure text's editor,
// its refusals, the 2-D view and the corner revision's row), named in the
// language in force, and the text evaluated after every edit. The marks in
// the text and the picks between text and view: figure_panel_marks.cpp;
// picking and revising a corner: figure_corner_revision.cpp.
#include "ui/figure_panel.h"

#include "figure/figure_contour.h"
#include "figure/figure_text.h"
#include "ui/job_document.h"
#include "ui/passes_bar.h"

#include <QDoubleSpinBox>
#include <QEvent>
#include <QFontDatabase>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QScrollBar>
#include <QSplitter>
#include <QTextCursor>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>

namespace taiwa::ui {

using figure::ContourCorner;

namespace {

// The first `lines` lines of `text`.
std::string firstLines(const std::string& text, int lines)
{
    std::size_t end = 0;
    for (int i = 0; i < lines && end != std::string::npos; ++i) {
        end = text.find('\n', end);
        if (end != std::string::npos) ++end;
    }
    return end == std::string::npos ? text : text.substr(0, end);
}

// The corner's value as the text writes it ("3", "2.5"), not "3.0000".
class ValueBox : public QDoubleSpinBox {
public:
    using QDoubleSpinBox::QDoubleSpinBox;
    QString textFromValue(double v) const override { return QString::fromStdString(figure::formatNumber(v)); }
};

}  // namespace

FigurePanel::FigurePanel(JobDocument* doc, QWidget* parent) : QWidget(parent), doc_(doc)
{
    auto* outer = new QVBoxLayout(this);
    outer->setContentsMargins(0, 0, 0, 0);
    auto* split = new QSplitter(Qt::Horizontal, this);
    split->setObjectName("figure.split");
    split->setChildrenCollapsible(false);
    outer->addWidget(split);

    // The text and its refusals.
    auto* left = new QWidget(split);
    auto* textBox = new QVBoxLayout(left);
    textBox->setContentsMargins(0, 0, 0, 0);
    textBox->setSpacing(2);
    title_ = new QLabel(left);
    title_->setObjectName("figure.title");
    title_->setWordWrap(true);
    textBox->addWidget(title_);
    editor_ = new QPlainTextEdit(left);
    editor_->setObjectName("figure.text");
    editor_->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    editor_->setLineWrapMode(QPlainTextEdit::NoWrap);
    editor_->setUndoRedoEnabled(false);  // the job's undo stack undoes the text
    editor_->setTabChangesFocus(true);
    editor_->installEventFilter(this);
    textBox->addWidget(editor_, 1);
    refusals_ = new QListWidget(left);
    refusals_->setObjectName("figure.refusals");
    refusals_->setWordWrap(true);
    refusals_->setMaximumHeight(QFontMetrics(refusals_->font()).lineSpacing() * 3 + 8);
    textBox->addWidget(refusals_);

    // The view with the corner revision above it.
    auto* right = new QWidget(split);
    auto* viewBox = new QVBoxLayout(right);
    viewBox->setContentsMargins(0, 0, 0, 0);
    viewBox->setSpacing(2);
    auto* buttons = new QHBoxLayout;
    const auto toolButton = [&](const QString& name, bool checkable) {
        auto* b = new QToolButton(right);
        b->setObjectName(name);
        b->setCheckable(checkable);
        b->setToolButtonStyle(Qt::ToolButtonTextOnly);
        buttons->addWidget(b);
        return b;
    };
    reviseChamfer_ = toolButton("figure.reviseChamfer", true);
    reviseRounding_ = toolButton("figure.reviseRounding", true);
    buttons->addStretch(1);
    fit_ = toolButton("figure.fit", false);
    viewBox->addLayout(buttons);
    revision_ = new QWidget(right);
    revision_->setObjectName("figure.revision");
    auto* rev = new QHBoxLayout(revision_);
    rev->setContentsMargins(0, 0, 0, 0);
    revisionText_ = new QLabel(revision_);
    revisionText_->setObjectName("figure.revisionText");
    revisionText_->setWordWrap(true);
    value_ = new ValueBox(revision_);
    value_->setObjectName("figure.cornerValue");
    value_->setLocale(QLocale::c());  // '.' as in the text, whatever the system's locale
    value_->setKeyboardTracking(false);  // one edit when the value is entered, not one a keystroke
    value_->setRange(0.0001, figure::kMaxNumber);
    value_->setDecimals(4);
    value_->setEnabled(false);
    rev->addWidget(revisionText_, 1);
    rev->addWidget(value_);
    revision_->hide();
    viewBox->addWidget(revision_);
    view_ = new FigureView(right);
    view_->setObjectName("figure.view");
    passes_ = new PassesBar(doc_, view_, right);
    viewBox->addWidget(passes_);
    viewBox->addWidget(view_, 1);
    split->addWidget(left);
    split->addWidget(right);
    split->setStretchFactor(0, 1);
    split->setStretchFactor(1, 1);
    nameParts();

    connect(editor_, &QPlainTextEdit::textChanged, this, &FigurePanel::onTextChanged);
    connect(editor_, &QPlainTextEdit::cursorPositionChanged, this, &FigurePanel::onCursorMoved);
    connect(refusals_, &QListWidget::itemClicked, this, &FigurePanel::goToRefusal);
    connect(refusals_, &QListWidget::itemActivated, this, &FigurePanel::goToRefusal);
    connect(view_, &FigureView::elementPicked, this, &FigurePanel::select);
    connect(view_, &FigureView::cornerPicked, this, &FigurePanel::pickCorner);
    connect(fit_, &QToolButton::clicked, view_, &FigureView::fitAll);
    connect(reviseChamfer_, &QToolButton::clicked, this, [this](bool on) {
        reviseCorners(on ? std::optional(ContourCorner::Kind::Chamfer) : std::nullopt);
    });
    connect(reviseRounding_, &QToolButton::clicked, this, [this](bool on) {
        reviseCorners(on ? std::optional(ContourCorner::Kind::Round) : std::nullopt);
    });
    connect(value_, &QDoubleSpinBox::valueChanged, this, &FigurePanel::reviseValue);
    connect(doc_, &JobDocument::changed, this, &FigurePanel::refresh);
    refresh();
}

void FigurePanel::nameParts()
{
    title_->setText(tr("Figure elements, one statement a line"));
    editor_->setPlaceholderText(tr("P1 = POINT/10, 20\nL1 = LINE/P1, ATANGL, 90\nK1 = CONTOUR/L1, ROUND, 5, L2, …"));
    refusals_->setToolTip(tr("What the text refuses; click one to go to its place"));
    reviseChamfer_->setText(tr("Revise chamfer"));
    reviseRounding_->setText(tr("Revise rounding"));
    fit_->setText(tr("Fit"));
    fit_->setToolTip(tr("Frame the stock, the points and the contours"));
}

void FigurePanel::changeEvent(QEvent* e)
{
    QWidget::changeEvent(e);
    if (e->type() != QEvent::LanguageChange || !fit_) return;
    nameParts();
    listRefusals();
    if (revising_) showRevision();
}

// The job's text in the editor (unless it is what the editor holds: the
// operator is typing), evaluated again.
void FigurePanel::refresh()
{
    const QString text = QString::fromStdString(doc_->job().figure);
    if (editor_->toPlainText() != text) {
        updating_ = true;
        const int at = editor_->textCursor().position();
        const int scrolled = editor_->verticalScrollBar()->value();
        editor_->setPlainText(text);
        QTextCursor c = editor_->textCursor();
        c.setPosition(std::clamp(at, 0, static_cast<int>(text.size())));
        editor_->setTextCursor(c);
        editor_->verticalScrollBar()->setValue(scrolled);
        updating_ = false;
    }
    value_->setSuffix(QStringLiteral(" ") + QString::fromUtf8(unitSymbol(doc_->job().lengthUnit)));
    evaluateText();
    passes_->refresh();
}

void FigurePanel::setCurrentUnit(int unit) { passes_->setUnit(unit); }

void FigurePanel::onTextChanged()
{
    if (updating_) return;
    Job j = doc_->job();
    j.figure = editor_->toPlainText().toStdString();
    doc_->edit(j, tr("Edit figure"), QStringLiteral("figure"));
}

void FigurePanel::evaluateText()
{
    const Job& job = doc_->job();
    // A job opened or its stock changed: framed anew; typing keeps the frame.
    const bool fit = !evaluatedOnce_ || job.stock != shownStock_ || doc_->path() != shownPath_;
    if (!fit && job.figure == shownText_) return;
    evaluatedOnce_ = true;
    shownText_ = job.figure;
    shownStock_ = job.stock;
    shownPath_ = doc_->path();
    const figure::ParseResult parsed = figure::parseFigure(job.figure);
    errors_.clear();
    if (parsed.ok()) {
        definitions_ = parsed.definitions;
    } else {
        // What can be drawn: the statements before the refused one.
        errors_.push_back(*parsed.error);
        definitions_ = figure::parseFigure(firstLines(job.figure, parsed.error->line - 1)).definitions;
    }
    figure::Evaluation evaluated = figure::evaluate(definitions_);
    if (parsed.ok()) errors_ = evaluated.errors;
    view_->setFigure(std::move(evaluated), job.stock, fit);
    listRefusals();
    markLines();
    if (revising_) showRevision();
}

bool FigurePanel::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == editor_) {
        // Leaving the editor ends its undo step; Ctrl+Z and Ctrl+Shift+Z go
        // to the job's undo stack.
        if (event->type() == QEvent::FocusOut) doc_->breakMerge();
        if (event->type() == QEvent::ShortcutOverride) {
            auto* key = static_cast<QKeyEvent*>(event);
            if (key->matches(QKeySequence::Undo) || key->matches(QKeySequence::Redo) ||
                key->keyCombination() == QKeyCombination(Qt::ControlModifier | Qt::ShiftModifier, Qt::Key_Z))
                return true;
        }
    }
    return QWidget::eventFilter(watched, event);
}

}  // namespace taiwa::ui
