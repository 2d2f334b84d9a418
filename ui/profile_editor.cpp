// The editor of a turned profile (profile_editor.h).
#include "ui/profile_editor.h"
#include "ui/core_messages.h"

#include "tools/turning_tools.h"
#include "turning/allowance.h"
#include "turning/profile_resolve.h"
#include "ui/number_text.h"
#include "ui/profile_view.h"

#include <QApplication>
#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <functional>
#include <map>

namespace taiwa::ui {

using namespace turning;

namespace {

const char* const kRed = "#ffd0d0";

QString shown(double v) { return formatShown(v); }
QString shown(const std::optional<double>& v) { return v ? formatShown(*v) : QString(); }

// Marks a cell red with a tooltip, or clears it; touches it only when that
// changes something, and never the cell whose editor is open (a changed
// item makes the view reload its editor, losing what is being typed).
// A table that says whether a cell's editor is open.
class Table : public QTableWidget {
public:
    using QTableWidget::QTableWidget;
    bool editingNow() const { return state() == QAbstractItemView::EditingState; }
};

// Whether the cell's editor is open with text not yet in the item (a
// change of the item would make the view reload the editor from it).
bool editing(const QTableWidget* t, const QTableWidgetItem* item)
{
    const auto* table = dynamic_cast<const Table*>(t);
    if (!item || item != t->currentItem() || !table || !table->editingNow()) return false;
    const auto* editor = qobject_cast<const QLineEdit*>(QApplication::focusWidget());
    return !editor || editor->text() != item->text();
}

void mark(QTableWidget* t, QTableWidgetItem* item, bool red, const QString& tip)
{
    if (editing(t, item)) return;
    const QBrush want = red ? QBrush(QColor(kRed)) : QBrush();
    if (item->background() != want) item->setBackground(want);
    if (item->toolTip() != tip) item->setToolTip(tip);
}

QTableWidgetItem* cell(const QString& text, bool editable = true)
{
    auto* item = new QTableWidgetItem(text);
    if (!editable) item->setFlags(item->flags() & ~Qt::ItemIsEditable);
    return item;
}

// Which cell a check field names: "rows[3].radius" -> row 2, R.
std::optional<std::pair<int, int>> rowCell(const QString& field)
{
    static const QRegularExpression re(QStringLiteral(R"(^rows\[(\d+)\]\.(\w+)(\.\w+)?$)"));
    const auto m = re.match(field);
    if (!m.hasMatch()) return std::nullopt;
    const int row = m.captured(1).toInt() - 1;
    const QString key = m.captured(2);
    const int col = key == "x" ? ProfileEditor::XCol : key == "z" ? ProfileEditor::ZCol
                  : key == "radius" ? ProfileEditor::RCol : key == "centre" ? ProfileEditor::CXCol
                  : key == "corner" ? ProfileEditor::CornerCol : key == "cornerSize" ? ProfileEditor::SizeCol
                  : key == "id" ? ProfileEditor::EdgeCol : key == "thread" ? ProfileEditor::PitchCol : ProfileEditor::XCol;
    return std::make_pair(row, col);
}

std::optional<std::pair<int, int>> allowanceCell(const QString& field)
{
    static const QRegularExpression re(QStringLiteral(R"(^allowances\[(\d+)\]\.(\w+)$)"));
    const auto m = re.match(field);
    if (!m.hasMatch()) return std::nullopt;
    const QString key = m.captured(2);
    const int col = key == "edge" ? ProfileEditor::AEdgeCol : key == "adjustment" ? ProfileEditor::AAdjustCol
                  : key == "grooveWidth" ? ProfileEditor::AWidthCol : key == "grooveDepth" ? ProfileEditor::ADepthCol
                  : ProfileEditor::AAllowCol;
    return std::make_pair(m.captured(1).toInt() - 1, col);
}

}  // namespace

ProfileEditor::ProfileEditor(const QString& prefix, QWidget* parent) : QWidget(parent), prefix_(prefix)
{
    auto* outer = new QVBoxLayout(this);
    outer->setContentsMargins(0, 0, 0, 0);
    view_ = new ProfileView(this);
    view_->setObjectName(prefix + ".view");
    outer->addWidget(view_);

    rows_ = new Table(0, RowColumns, this);
    rows_->setObjectName(prefix + ".rows");
    rows_->setHorizontalHeaderLabels({tr("Edge"), tr("Element"), tr("X (dia.)"), tr("Z"), tr("R"), tr("Centre X"),
                                      tr("Centre Z"), tr("Corner"), tr("Size"), tr("Ra µm"), tr("Tolerance"), tr("Thread pitch")});
    rows_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    rows_->verticalHeader()->setVisible(false);
    rows_->setEditTriggers(QAbstractItemView::AllEditTriggers);
    rows_->setMinimumHeight(150);
    // The unit column decides the width: the tables scroll inside it.
    rows_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Expanding);
    rows_->setMinimumWidth(200);
    auto* rowsTitle = new QLabel(tr("Profile, in cutting order (X is a diameter; arcs: R, or the centre)"), this);
    rowsTitle->setWordWrap(true);
    outer->addWidget(rowsTitle);
    outer->addWidget(rows_);
    auto* rowButtons = new QHBoxLayout;
    const auto button = [&](QHBoxLayout* box, const QString& name, const QString& text) {
        auto* b = new QPushButton(text, this);
        b->setObjectName(prefix + "." + name);
        b->setAutoDefault(false);
        box->addWidget(b);
        return b;
    };
    connect(button(rowButtons, "addRow", tr("Add row")), &QPushButton::clicked, this, [this] { addRow(false); });
    connect(button(rowButtons, "insertRow", tr("Insert row")), &QPushButton::clicked, this, [this] { addRow(true); });
    connect(button(rowButtons, "deleteRow", tr("Delete row")), &QPushButton::clicked, this, &ProfileEditor::deleteRow);
    rowButtons->addStretch(1);
    outer->addLayout(rowButtons);
    auto* reviseButtons = new QHBoxLayout;
    connect(button(reviseButtons, "reviseChamfers", tr("Revise chamfers")), &QPushButton::clicked, this,
            [this] { reviseCorners(CornerKind::Chamfer); });
    connect(button(reviseButtons, "reviseRoundings", tr("Revise roundings")), &QPushButton::clicked, this,
            [this] { reviseCorners(CornerKind::Rounding); });
    reviseButtons->addStretch(1);
    outer->addLayout(reviseButtons);

    // Corner revision: the picked corner's size.
    revision_ = new QWidget(this);
    revision_->setObjectName(prefix + ".revision");
    auto* rev = new QHBoxLayout(revision_);
    rev->setContentsMargins(0, 0, 0, 0);
    revisionText_ = new QLabel(revision_);
    revisionText_->setObjectName(prefix + ".revisionText");
    cornerSize_ = new QLineEdit(revision_);
    cornerSize_->setObjectName(prefix + ".cornerSize");
    cornerSize_->setMaximumWidth(90);
    auto* done = new QPushButton(tr("Done"), revision_);
    done->setObjectName(prefix + ".revisionDone");
    done->setAutoDefault(false);
    rev->addWidget(revisionText_, 1);
    rev->addWidget(cornerSize_);
    rev->addWidget(done);
    revision_->hide();
    outer->addWidget(revision_);
    connect(cornerSize_, &QLineEdit::returnPressed, this, &ProfileEditor::editCornerSize);
    connect(done, &QPushButton::clicked, this, [this] { reviseCorners(CornerKind::None); });

    allowances_ = new Table(0, AllowanceColumns, this);
    allowances_->setObjectName(prefix + ".allowances");
    allowances_->setHorizontalHeaderLabels(
        {tr("Edge"), tr("Allowance"), tr("Adjustment"), tr("Relief groove"), tr("Width"), tr("Depth")});
    allowances_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    allowances_->verticalHeader()->setVisible(false);
    allowances_->setEditTriggers(QAbstractItemView::AllEditTriggers);
    allowances_->setMinimumHeight(90);
    allowances_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    allowances_->setMinimumWidth(200);
    auto* allowanceTitle = new QLabel(tr("Grinding allowance per edge (empty: adjustment from the finishing tool's "
                                         "nose radius, depth = allowance, no width = no groove)"),
                                      this);
    allowanceTitle->setWordWrap(true);
    outer->addWidget(allowanceTitle);
    outer->addWidget(allowances_);
    auto* allowanceButtons = new QHBoxLayout;
    addAllowance_ = button(allowanceButtons, "addAllowance", tr("Add allowance for picked edge"));
    connect(addAllowance_, &QPushButton::clicked, this, &ProfileEditor::addAllowance);
    connect(button(allowanceButtons, "deleteAllowance", tr("Delete allowance")), &QPushButton::clicked, this,
            &ProfileEditor::deleteAllowance);
    allowanceButtons->addStretch(1);
    outer->addLayout(allowanceButtons);

    messages_ = new QLabel(this);
    messages_->setObjectName(prefix + ".messages");
    messages_->setStyleSheet("color: #a00000;");
    messages_->setWordWrap(true);
    outer->addWidget(messages_);

    connect(rows_, &QTableWidget::itemChanged, this, &ProfileEditor::onRowItem);
    connect(allowances_, &QTableWidget::itemChanged, this, &ProfileEditor::onAllowanceItem);
    // The picked edge and the table rows follow each other.
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

void ProfileEditor::refreshView()
{
    if (profile_.rows.size() > kMaxProfileRows || profile_.allowances.size() > kMaxAllowanceRows) {
        view_->setProfile({}, std::nullopt, bar_);  // refused by the checks: nothing to draw
        return;
    }
    const Resolution r = resolveProfile(profile_);
    std::optional<DeformedProfile> deformed;
    if (r.ok()) {
        AllowanceOptions o;
        if (const Tool* t = finishingTurningTool(library_, profile_.side == ProfileSide::Inner)) o.noseRadius = t->cornerRadius;
        Deformation d = applyAllowances(r.profile, profile_.allowances, o);
        if (d.ok()) deformed = std::move(d.profile);
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
        const bool open = editing(t, item);
        if (!item) t->setItem(r, c, cell(text, editable));
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
        auto* kind = combo(rows_, i, KindCol, "rows.kind",
                           {{tr("line"), int(ElementKind::Line)}, {tr("arc CW (G2)"), int(ElementKind::ArcCW)},
                            {tr("arc CCW (G3)"), int(ElementKind::ArcCCW)}},
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
        auto* corner = combo(rows_, i, CornerCol, "rows.corner",
                             {{tr("none"), int(CornerKind::None)}, {tr("chamfer"), int(CornerKind::Chamfer)},
                              {tr("rounding"), int(CornerKind::Rounding)}},
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

void ProfileEditor::commit(const TurnedProfile& after, const QString& text, const QString& key)
{
    if (after == profile_) return;
    emit edited(after, text, key);
}

void ProfileEditor::onRowItem(QTableWidgetItem* item)
{
    if (updating_) return;
    const int r = item->row(), c = item->column();
    if (r < 0 || r >= static_cast<int>(profile_.rows.size())) return;
    TurnedProfile after = profile_;
    ProfileRow& row = after.rows[static_cast<std::size_t>(r)];
    const QString text = item->text().trimmed();
    std::erase(notANumber_, std::make_pair(r, c));
    if (c == TolCol) {
        row.attributes.tolerance = text.toStdString();
    } else {
        const bool optional =
            c == RCol || c == CXCol || c == CZCol || c == RaCol || c == PitchCol || (c == SizeCol && text.isEmpty());
        const std::optional<double> v = parseNumber(text);
        if (!(optional && text.isEmpty()) && !v) {
            notANumber_.emplace_back(r, c);
            updating_ = true;
            mark(rows_, item, true, tr("not a number"));
            updating_ = false;
            messages_->setText(tr("row %1: not a number").arg(r + 1));
            return;
        }
        switch (c) {
        case XCol: row.x = *v; break;
        case ZCol: row.z = *v; break;
        case RCol: row.radius = v; break;
        case CXCol: row.centreX = v; break;
        case CZCol: row.centreZ = v; break;
        case SizeCol: row.cornerSize = v.value_or(0.0); break;
        case RaCol: row.attributes.roughness = v; break;
        case PitchCol:  // a pitch typed cuts a thread (its depth kept, else ISO's); emptied, none
            if (!v) row.attributes.thread.reset();
            else if (row.attributes.thread) row.attributes.thread->pitch = *v;
            else row.attributes.thread = ThreadSpec{*v, std::nullopt};
            break;
        default: return;
        }
    }
    const QString column = rows_->horizontalHeaderItem(c)->text();
    commit(after, tr("%1 of row %2").arg(column).arg(r + 1), QStringLiteral("rows[%1].%2").arg(r + 1).arg(c));
}

void ProfileEditor::onAllowanceItem(QTableWidgetItem* item)
{
    if (updating_) return;
    const int k = item->row(), c = item->column();
    if (k < 0 || k >= static_cast<int>(profile_.allowances.size())) return;
    TurnedProfile after = profile_;
    AllowanceRow& a = after.allowances[static_cast<std::size_t>(k)];
    const QString text = item->text().trimmed();
    if (c == AEdgeCol) {
        a.edge = text.toUpper().toStdString();
    } else {
        const std::optional<double> v = parseNumber(text);
        const bool optional = c != AAllowCol;
        if (!(optional && text.isEmpty()) && !v) {
            updating_ = true;
            mark(allowances_, item, true, tr("not a number"));
            updating_ = false;
            messages_->setText(tr("allowance %1: not a number").arg(k + 1));
            return;
        }
        switch (c) {
        case AAllowCol: a.allowance = *v; break;
        case AAdjustCol: a.adjustment = v; break;
        case AWidthCol: a.grooveWidth = v; break;
        case ADepthCol: a.grooveDepth = v; break;
        default: return;
        }
    }
    const QString column = allowances_->horizontalHeaderItem(c)->text();
    commit(after, tr("%1 of allowance %2").arg(column).arg(k + 1), QStringLiteral("allowances[%1].%2").arg(k + 1).arg(c));
}

// A new row after the last (or before the current one), starting where the
// previous ends; a new id, so that every other edge keeps its own.
void ProfileEditor::addRow(bool atCurrent)
{
    TurnedProfile after = profile_;
    ProfileRow row;
    row.id = after.nextRowId();
    const int at = atCurrent && rows_->currentRow() >= 0 ? rows_->currentRow() : static_cast<int>(after.rows.size());
    if (at > 0) {
        row.x = after.rows[static_cast<std::size_t>(at - 1)].x;
        row.z = after.rows[static_cast<std::size_t>(at - 1)].z;
    } else {
        row.x = after.startX;
        row.z = after.startZ;
    }
    after.rows.insert(after.rows.begin() + at, row);
    commit(after, tr("Add row %1").arg(at + 1), {});
    rows_->setCurrentCell(at, XCol);
}

void ProfileEditor::deleteRow()
{
    const int r = rows_->currentRow();
    if (r < 0 || r >= static_cast<int>(profile_.rows.size())) return;
    TurnedProfile after = profile_;
    after.rows.erase(after.rows.begin() + r);
    commit(after, tr("Delete row %1").arg(r + 1), {});
}

void ProfileEditor::addAllowance()
{
    const QString edge = view_->selectedEdge();
    if (edge.isEmpty()) {
        messages_->setText(tr("Pick an edge in the view first."));
        return;
    }
    TurnedProfile after = profile_;
    for (const auto& a : after.allowances)
        if (QString::fromStdString(a.edge) == edge) {
            messages_->setText(tr("%1 has an allowance already.").arg(edge));
            return;
        }
    AllowanceRow a;
    a.edge = edge.toStdString();
    a.allowance = 0.2;
    after.allowances.push_back(a);
    commit(after, tr("Add grinding allowance for %1").arg(edge), {});
    allowances_->setCurrentCell(static_cast<int>(after.allowances.size()) - 1, AAllowCol);
}

void ProfileEditor::deleteAllowance()
{
    const int k = allowances_->currentRow();
    if (k < 0 || k >= static_cast<int>(profile_.allowances.size())) return;
    TurnedProfile after = profile_;
    after.allowances.erase(after.allowances.begin() + k);
    commit(after, tr("Delete allowance %1").arg(k + 1), {});
}

void ProfileEditor::reviseCorners(CornerKind kind)
{
    revising_ = kind;
    revisedCorner_.clear();
    if (kind == CornerKind::None) {
        view_->setHighlightedCorners({});
        revision_->hide();
        return;
    }
    QStringList ids;
    for (const auto& r : profile_.rows)
        if (r.corner == kind) ids << QString::fromStdString(cornerEdgeId(r.id));
    view_->setSelectedEdge({});
    view_->setHighlightedCorners(ids);
    const QString what = kind == CornerKind::Chamfer ? tr("chamfers") : tr("roundings");
    revisionText_->setText(ids.isEmpty() ? tr("The profile has no %1.").arg(what)
                                         : tr("%1 %2: pick one in the view").arg(ids.size()).arg(what));
    cornerSize_->clear();
    cornerSize_->setEnabled(false);
    revision_->show();
}

void ProfileEditor::pickCorner(const QString& id)
{
    if (revising_ == CornerKind::None) return;  // any corner of the kind under revision
    for (const auto& r : profile_.rows) {
        if (QString::fromStdString(cornerEdgeId(r.id)) != id || r.corner != revising_) continue;
        revisedCorner_ = id;
        view_->setHighlightedCorners({id});
        revisionText_->setText((revising_ == CornerKind::Chamfer ? tr("Chamfer %1: leg") : tr("Rounding %1: radius")).arg(id));
        cornerSize_->setEnabled(true);
        cornerSize_->setText(formatShown(r.cornerSize));
        cornerSize_->setFocus();
        cornerSize_->selectAll();
        return;
    }
}

void ProfileEditor::editCornerSize()
{
    const auto v = parseNumber(cornerSize_->text());
    if (!v || revisedCorner_.isEmpty()) {
        cornerSize_->setStyleSheet(QStringLiteral("background: %1;").arg(kRed));
        return;
    }
    cornerSize_->setStyleSheet({});
    TurnedProfile after = profile_;
    for (auto& r : after.rows)
        if (QString::fromStdString(cornerEdgeId(r.id)) == revisedCorner_) r.cornerSize = *v;
    commit(after, tr("Revise %1").arg(revisedCorner_), {});
}

Diagnostics ProfileEditor::showDiagnostics(const Diagnostics& ofThisUnit)
{
    updating_ = true;
    // What each cell shows: red with its message, "not a number", or clear.
    std::map<std::pair<QTableWidget*, std::pair<int, int>>, QString> red;
    for (const auto& rc : notANumber_) red[{rows_, rc}] = tr("not a number");
    Diagnostics unmatched;
    QStringList lines;
    for (const Diagnostic& d : ofThisUnit) {
        const QString field = QString::fromStdString(d.field);
        std::optional<std::pair<int, int>> at = rowCell(field);
        QTableWidget* table = rows_;
        if (!at) {
            at = allowanceCell(field);
            table = allowances_;
        }
        if (!at && field != "rows" && field != "allowances") {
            unmatched.push_back(d);
            continue;
        }
        lines << coreMessage(d.message);
        if (at)
            red[{table, *at}] = coreMessage(d.message);
    }
    for (QTableWidget* t : {rows_, allowances_})
        for (int r = 0; r < t->rowCount(); ++r)
            for (int c = 0; c < t->columnCount(); ++c)
                if (QTableWidgetItem* item = t->item(r, c)) {
                    const auto it = red.find({t, {r, c}});
                    mark(t, item, it != red.end(), it != red.end() ? it->second : QString());
                }
    updating_ = false;
    messages_->setText(lines.join('\n'));
    return unmatched;
}

}  // namespace taiwa::ui
