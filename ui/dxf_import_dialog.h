// DXF import in the station (docs/dxf-import.md): a drawing's contours turned
// into figure elements appended to the job's figure. The dialog reads the
// file, lists its layers with their entity counts (all ticked at first), and
// takes the gap tolerance; on every change it reads the drawing again and
// shows what it found — closed and open contours, gaps with their positions,
// branches, entities skipped, contours left out — and the figure text it
// would add, named so that nothing the job's figure defines is taken again
// and written in the job's length unit. Import appends that text.
#pragma once

#include "model/job.h"

#include <QDialog>
#include <QString>

#include <set>
#include <string>

class QDialogButtonBox;
class QDoubleSpinBox;
class QLabel;
class QListWidget;
class QPlainTextEdit;

namespace taiwa::ui {

class DxfImportDialog : public QDialog {
    Q_OBJECT
public:
    // Widget objectNames: "dxf.file", "dxf.choose", "dxf.layers", "dxf.gap",
    // "dxf.report", "dxf.text", "dxf.buttons".
    DxfImportDialog(const Job& job, QWidget* parent = nullptr);

    // Reads the drawing at `path` (the Choose… button asks for one).
    void setPath(const QString& path);
    // The figure text Import adds (empty: nothing to add), in the job's unit.
    const std::string& figureText() const { return text_; }
    // What the last reading found, as the report shows it.
    QString report() const;
    // The job's figure with the drawing's elements appended.
    std::string appendedTo(const std::string& figure) const;

private:
    void choose();
    void read(bool layersFromFile);

    Job job_;
    QString path_;
    std::string text_;
    QLabel* file_ = nullptr;
    QListWidget* layers_ = nullptr;
    QDoubleSpinBox* gap_ = nullptr;
    QPlainTextEdit* report_ = nullptr;
    QPlainTextEdit* preview_ = nullptr;
    QDialogButtonBox* buttons_ = nullptr;
    bool reading_ = false;
};

}  // namespace taiwa::ui
