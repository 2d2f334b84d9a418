// The technology data of the job: for α1, α2, α3, β2 and γ the value of the
// material table, a per-job override field (empty = use the table) and the
// value in force. OK applies the overrides as one undoable edit.
#pragma once

#include "model/job.h"

#include <QDialog>

#include <array>
#include <optional>

class QLabel;
class QLineEdit;

namespace taiwa::ui {

class TechnologyDialog : public QDialog {
    Q_OBJECT
public:
    TechnologyDialog(const Job& job, QWidget* parent = nullptr);
    // The overrides as typed; nullopt while a field is not a number.
    std::optional<TechnologyOverrides> overrides() const;

private:
    void refresh();
    Job job_;
    std::array<QLineEdit*, 6> edits_{};  // one per technology value (α1, α2, α3, β2, γ, step-over)
    std::array<QLabel*, 6> effective_{};
    QLabel* error_;
};

}  // namespace taiwa::ui
