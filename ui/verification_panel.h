// The verification in the station: a Verify button that cuts the current
// plan on the verification's grid (core/verify) on a worker thread, the
// findings listed one a line (faults in red), and a finding chosen in the
// list announced with its step, move and position, which the window passes
// to the step list, the NC view and the 3-D view. A new plan makes the list
// stale until verified again. After a milling job's verification the
// Colour map box shows the finished part coloured by what was found
// (verify/deviation.h) in the 3-D view, its legend beside it.
#pragma once

#include "model/plan.h"
#include "verify/deviation.h"
#include "verify/verify.h"

#include <QThreadPool>
#include <QWidget>

#include <memory>

class QCheckBox;
class QLabel;
class QListWidget;
class QPushButton;

namespace taiwa::ui {

class VerificationPanel : public QWidget {
    Q_OBJECT
public:
    explicit VerificationPanel(QWidget* parent = nullptr);
    ~VerificationPanel() override;

    // The plan the button verifies (nullptr: none; the button is disabled).
    // Findings of an earlier plan are cleared.
    void setPlan(std::shared_ptr<const Plan> plan);
    // Starts the verification on the worker thread (the button does this).
    void verify();
    // Verifies on the calling thread and shows the result (tests).
    void verifyNow();
    bool isBusy() const { return busy_; }
    // The last report shown (empty findings before any).
    const verify::Report& report() const { return report_; }
    QListWidget* list() const { return list_; }
    QCheckBox* colourMapBox() const { return colourMap_; }
    // The last verification's colour map (nullptr before any, for a lathe
    // job and after a new plan).
    const std::shared_ptr<const verify::DeviationMap>& deviationMap() const { return map_; }

protected:
    // The language switched: the buttons, the legend, the summary and the
    // findings in the new one.
    void changeEvent(QEvent* e) override;

signals:
    // The operator chose a finding: its step (-1: the whole job), move (-1:
    // the step as a whole) and worst point.
    void findingSelected(int step, int move, taiwa::Point3 where);
    // A verification finished (its report is report()).
    void verified();
    // The colour map to show in the 3-D view, or nullptr for none: the box
    // ticked or cleared, a new verification with the box ticked, a new plan.
    void colourMapChanged(std::shared_ptr<const taiwa::verify::DeviationMap> map);

private:
    void nameParts();
    // The summary and the findings of the state shown (no plan, not
    // verified, verifying, the report), in the language in force.
    void showReport();
    // A verification's result for the plan of setPlan's `generation` (an
    // older one's is dropped).
    void show(std::uint64_t generation, const verify::Report& r, std::shared_ptr<const verify::DeviationMap> map);
    void showColourMap();
    void onRowChanged(int row);

    QPushButton* run_;
    QLabel* summary_;
    QListWidget* list_;
    QCheckBox* colourMap_;
    QLabel* legend_;
    std::shared_ptr<const Plan> plan_;
    verify::Report report_;
    std::shared_ptr<const verify::DeviationMap> map_;
    std::uint64_t generation_ = 0;  // of setPlan: a result for an older plan is dropped
    bool busy_ = false;
    bool reported_ = false;   // report_ is the current plan's, shown
    bool verifying_ = false;  // the current plan is being verified
    QThreadPool pool_;
};

}  // namespace taiwa::ui
