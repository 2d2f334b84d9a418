// The editor of a turned profile (module TURN), under the unit's form: the
// profile view, the profile table (one row per element: kind, end point X
// as a diameter and Z, arc radius or centre, the corner at its end, Ra and
// tolerance), the grinding-allowance table, and the corner revision of seed
// 002 (every chamfer or rounding highlighted, one picked, its size changed
// as one edit). Every change is handed on as the whole profile after it,
// for one undoable edit of the job; diagnostics naming "rows[3].radius" or
// "allowances[1].grooveWidth" mark their cell.
#pragma once

#include "model/diagnostic.h"
#include "model/job.h"
#include "modules/module_kind.h"
#include "model/tool.h"
#include "model/turned.h"

#include <QWidget>

#include <optional>
#include <vector>

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QTableWidget;
class QTableWidgetItem;
class QVBoxLayout;

namespace taiwa::ui {

class ProfileView;

class ProfileEditor : public QWidget {
    Q_OBJECT
public:
    // Widget objectNames start with `prefix` ("turn"): "turn.view",
    // "turn.rows", "turn.allowances", "turn.addRow", "turn.cornerSize",
    // "turn.rowsTitle", …
    explicit ProfileEditor(const QString& prefix, QWidget* parent = nullptr);

    // The profile as the job holds it. force = false keeps a cell whose text
    // is not a number (the operator is typing).
    void setProfile(const turning::TurnedProfile& p, bool force);
    // What the view needs besides the profile: the bar and the library (the
    // finishing tool's nose radius for the deformed profile).
    void setContext(std::optional<BarStock> bar, const std::vector<Tool>& library);
    // The unit being edited and its module's door: the deformed profile
    // drawn is the one its plan cuts (ModuleKind::turned: the nose radius of
    // the finishing insert the plan takes, with the unit's pins). Drawn at
    // the next setProfile, which the unit form calls right after it: one
    // deformation per refresh.
    void setUnit(const ModuleKind& kind, ModuleInput unit);
    // Marks the cells the diagnostics name; returns those it does not show.
    Diagnostics showDiagnostics(const Diagnostics& ofThisUnit);

    ProfileView* view() const { return view_; }
    QTableWidget* rowsTable() const { return rows_; }
    QTableWidget* allowanceTable() const { return allowances_; }
    // Corner revision: every corner of that kind highlighted (None ends it).
    void reviseCorners(turning::CornerKind kind);
    // The corner under revision picked: only it highlighted, its size editable.
    void pickCorner(const QString& id);

    // Columns of the profile table and of the allowance table.
    enum RowColumn { EdgeCol, KindCol, XCol, ZCol, RCol, CXCol, CZCol, CornerCol, SizeCol, RaCol, TolCol, PitchCol, RowColumns };
    enum AllowanceColumn { AEdgeCol, AAllowCol, AAdjustCol, AGrooveCol, AWidthCol, ADepthCol, AllowanceColumns };
    // A check's field that names a cell ("allowances[2].grooveWidth") as the
    // tables show it ("allowance row 2, Width"); empty for any other field.
    static QString cellName(const QString& field);

protected:
    // The language switched: headings, titles, buttons, code cells and the
    // corner revision's line in the new one.
    void changeEvent(QEvent* e) override;

signals:
    void edited(const taiwa::turning::TurnedProfile& after, const QString& text, const QString& mergeKey);

private:
    static QStringList rowHeadings();
    static QStringList allowanceHeadings();
    // The code cells' items: their text and value.
    static std::vector<std::pair<QString, int>> elementKinds();
    static std::vector<std::pair<QString, int>> cornerKinds();
    void nameParts();
    void buildRevision(QVBoxLayout* outer);  // the constructor's parts
    void followPicks();
    // What the corner revision's line says: how many corners to pick from, or the picked one's size.
    QString revisionLine() const;
    void fill(bool force);
    void refreshView();
    void onRowItem(QTableWidgetItem* item);
    void onAllowanceItem(QTableWidgetItem* item);
    void addRow(bool atCurrent);
    void deleteRow();
    void addAllowance();
    void deleteAllowance();
    void commit(const turning::TurnedProfile& after, const QString& text, const QString& key);
    void editCornerSize();

    QString prefix_;
    turning::TurnedProfile profile_;
    std::optional<BarStock> bar_;
    std::vector<Tool> library_;
    const ModuleKind* kind_ = nullptr;
    std::optional<ModuleInput> unit_;
    ProfileView* view_ = nullptr;
    QCheckBox* exaggerate_ = nullptr;  // the allowances drawn kExaggeration times as deep
    static constexpr int kExaggeration = 10;
    QTableWidget* rows_ = nullptr;
    QTableWidget* allowances_ = nullptr;
    QLabel* messages_ = nullptr;
    QLabel* rowsTitle_ = nullptr;
    QLabel* allowanceTitle_ = nullptr;
    QPushButton* addAllowance_ = nullptr;
    QWidget* revision_ = nullptr;
    QLabel* revisionText_ = nullptr;
    QLineEdit* cornerSize_ = nullptr;
    turning::CornerKind revising_ = turning::CornerKind::None;
    QString revisedCorner_;
    bool updating_ = false;
    std::vector<std::pair<int, int>> notANumber_;  // (row, column) of the profile table
};

}  // namespace taiwa::ui
