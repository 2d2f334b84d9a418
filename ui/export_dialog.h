// The station's export dialog (docs/station.md, "Export"): one dialog for
// everything an export needs — the folder, the controller dialect, the
// tape's units, whether the sheet carries its pictures (drawn by the core,
// no display needed) and the verification's resolution — instead of a
// folder chooser followed by a dialect box. The folder and the pictures'
// choice are remembered for the next export (QSettings).
#pragma once

#include "model/job.h"

#include <QDialog>
#include <QString>
#include <QStringList>

#include <optional>

class QCheckBox;
class QComboBox;
class QDialogButtonBox;
class QDoubleSpinBox;
class QLineEdit;

namespace taiwa::ui {

struct ExportChoice {
    QString folder;
    QString dialect = QStringLiteral("linuxcnc");
    std::optional<LengthUnit> units;  // none: the job's own
    bool pictures = true;
    double resolution = 0.05;  // mm, the verification's grid before the files are written
};

class ExportDialog : public QDialog {
    Q_OBJECT
public:
    // Widget objectNames: "export.folder", "export.choose", "export.dialect",
    // "export.units", "export.pictures", "export.resolution", "export.buttons".
    // `initial`'s folder empty: the one remembered from the last export.
    ExportDialog(const ExportChoice& initial, const QStringList& dialects, QWidget* parent = nullptr);

    ExportChoice choice() const;
    // Remembers the choice's folder and pictures for next time.
    static void remember(const ExportChoice& c);
    // The remembered folder (where `c` has none) and pictures over `c`.
    static ExportChoice remembered(ExportChoice c);

private:
    void choose();
    void updateOk();

    QLineEdit* folder_ = nullptr;
    QComboBox* dialect_ = nullptr;
    QComboBox* units_ = nullptr;
    QCheckBox* pictures_ = nullptr;
    QDoubleSpinBox* resolution_ = nullptr;
    QDialogButtonBox* buttons_ = nullptr;
};

}  // namespace taiwa::ui
