// The shop's tool library (SQLite, ToolLibrary) as a table the operator
// edits: T number, name, type, diameter, corner radius, taper, flutes,
// flute length, stick-out, holder, life and the life already used. A cell
// typed over is checked (tools/tool_check.h) and saved at once, or refused
// with the reason and put back; a tool can be copied under the next free T
// number or retired (removed); every change is an undo step (Ctrl+Z). The
// selected tool's wear can be reset (a fresh tool was put in). The machine's
// tool table is exported from here: LinuxCNC's tool.tbl or a FANUC program
// of G10 offsets. Every database error is shown, never hidden. On the shop
// server (docs/shop-server.md) a save over a tool another station changed
// meanwhile shows both and asks: keep mine, or take theirs. Before an edit
// is applied, the steps of the open job it changes (another tool chosen,
// or the same tool with other data) and a name that would state another
// diameter are shown, and the operator applies it or leaves it.
#pragma once

#include "model/tool.h"
#include "pipeline/tool_edit_impact.h"

#include <QDialog>

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <vector>

class QLabel;
class QPushButton;
class QTableWidget;
class QTableWidgetItem;
class QUndoStack;

namespace taiwa {
class ToolStore;
}

namespace taiwa::ui {

class ToolLibraryDialog : public QDialog {
    Q_OBJECT
public:
    enum Column { Id, Name, Type, Diameter, Corner, Taper, Flutes, FluteLength, Stickout, Holder, HolderDiameter, Life, Used, ColumnCount };

    explicit ToolLibraryDialog(QWidget* parent = nullptr);
    ~ToolLibraryDialog() override;
    QTableWidget* table() const { return table_; }
    QUndoStack* undoStack() const { return undo_; }
    // True when a tool was changed (the window re-plans with the new library).
    bool changed() const { return changed_; }
    // The tools as read last.
    const std::vector<Tool>& tools() const { return tools_; }
    // The status line's text (what was saved, or why not).
    QString status() const;

    // Replaces tool `before.id` (or adds `after`, or with no `after` removes
    // it) in the library, as one undo step; false with the reason shown when
    // it is refused or the database fails.
    bool change(const std::optional<Tool>& before, const std::optional<Tool>& after, const QString& text);
    // Copies the selected tool to the next free T number; retires (removes) it.
    void copySelected();
    void retireSelected();
    // Writes the machine's tool table: `fanuc` a G10 program, else LinuxCNC's tool.tbl.
    bool exportToolTable(const QString& path, bool fanuc);

    // What an edit would change in the open job (the station plans it:
    // pipeline/tool_edit_impact.h); without one, only the name is looked at.
    using Impact = std::function<ToolEditImpact(const std::vector<Tool>& before, const std::vector<Tool>& after)>;
    void setImpact(Impact impact) { impact_ = std::move(impact); }
    // Asks whether to apply an edit that changes steps or leaves a name
    // stating another diameter; by default a question box ("tools.confirm",
    // Yes applies). Tests answer it.
    using Confirm = std::function<bool(const QString& question)>;
    void setConfirm(Confirm confirm) { confirm_ = std::move(confirm); }
    // The question an edit from `before` to `after` asks ("" when none).
    QString editQuestion(const std::optional<Tool>& before, const std::optional<Tool>& after) const;

private:
    friend class ToolEdit;
    // A length or a time to 0.001, as the table and the conflict's question write it.
    static QString num(double v);
    // A tool in one line, for the conflict's question.
    static QString summary(const Tool& t);
    QString fieldHeader(const std::string& key) const;
    // Reads the library and fills the table; the status line says how many
    // tools unless `keepStatus` (it says what was just done, or refused).
    void load(bool keepStatus = false);
    void resetWear();
    void onItemChanged(QTableWidgetItem* item);
    void exportAsked();
    // Applies one side of an edit to the database: save `tool`, or remove `id`.
    bool apply(const std::optional<Tool>& tool, int id);
    // The same on the shop server, at the version read; a conflict asks
    // (a message box "tools.conflict": "tools.keepMine", "tools.takeTheirs").
    bool applyOnServer(const std::optional<Tool>& tool, int id);
    void fail(const QString& message);
    int selectedRow() const;
    // The selected tool; none, with "Select a tool first." shown, when no row is.
    std::optional<Tool> selectedTool();

    QTableWidget* table_;
    QLabel* status_;
    QPushButton* reset_;
    QUndoStack* undo_;
    std::vector<Tool> tools_;
    // The shop server's store when the setting names one, and the version
    // of each tool as read (none: the SQLite file, edited as always).
    std::unique_ptr<ToolStore> server_;
    std::map<int, std::int64_t> versions_;
    bool changed_ = false;
    bool filling_ = false;
    Impact impact_;
    Confirm confirm_;
};

}  // namespace taiwa::ui
