// The figure panel of a milling job: the job's figure elements
// (Job::figure, docs/figure-elements.md) as text in a monospace editor, the
// text's refusals listed under it as "line:column: message" (their lines
// marked; a click on one puts the cursor there), and the 2-D view of what
// the text defines (figure_view.h). Picking an element in the view selects
// its statement, and the cursor on a statement picks its element. The
// corner revision of seed 002: "Revise chamfer" / "Revise rounding" show
// every corner of that kind in their own colour, a click leaves one, and
// its value changed in the spin box rewrites that number in the text
// (figure::reviseCorner). Every change of the text is an undoable edit of
// the job (typing in one visit of the editor is one undo step). For a unit
// that clears an area by drawn passes, the passes are drawn in the view
// (passes_bar.h).
#pragma once

#include "figure/figure_eval.h"
#include "ui/figure_view.h"

#include <QWidget>

#include <optional>
#include <vector>

class QDoubleSpinBox;
class QLabel;
class QListWidget;
class QListWidgetItem;
class QPlainTextEdit;
class QTextCursor;
class QToolButton;

namespace taiwa::ui {

class JobDocument;

class FigurePanel : public QWidget {
    Q_OBJECT
public:
    // Widget objectNames: "figure.text", "figure.refusals", "figure.view",
    // "figure.reviseChamfer", "figure.reviseRounding", "figure.revisionText",
    // "figure.cornerValue", "figure.fit", "figure.title".
    explicit FigurePanel(JobDocument* doc, QWidget* parent = nullptr);

    QPlainTextEdit* editor() const { return editor_; }
    QListWidget* refusalList() const { return refusals_; }
    FigureView* view() const { return view_; }
    QDoubleSpinBox* cornerValue() const { return value_; }
    // The drawing of passes for the current unit (passes_bar.h).
    class PassesBar* passesBar() const { return passes_; }
    void setCurrentUnit(int unit);
    // What the view draws: the text evaluated (when the text is refused,
    // the statements before the refused one), and every refusal listed.
    const figure::Evaluation& evaluation() const { return view_->evaluation(); }
    const std::vector<figure::FigureError>& refusals() const { return errors_; }

    // The element or contour picked, in the view and in the editor.
    QString selected() const { return view_->selected(); }
    void select(const QString& name);
    // Corner revision: every corner of that kind highlighted (nullopt ends it).
    void reviseCorners(std::optional<figure::ContourCorner::Kind> kind);
    void pickCorner(const QString& contour, int index);
    std::optional<CornerRef> pickedCorner() const { return picked_; }

signals:
    // An element or contour picked in the view or by the cursor (empty: none).
    void selectionChanged(const QString& name);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;
    // The language switched: the heading, the buttons, the refusals and
    // the corner revision's line in the new one.
    void changeEvent(QEvent* e) override;

private:
    void nameParts();
    void listRefusals();
    void refresh();
    void onTextChanged();
    void evaluateText();
    void markLines();
    void goToRefusal(QListWidgetItem* item);
    void selectStatement(const QString& name);
    void onCursorMoved();
    void showRevision();
    void reviseValue(double value);
    int positionOf(int line, int column) const;  // 1-based line, column in bytes
    QTextCursor valueCursor(const figure::ContourCorner& corner) const;

    JobDocument* doc_;
    QPlainTextEdit* editor_ = nullptr;
    QListWidget* refusals_ = nullptr;
    FigureView* view_ = nullptr;
    QToolButton* reviseChamfer_ = nullptr;
    QToolButton* reviseRounding_ = nullptr;
    QToolButton* fit_ = nullptr;
    QLabel* title_ = nullptr;
    QWidget* revision_ = nullptr;
    QLabel* revisionText_ = nullptr;
    QDoubleSpinBox* value_ = nullptr;
    class PassesBar* passes_ = nullptr;
    std::vector<figure::Definition> definitions_;  // of what the view draws
    std::vector<figure::FigureError> errors_;
    std::optional<figure::ContourCorner::Kind> revising_;
    std::optional<CornerRef> picked_;
    std::string shownText_;  // the figure text last evaluated
    Stock shownStock_;
    QString shownPath_;
    bool evaluatedOnce_ = false;
    bool updating_ = false;
};

}  // namespace taiwa::ui
