// The turned-profile editor's checks (profile_editor.h): a check's field
// ("rows[3].radius", "allowances[1].grooveWidth") found as a cell of the
// profile or allowance table, named as the tables show it, and marked red
// with its message; the messages listed under the tables.
#include "ui/profile_editor.h"

#include "ui/core_messages.h"
#include "ui/table_cells.h"

#include <QLabel>
#include <QRegularExpression>
#include <QStringList>
#include <QTableWidget>

#include <map>
#include <optional>
#include <utility>

namespace taiwa::ui {

namespace {

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

QString ProfileEditor::cellName(const QString& field)
{
    if (const auto at = rowCell(field))
        return tr("profile row %1, %2").arg(at->first + 1).arg(rowHeadings().value(at->second));
    if (const auto at = allowanceCell(field))
        return tr("allowance row %1, %2").arg(at->first + 1).arg(allowanceHeadings().value(at->second));
    return {};
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
                    markCell(t, item, it != red.end(), it != red.end() ? it->second : QString());
                }
    updating_ = false;
    messages_->setText(lines.join('\n'));
    return unmatched;
}

}  // namespace taiwa::ui
