// The editor of a turned profile (profile_editor.h): its tables and buttons,
// their headings in the language in force, the profile shown and drawn. The
// edits themselves: profile_editor_edits.cpp; the checks marked on the
// cells: profile_editor_checks.cpp.
#include "ui/profile_editor.h"

#include "turning/allowance.h"
#include "turning/profile_resolve.h"
#include "ui/number_text.h"
#include "ui/profile_view.h"
#include "ui/table_cells.h"

#include <QCheckBox>
#include <QComboBox>
#include <QEvent>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <functional>

namespace taiwa::ui {

using namespace turning;

namespace {

QString shown(double v) { return formatShown(v); }
QString shown(const std::optional<double>& v) { return v ? formatShown(*v) : QString(); }

// A table of the editor's: every cell edited in place, its columns as wide
// as their contents, scrolling inside the unit column (which decides the
// width).
EditingTable* editingTable(int columns, const QString& name, int minHeight, QSizePolicy::Policy vertical, QWidget* parent)
{
    auto* t = new EditingTable(0, columns, parent);
    t->setObjectName(name);
    t->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    t->verticalHeader()->setVisible(false);
    t->setEditTriggers(QAbstractItemView::AllEditTriggers);
    t->setMinimumHeight(minHeight);
    t->setSizePolicy(QSizePolicy::Ignored, vertical);
    t->setMinimumWidth(200);
    return t;
}

}  // namespace

ProfileEditor::ProfileEditor(const QString& prefix, QWidget* parent) : QWidget(parent), prefix_(prefix)
{
    auto* outer = new QVBoxLayout(this);
    outer->setContentsMargins(0, 0, 0, 0);
    view_ = new ProfileView(this);
    view_->setObjectName(prefix + ".view");
    outer->addWidget(view_);
    // The allowances and grooves drawn ten times as deep: a 0.5 mm grinding
    // allowance is seen without zooming in.
    exaggerate_ = new QCheckBox(this);
    exaggerate_->setObjectName(prefix + ".exaggerate");
    connect(exaggerate_, &QCheckBox::toggled, view_, [this](bool on) { view_->setExaggeration(on ? kExaggeration : 1.0); });
    outer->addWidget(exaggerate_);

    rows_ = editingTable(RowColumns, prefix + ".rows", 150, QSizePolicy::Expanding, this);
    rowsTitle_ = new QLabel(this);
    rowsTitle_->setObjectName(prefix + ".rowsTitle");
    rowsTitle_->setWordWrap(true);
    outer->addWidget(rowsTitle_);
    outer->addWidget(rows_);
    // The buttons at most two to a row: the unit column stays narrow (a
    // 1280-pixel screen) and the form never scrolls sideways.
    auto* rowButtons = new QGridLayout;
    const auto button = [&](QGridLayout* box, int r, int c, const QString& name) {
        auto* b = new QPushButton(this);
        b->setObjectName(prefix + "." + name);
        b->setAutoDefault(false);
        box->addWidget(b, r, c);
        box->setColumnStretch(2, 1);
        return b;
    };
    connect(button(rowButtons, 0, 0, "addRow"), &QPushButton::clicked, this, [this] { addRow(false); });
    connect(button(rowButtons, 0, 1, "insertRow"), &QPushButton::clicked, this, [this] { addRow(true); });
    connect(button(rowButtons, 1, 0, "deleteRow"), &QPushButton::clicked, this, &ProfileEditor::deleteRow);
    outer->addLayout(rowButtons);
    auto* reviseButtons = new QGridLayout;
    connect(button(reviseButtons, 0, 0, "reviseChamfers"), &QPushButton::clicked, this,
            [this] { reviseCorners(CornerKind::Chamfer); });
    connect(button(reviseButtons, 0, 1, "reviseRoundings"), &QPushButton::clicked, this,
            [this] { reviseCorners(CornerKind::Rounding); });
    outer->addLayout(reviseButtons);

    buildRevision(outer);

    allowances_ = editingTable(AllowanceColumns, prefix + ".allowances", 90, QSizePolicy::Preferred, this);
    allowanceTitle_ = new QLabel(this);
    allowanceTitle_->setObjectName(prefix + ".allowancesTitle");
    allowanceTitle_->setWordWrap(true);
    outer->addWidget(allowanceTitle_);
    outer->addWidget(allowances_);
    auto* allowanceButtons = new QGridLayout;
    addAllowance_ = button(allowanceButtons, 0, 0, "addAllowance");
    connect(addAllowance_, &QPushButton::clicked, this, &ProfileEditor::addAllowance);
    connect(button(allowanceButtons, 1, 0, "deleteAllowance"), &QPushButton::clicked, this,
            &ProfileEditor::deleteAllowance);
    outer->addLayout(allowanceButtons);

    messages_ = new QLabel(this);
    messages_->setObjectName(prefix + ".messages");
    messages_->setStyleSheet("color: #a00000;");
    messages_->setWordWrap(true);
    outer->addWidget(messages_);
    nameParts();

    connect(rows_, &QTableWidget::itemChanged, this, &ProfileEditor::onRowItem);
    connect(allowances_, &QTableWidget::itemChanged, this, &ProfileEditor::onAllowanceItem);
    followPicks();
}

// Corner revision: the picked corner's size, its line edit and Done.
void ProfileEditor::buildRevision(QVBoxLayout* outer)
{
    revision_ = new QWidget(this);
    revision_->setObjectName(prefix_ + ".revision");
    auto* rev = new QHBoxLayout(revision_);
    rev->setContentsMargins(0, 0, 0, 0);
    revisionText_ = new QLabel(revision_);
    revisionText_->setObjectName(prefix_ + ".revisionText");
    cornerSize_ = new QLineEdit(revision_);
    cornerSize_->setObjectName(prefix_ + ".cornerSize");
    cornerSize_->setMaximumWidth(90);
    auto* done = new QPushButton(revision_);
    done->setObjectName(prefix_ + ".revisionDone");
    done->setAutoDefault(false);
    rev->addWidget(revisionText_, 1);
    rev->addWidget(cornerSize_);
    rev->addWidget(done);
    revision_->hide();
    outer->addWidget(revision_);
    connect(cornerSize_, &QLineEdit::returnPressed, this, &ProfileEditor::editCornerSize);
    connect(done, &QPushButton::clicked, this, [this] { reviseCorners(CornerKind::None); });
}

// The picked edge and the table rows follow each other.
void ProfileEditor::followPicks()
{
    connect(view_, &ProfileView::edgePicked, this, [this](const QString& id) {
        if (revising_ != CornerKind::None) {
            pickCorner(id);
            return;
        }
        for (std::size_t i = 0; i < profile_.rows.size(); ++i)
            if (id == QString::fromStdString(edgeId(profile_.rows[i].id)) ||
                id == QString::fromStdString(cornerEdgeId(profile_.rows[i].id)))
                rows_->setCurrentCell(static_cast<int>(i), id.endsWith(".c") ? CornerCol : XCol);
        for (std::size_t k = 0; k < profile_.allowances.size(); ++k)
            if (id == QString::fromStdString(profile_.allowances[k].edge)) allowances_->setCurrentCell(int(k), AAllowCol);
    });
    connect(rows_, &QTableWidget::currentCellChanged, this, [this](int row, int col) {
        if (row < 0 || row >= static_cast<int>(profile_.rows.size()) || revising_ != CornerKind::None) return;
        const int id = profile_.rows[static_cast<std::size_t>(row)].id;
        view_->setSelectedEdge(QString::fromStdString(col == CornerCol || col == SizeCol ? cornerEdgeId(id) : edgeId(id)));
    });
    connect(allowances_, &QTableWidget::currentCellChanged, this, [this](int row, int) {
        if (row >= 0 && row < static_cast<int>(profile_.allowances.size()))
            view_->setSelectedEdge(QString::fromStdString(profile_.allowances[static_cast<std::size_t>(row)].edge));
    });
}

QStringList ProfileEditor::rowHeadings()
{
    return {tr("Edge"), tr("Element"), tr("X (dia.)"), tr("Z"),    tr("R"),         tr("Centre X"),
            tr("Centre Z"), tr("Corner"), tr("Size"), tr("Ra µm"), tr("Tolerance"), tr("Thread pitch")};
}

QStringList ProfileEditor::allowanceHeadings()
{
    return {tr("Edge"), tr("Allowance"), tr("Adjustment"), tr("Relief groove"), tr("Width"), tr("Depth")};
}

std::vector<std::pair<QString, int>> ProfileEditor::elementKinds()
{
    return {{tr("line"), int(ElementKind::Line)}, {tr("arc CW (G2)"), int(ElementKind::ArcCW)},
            {tr("arc CCW (G3)"), int(ElementKind::ArcCCW)}};
}

std::vector<std::pair<QString, int>> ProfileEditor::cornerKinds()
{
    return {{tr("none"), int(CornerKind::None)}, {tr("chamfer"), int(CornerKind::Chamfer)},
            {tr("rounding"), int(CornerKind::Rounding)}};
}

void ProfileEditor::nameParts()
{
    rows_->setHorizontalHeaderLabels(rowHeadings());
    allowances_->setHorizontalHeaderLabels(allowanceHeadings());
    exaggerate_->setText(tr("Allowances and grooves drawn ×%1").arg(kExaggeration));
    rowsTitle_->setText(tr("Profile, in cutting order (X is a diameter; arcs: R, or the centre)"));
    allowanceTitle_->setText(tr("Grinding allowance per edge (empty: adjustment from the finishing tool's "
                                "nose radius, depth = allowance, no width = no groove)"));
    const std::pair<const char*, QString> buttons[] = {
        {"addRow", tr("Add row")},
        {"insertRow", tr("Insert row")},
        {"deleteRow", tr("Delete row")},
        {"reviseChamfers", tr("Revise chamfers")},
        {"reviseRoundings", tr("Revise roundings")},
        {"revisionDone", tr("Done")},
        {"addAllowance", tr("Add allowance for picked edge")},
        {"deleteAllowance", tr("Delete allowance")}};
    for (const auto& [name, text] : buttons)
        if (auto* b = findChild<QPushButton*>(prefix_ + "." + QString::fromLatin1(name))) b->setText(text);
    // The code cells' boxes, made by fill(): their items in the new words.
    const auto rename = [this](int column, const std::vector<std::pair<QString, int>>& items) {
        for (int r = 0; r < rows_->rowCount(); ++r)
            if (auto* box = qobject_cast<QComboBox*>(rows_->cellWidget(r, column)))
                for (const auto& [text, value] : items)
                    if (const int i = box->findData(value); i >= 0) box->setItemText(i, text);
    };
    rename(KindCol, elementKinds());
    rename(CornerCol, cornerKinds());
}

void ProfileEditor::changeEvent(QEvent* e)
{
    QWidget::changeEvent(e);
    if (e->type() != QEvent::LanguageChange || !messages_) return;
    nameParts();
    if (revising_ != CornerKind::None) revisionText_->setText(revisionLine());
}

void ProfileEditor::setProfile(const TurnedProfile& p, bool force)
{
    profile_ = p;
    fill(force);
    refreshView();
    if (revising_ != CornerKind::None) {
        const QString keep = revisedCorner_;
        reviseCorners(revising_);
        if (!keep.isEmpty()) pickCorner(keep);
    }
}

void ProfileEditor::setContext(std::optional<BarStock> bar, const std::vector<Tool>& library)
{
    bar_ = bar;
    library_ = library;
    refreshView();
}

void ProfileEditor::setUnit(const ModuleKind& kind, ModuleInput unit)
{
    kind_ = &kind;
    unit_ = std::move(unit);
}

void ProfileEditor::refreshView()
{
    if (profile_.rows.size() > kMaxProfileRows || profile_.allowances.size() > kMaxAllowanceRows) {
        view_->setProfile({}, std::nullopt, bar_);  // refused by the checks: nothing to draw
        return;
    }
    const Resolution r = resolveProfile(profile_);
    std::optional<DeformedProfile> deformed;
    if (r.ok()) {
        // Deformed once, as the check and the plan deform it: through the
        // module's door (its finishing insert's nose radius, with the bar
        // when it is known), else by the allowance rows alone. A refused
        // row draws nothing.
        if (kind_ && unit_) {
            ModuleInput unit = *unit_;
            kind_->setTurnedProfile(unit, profile_);
            Job job;
            job.bar = bar_;
            static const TechnologyData tech{};
            static const std::string material;
            const UnitPlanContext ctx{tech, library_, material, 0, &job};
            if (auto part = kind_->turned(unit, ctx); part && part->complete) deformed = std::move(part->deformed);
        } else if (Deformation d = deformProfile(profile_, r.profile, library_, LengthUnit::Millimetre); d.ok()) {
            deformed = std::move(d.profile);
        }
    }
    view_->setProfile(r.profile, deformed, bar_);
}

void ProfileEditor::fill(bool force)
{
    updating_ = true;
    const int n = static_cast<int>(profile_.rows.size());
    const bool rebuild = force || rows_->rowCount() != n;
    if (rebuild) {
        rows_->setRowCount(n);
        notANumber_.clear();
    }
    const auto set = [&](QTableWidget* t, int r, int c, const QString& text, bool editable = true) {
        QTableWidgetItem* item = t->item(r, c);
        const bool typing = t == rows_ && std::find(notANumber_.begin(), notANumber_.end(), std::make_pair(r, c)) != notANumber_.end();
        const bool open = cellEditing(t, item);
        if (!item) t->setItem(r, c, newCell(text, editable));
        else if (item->text() != text && (!typing || force) && !open) item->setText(text);
    };
    // A code cell: a combo box made once per row, its choice one edit.
    const auto combo = [&](QTableWidget* t, int r, int c, const QString& name, std::vector<std::pair<QString, int>> items,
                           std::function<void(TurnedProfile&, int)> apply, const QString& what) {
        auto* box = qobject_cast<QComboBox*>(t->cellWidget(r, c));
        if (box) return box;
        box = new QComboBox(t);
        box->setObjectName(QStringLiteral("%1.%2.%3").arg(prefix_, name).arg(r + 1));
        for (const auto& [text, value] : items) box->addItem(text, value);
        t->setCellWidget(r, c, box);
        connect(box, &QComboBox::activated, this, [this, box, apply, what](int index) {
            TurnedProfile after = profile_;
            apply(after, box->itemData(index).toInt());
            commit(after, what, {});
        });
        return box;
    };
    for (int i = 0; i < n; ++i) {
        const ProfileRow& row = profile_.rows[static_cast<std::size_t>(i)];
        set(rows_, i, EdgeCol, QString::fromStdString(edgeId(row.id)), false);
        const auto rowIndex = static_cast<std::size_t>(i);
        auto* kind = combo(rows_, i, KindCol, "rows.kind", elementKinds(),
                           [rowIndex](TurnedProfile& p, int v) {
                               if (rowIndex < p.rows.size()) p.rows[rowIndex].kind = static_cast<ElementKind>(v);
                           },
                           tr("Element of row %1").arg(i + 1));
        kind->setCurrentIndex(kind->findData(int(row.kind)));
        set(rows_, i, XCol, shown(row.x));
        set(rows_, i, ZCol, shown(row.z));
        set(rows_, i, RCol, shown(row.radius));
        set(rows_, i, CXCol, shown(row.centreX));
        set(rows_, i, CZCol, shown(row.centreZ));
        auto* corner = combo(rows_, i, CornerCol, "rows.corner", cornerKinds(),
                             [rowIndex](TurnedProfile& p, int v) {
                                 if (rowIndex < p.rows.size()) p.rows[rowIndex].corner = static_cast<CornerKind>(v);
                             },
                             tr("Corner of row %1").arg(i + 1));
        corner->setCurrentIndex(corner->findData(int(row.corner)));
        set(rows_, i, SizeCol, row.corner == CornerKind::None && row.cornerSize == 0 ? QString() : shown(row.cornerSize));
        set(rows_, i, RaCol, shown(row.attributes.roughness));
        set(rows_, i, TolCol, QString::fromStdString(row.attributes.tolerance));
        set(rows_, i, PitchCol, row.attributes.thread ? shown(row.attributes.thread->pitch) : QString());
    }
    const int m = static_cast<int>(profile_.allowances.size());
    if (force || allowances_->rowCount() != m) allowances_->setRowCount(m);
    for (int k = 0; k < m; ++k) {
        const AllowanceRow& a = profile_.allowances[static_cast<std::size_t>(k)];
        set(allowances_, k, AEdgeCol, QString::fromStdString(a.edge));
        set(allowances_, k, AAllowCol, shown(a.allowance));
        set(allowances_, k, AAdjustCol, shown(a.adjustment));
        std::vector<std::pair<QString, int>> kinds;
        for (const GrooveKind g : {GrooveKind::Auto, GrooveKind::None, GrooveKind::Lateral, GrooveKind::Longitudinal, GrooveKind::Ring})
            kinds.emplace_back(QString::fromUtf8(toKey(g)), int(g));
        const auto at = static_cast<std::size_t>(k);
        auto* groove = combo(allowances_, k, AGrooveCol, "allowances.groove", kinds,
                             [at](TurnedProfile& p, int v) {
                                 if (at < p.allowances.size()) p.allowances[at].groove = static_cast<GrooveKind>(v);
                             },
                             tr("Groove kind of allowance %1").arg(k + 1));
        groove->setCurrentIndex(groove->findData(int(a.groove)));
        set(allowances_, k, AWidthCol, shown(a.grooveWidth));
        set(allowances_, k, ADepthCol, shown(a.grooveDepth));
    }
    updating_ = false;
}

}  // namespace taiwa::ui
