// How the tool library dialog saves a change (tool_library_dialog.h): into
// the station's SQLite library, or onto the shop server at the version read,
// a conflict with another station's change asked about; what it changes in
// the open job asked before; and each change an undo step of its own.
#include "ui/tool_library_dialog.h"
#include "ui/core_messages.h"
#include "ui/core_texts.h"

#include "tools/tool_check.h"
#include "tools/tool_change_log.h"
#include "tools/tool_library.h"
#include "tools/tool_store.h"

#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QTableWidget>
#include <QUndoCommand>
#include <QUndoStack>

namespace taiwa::ui {

// One change of the library, made already when it is pushed: the tool
// before and after (none: added or removed).
class ToolEdit : public QUndoCommand {
public:
    ToolEdit(ToolLibraryDialog* dialog, std::optional<Tool> before, std::optional<Tool> after, const QString& text)
        : QUndoCommand(text), dialog_(dialog), before_(std::move(before)), after_(std::move(after))
    {
    }
    void redo() override
    {
        if (done_) return;  // QUndoStack::push redoes what change() just did
        dialog_->apply(after_, before_ ? before_->id : after_->id);
    }
    void undo() override
    {
        done_ = false;
        dialog_->apply(before_, after_ ? after_->id : before_->id);
    }

private:
    ToolLibraryDialog* dialog_;
    std::optional<Tool> before_, after_;
    bool done_ = true;
};

QString ToolLibraryDialog::summary(const Tool& t)
{
    return ToolLibraryDialog::tr("%1, Ø %2 mm, %3 flutes, stick-out %4 mm, holder %5, used %6 of %7 min")
        .arg(QString::fromStdString(t.name), num(t.diameter), QString::number(t.flutes), num(t.stickout), QString::fromStdString(t.holder),
             num(t.usedMinutes), num(t.lifeMinutes));
}

bool ToolLibraryDialog::applyOnServer(const std::optional<Tool>& tool, int id)
{
    if (!tool) {
        if (const auto removed = server_->remove(id); !removed) {
            fail(tr("Cannot retire the tool: %1").arg(coreMessage(removed.error())));
            return false;
        }
        return true;
    }
    const auto known = versions_.find(tool->id);
    const auto saved = server_->save(*tool, known == versions_.end() ? 0 : known->second);
    if (!saved) {
        fail(tr("Cannot save the tool: %1").arg(coreMessage(saved.error())));
        return false;
    }
    if (saved->saved()) return true;
    // Changed (or removed) by another station since it was read: both shown, the operator chooses.
    const ToolConflict& c = *saved->conflict;
    QMessageBox box(QMessageBox::Warning, tr("Tool changed meanwhile"),
                    tr("T%1 was changed by %2 at station %3 (%4) after this station read it.\n\nYours: %5\nTheirs: %6")
                        .arg(tool->id)
                        .arg(QString::fromStdString(c.changedBy), QString::fromStdString(c.station), QString::fromStdString(c.changedAt),
                             summary(*tool), c.theirs ? summary(*c.theirs) : tr("removed")),
                    QMessageBox::NoButton, this);
    box.setObjectName("tools.conflict");
    QPushButton* mine = box.addButton(tr("Keep mine"), QMessageBox::AcceptRole);
    mine->setObjectName("tools.keepMine");
    QPushButton* theirs = box.addButton(tr("Take theirs"), QMessageBox::RejectRole);
    theirs->setObjectName("tools.takeTheirs");
    box.exec();
    if (box.clickedButton() == mine) {
        const auto again = server_->save(*tool, c.theirVersion);
        if (again && again->saved()) return true;
        load(true);
        fail(again ? tr("T%1 was changed again meanwhile; nothing saved").arg(tool->id)
                   : tr("Cannot save the tool: %1").arg(coreMessage(again.error())));
        return false;
    }
    load(true);
    fail(tr("T%1: theirs taken, yours not saved").arg(tool->id));
    changed_ = true;  // the library the window plans with changed all the same
    return false;
}

bool ToolLibraryDialog::apply(const std::optional<Tool>& tool, int id)
{
    if (server_) {
        if (!applyOnServer(tool, id)) return false;
    } else {
        auto lib = ToolLibrary::open(defaultToolLibraryPath());
        if (!lib) {
            fail(tr("Cannot open the tool library: %1").arg(coreMessage(lib.error())));
            return false;
        }
        if (tool) {
            if (const auto saved = lib->save(*tool); !saved) {
                fail(tr("Cannot save the tool: %1").arg(coreMessage(saved.error())));
                return false;
            }
        } else if (const auto removed = lib->remove(id); !removed) {
            fail(tr("Cannot retire the tool: %1").arg(coreMessage(removed.error())));
            return false;
        }
    }
    changed_ = true;
    const int row = selectedRow();
    load(true);
    // The tool just changed stays selected (or the row where it was).
    int at = row;
    for (std::size_t i = 0; i < tools_.size(); ++i)
        if (tool && tools_[i].id == tool->id) at = static_cast<int>(i);
    if (at >= 0 && at < table_->rowCount()) table_->selectRow(at);
    return true;
}

// A field of the change log (toolJson's key) by its column's heading, as
// the operator reads it in the table; a field with no column by its key.
QString ToolLibraryDialog::fieldHeader(const std::string& key) const
{
    static const std::pair<const char*, Column> columns[] = {
        {"id", Id},         {"name", Name},         {"type", Type},           {"diameter", Diameter},
        {"cornerRadius", Corner}, {"taperAngle", Taper}, {"flutes", Flutes},  {"fluteLength", FluteLength},
        {"stickout", Stickout}, {"holder", Holder}, {"holderDiameter", HolderDiameter}, {"lifeMinutes", Life},
        {"usedMinutes", Used}};
    for (const auto& [k, column] : columns)
        if (key == k) return table_->horizontalHeaderItem(column)->text();
    return QString::fromStdString(key);
}

QString ToolLibraryDialog::editQuestion(const std::optional<Tool>& before, const std::optional<Tool>& after) const
{
    QStringList lines;
    if (impact_) {
        // The library as it would be: the tool replaced, added or removed.
        std::vector<Tool> edited;
        const int id = before ? before->id : after->id;
        for (const Tool& t : tools_)
            if (t.id != id) edited.push_back(t);
        if (after) edited.push_back(*after);
        const ToolEditImpact impact = impact_(tools_, edited);
        if (!impact.steps.empty())
            lines << tr("This changes %n step(s) of the open job:", "", static_cast<int>(impact.steps.size()));
        const auto tool = [](std::optional<int> t) { return t ? QString("T%1").arg(*t) : tr("no tool"); };
        for (const StepToolChange& c : impact.steps) {
            const QString step = tr("unit %1, %2").arg(c.step.unit + 1).arg(stepLabel(c.step));
            if (c.toolEdited) lines << tr("  %1: %2, its data changed").arg(step, tool(c.after));
            else if (!c.after && !c.before) lines << tr("  %1: no tool").arg(step);
            else lines << tr("  %1: %2 → %3").arg(step, tool(c.before), tool(c.after));
        }
        if (!impact.refusals.empty()) lines << tr("The job would be refused:");
        for (const Diagnostic& d : impact.refusals) lines << "  " + diagnosticText("", d);
    }
    // Its fields ("diameter 10 → 60"), and a name that would state another
    // size (tools/tool_change_log.h) when the edit touches the diameter or the name.
    QStringList fields;
    if (before && after)
        for (const ToolFieldChange& f : toolChanges(*before, *after))
            fields << tr("T%1: %2 %3 → %4")
                          .arg(after->id)
                          .arg(fieldHeader(f.field), QString::fromStdString(f.before), QString::fromStdString(f.after));
    if (after && (!before || before->diameter != after->diameter || before->name != after->name))
        if (const auto mismatch = nameSizeMismatch(*after)) lines << tr("T%1: %2").arg(after->id).arg(coreMessage(*mismatch));
    if (lines.isEmpty()) return {};  // the fields alone are what the operator typed: not asked
    lines = fields + lines;
    lines << tr("Apply the change?");
    return lines.join('\n');
}

bool ToolLibraryDialog::change(const std::optional<Tool>& before, const std::optional<Tool>& after, const QString& text)
{
    if (after) {
        if (const auto problems = toolProblems(*after); !problems.empty()) {
            fail(tr("T%1 not saved: %2").arg(after->id).arg(coreMessage(problems.front().message)));
            return false;
        }
    }
    // What it changes, asked before it is applied; left: the table as it was.
    if (const QString question = editQuestion(before, after); !question.isEmpty()) {
        const bool yes = confirm_ ? confirm_(question) : [&] {
            QMessageBox box(QMessageBox::Question, tr("Change the tool?"), question, QMessageBox::Yes | QMessageBox::No,
                            this);
            box.setObjectName("tools.confirm");
            box.setDefaultButton(QMessageBox::No);
            return box.exec() == QMessageBox::Yes;
        }();
        if (!yes) {
            load(true);
            fail(tr("T%1 not changed").arg(before ? before->id : after->id));
            return false;
        }
    }
    if (!apply(after, before ? before->id : after->id)) return false;
    undo_->push(new ToolEdit(this, before, after, text));
    status_->setText(text);
    status_->setStyleSheet({});
    return true;
}

}  // namespace taiwa::ui
