// The NC view: the posted tape in a read-only, highlighted text view with the
// dialect chooser above it and the block count under it. A click on a line
// names the (step, move) it came from through PostedProgram::lines;
// selectMove() does the reverse.
#pragma once

#include "post/post.h"

#include <QWidget>

#include <memory>
#include <vector>

class QComboBox;
class QTextDocument;
class QLabel;
class QPlainTextEdit;

namespace taiwa::ui {

class NcHighlighter;
class NcDocumentMaker;

// The dialect last chosen in any window (the settings' "nc/dialect"),
// which a new job takes; linuxcnc until one is chosen.
QString lastChosenDialect();
void rememberDialect(const QString& dialect);

class NcView : public QWidget {
    Q_OBJECT
public:
    explicit NcView(QWidget* parent = nullptr);
    ~NcView() override;

    // The dialect chosen in the combo box ("linuxcnc", "fanuc").
    QString dialect() const;
    // Shows `dialect` as chosen (the plan runner's, which the program is
    // posted in), without announcing it as a change.
    void setDialect(const QString& dialect);
    // Shows a program; `lines` has one entry per line of `nc`. Its text is
    // the one prepared, if it was (prepareProgram), else put in here.
    void setProgram(const QString& nc, const std::vector<BlockSource>& lines);
    // Starts putting a program's text in a document on a thread of its own,
    // for setProgram to take later (a large tape: tens of ms).
    void prepareProgram(const QString& nc);
    // Whether the text of `nc` is prepared and waits to be shown.
    bool isPrepared(const QString& nc) const;
    // How many programs were shown from a prepared text (tests).
    int preparedShown() const;
    // Shows why there is no program (input errors, planning failure).
    void setMessage(const QString& text);
    // Greys the program while it is not the current job's (input errors).
    void setStale(bool stale);
    // Selects and shows the first line posted from (step, move); false if none.
    bool selectMove(int step, int move);
    // Scrolls to the first line of a step (its header comment) without
    // emitting moveSelected; -1 does nothing.
    void showStep(int step);
    QPlainTextEdit* text() const { return text_; }
    const NcHighlighter* highlighter() const { return highlighter_; }
    // The (step, move) the line under the text cursor was posted from;
    // step -1 for lines that belong to no move (header, comments).
    BlockSource currentSource() const;
    // The line drawn as the current block (a band across the view), -1 none.
    int highlightedLine() const { return highlightedLine_; }

signals:
    void dialectChanged(const QString& dialect);
    // The operator put the cursor on a line posted from (step, move).
    void moveSelected(int step, int move);

protected:
    // The language switched: the heading and the block count in the new one.
    void changeEvent(QEvent* e) override;

private:
    void nameParts();
    void onCursorMoved();
    // The NC view coloured by the rules of the dialect chosen.
    void useRulesOf(const QString& dialect);
    void showText(const QString& text);
    QComboBox* dialect_;
    QLabel* label_ = nullptr;  // "NC dialect:" (its own pointer: path 2's view renames its parts)
    QLabel* summary_;
    QPlainTextEdit* text_;
    NcHighlighter* highlighter_ = nullptr;
    std::unique_ptr<NcDocumentMaker> maker_;
    std::unique_ptr<QTextDocument> document_;  // the text shown (none: the view's own, empty)
    std::vector<BlockSource> lines_;
    bool selecting_ = false;
    int highlightedLine_ = -1;
};

}  // namespace taiwa::ui
