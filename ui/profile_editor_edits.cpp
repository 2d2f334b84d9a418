// The turned-profile editor's edits (profile_editor.h): a row's or an
// allowance's cell typed, rows and allowances added and deleted, corners
// revised, picked and sized. Each is one undoable change of the profile
// (commit); the table, drawing and checks follow from the new profile.
#include "ui/profile_editor.h"

#include "ui/number_text.h"
#include "ui/profile_view.h"
#include "ui/table_cells.h"

#include <QLabel>
#include <QLineEdit>
#include <QStringList>
#include <QTableWidget>

#include <algorithm>
#include <optional>

namespace taiwa::ui {

using namespace turning;

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
            markCell(rows_, item, true, tr("not a number"));
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
            markCell(allowances_, item, true, tr("not a number"));
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
    revisionText_->setText(revisionLine());
    cornerSize_->clear();
    cornerSize_->setEnabled(false);
    revision_->show();
}

QString ProfileEditor::revisionLine() const
{
    const bool chamfer = revising_ == CornerKind::Chamfer;
    if (!revisedCorner_.isEmpty()) return (chamfer ? tr("Chamfer %1: leg") : tr("Rounding %1: radius")).arg(revisedCorner_);
    int corners = 0;
    for (const auto& r : profile_.rows) corners += r.corner == revising_ ? 1 : 0;
    const QString what = chamfer ? tr("chamfers") : tr("roundings");
    return corners == 0 ? tr("The profile has no %1.").arg(what) : tr("%1 %2: pick one in the view").arg(corners).arg(what);
}

void ProfileEditor::pickCorner(const QString& id)
{
    if (revising_ == CornerKind::None) return;  // any corner of the kind under revision
    for (const auto& r : profile_.rows) {
        if (QString::fromStdString(cornerEdgeId(r.id)) != id || r.corner != revising_) continue;
        revisedCorner_ = id;
        view_->setHighlightedCorners({id});
        revisionText_->setText(revisionLine());
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
        cornerSize_->setStyleSheet(QStringLiteral("background: %1;").arg(kRefusedBackground));
        return;
    }
    cornerSize_->setStyleSheet({});
    TurnedProfile after = profile_;
    for (auto& r : after.rows)
        if (QString::fromStdString(cornerEdgeId(r.id)) == revisedCorner_) r.cornerSize = *v;
    commit(after, tr("Revise %1").arg(revisedCorner_), {});
}

}  // namespace taiwa::ui
