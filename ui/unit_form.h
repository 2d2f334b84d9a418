// The form of one module kind: a QFormLayout of line edits and code
// combo boxes built from FieldSpecs, each with a message label under it.
// Typed text is kept as typed; text that is not a number turns the field red
// with "not a number", and the check diagnostics of the unit are shown on the
// widgets whose field they name.
#pragma once

#include "model/diagnostic.h"
#include "model/job.h"
#include "model/sketch.h"
#include "model/tool.h"
#include "ui/field_spec.h"

#include <QWidget>

#include <optional>
#include <vector>

class QGridLayout;
class QLabel;
class QLineEdit;
class QComboBox;

namespace taiwa::ui {

class UnitForm : public QWidget {
    Q_OBJECT
public:
    // The form of one module kind: its drawing above its fields; widget
    // objectNames "<prefix>.<key>" (prefix: modulePrefix(kind), "m4").
    explicit UnitForm(const ModuleKind& kind, QWidget* parent = nullptr);

    const std::vector<FieldSpec>& fields() const { return fields_; }
    // Shows the unit's values. force = false keeps text the operator is
    // typing (a field whose text is not a number, or parses to the value).
    void setUnit(const MachiningUnit& unit, bool force);
    // Marks the widgets the diagnostics name; returns the ones no widget shows.
    Diagnostics showDiagnostics(const Diagnostics& ofThisUnit);
    bool hasUnparsableText() const;
    // Puts the keyboard focus into the first field (after a unit is added).
    void focusFirstField();
    // The unit's live figure under the drawing (probing: the touches and
    // the fit); hidden when the module has none.
    void setSketch(std::optional<Sketch> sketch);
    // The job around the unit (a turned profile's bar) and the tool library
    // (its finishing tool's nose radius), for the profile editor.
    void setContext(const Job& job, const std::vector<Tool>& library);
    // The editor of a turned profile (module TURN); nullptr for other modules.
    class ProfileEditor* profileEditor() const { return profile_; }
    // The symbol of the field being typed in, marked in the drawing ("sym-T";
    // empty: none), and the line of help under the drawing.
    QString highlightedSymbol() const { return highlighted_; }
    QString helpText() const;

protected:
    // Ctrl+Z / Ctrl+Shift+Z in a field go to the job's undo stack, not to the
    // line edit's own undo.
    bool eventFilter(QObject* watched, QEvent* event) override;
    // The drawing follows the form's width (at most its own size).
    void resizeEvent(QResizeEvent* event) override;
    // The language switched: labels, code meanings, help and drawing in the new one.
    void changeEvent(QEvent* e) override;

signals:
    // A field got a valid value (from typing or from a combo box).
    void edited(int field, std::optional<double> value);
    // A text field (contour names) as typed.
    void textEdited(int field, const QString& text);
    // The unit's name as typed.
    void nameEdited(const QString& name);
    // The operator left a field (Tab, Enter, click elsewhere).
    void fieldLeft();
    // Enter in the last field: on to the next unit, or the step list.
    void lastFieldDone();
    // The unit's module input as a whole after an edit of the profile editor.
    void unitEdited(const taiwa::ModuleInput& after, const QString& text, const QString& mergeKey);

private:
    struct Row {
        QLineEdit* edit = nullptr;
        QComboBox* combo = nullptr;
        QLabel* message = nullptr;
        bool notANumber = false;
        bool fraction = false;  // a whole-number field holds a fraction
    };
    void onTextEdited(int field, const QString& text);
    void setMessage(int field, const QString& message, bool warning = false);

    class SketchView* sketch_ = nullptr;
    class QLabel* drawing_ = nullptr;
    class QLabel* help_ = nullptr;
    int drawingWidth_ = 320;  // the drawing's own width
    int drawingShown_ = 0;    // the width it is drawn at: at most the form's
    void drawDrawing();
    int drawingRoom() const;
    // A label and its field (the buddy: the editor the label names).
    void addRow(const QString& text, QWidget* field, QWidget* buddy);
    // Labels beside the fields, or above them when both do not fit.
    void arrange();
    // Lays the form out at once (after its messages changed), each level of
    // layouts up to the window, not one level per turn of the event loop:
    // the scroll area learns the form's new height before anything is
    // painted, and no wrapped error text is squeezed meanwhile.
    void layOutNow();
    QGridLayout* grid_ = nullptr;
    std::vector<std::pair<QLabel*, QWidget*>> labelled_;
    bool labelsAbove_ = false;
    bool arranged_ = false;
    QString highlighted_;
    void showHelp(int field);  // -1: none
    int helpField_ = -1;       // the field whose help is shown
    // The labels, the code boxes' meanings and the placeholders, in the language in force.
    void nameFields();
    void enterPressed(int field);
    class ProfileEditor* profile_ = nullptr;
    const ModuleKind& kind_;
    ModuleInput current_;  // the unit's module input as last shown
    std::vector<FieldSpec> fields_;
    std::vector<Row> rows_;
    QLineEdit* name_ = nullptr;
    bool updating_ = false;
};

}  // namespace taiwa::ui
