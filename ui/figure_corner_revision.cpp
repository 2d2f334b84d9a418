// The figure panel's corner revision (figure_panel.h): the chamfers or the
// roundings of the figure's contours highlighted in the view, one picked
// there, its value in the spin box, and a new value written into the text
// as one undoable edit, every other byte kept.
#include "ui/figure_panel.h"

#include "figure/figure_contour.h"
#include "figure/figure_text.h"
#include "ui/job_document.h"

#include <QDoubleSpinBox>
#include <QLabel>
#include <QPlainTextEdit>
#include <QToolButton>

#include <algorithm>

namespace taiwa::ui {

using figure::ContourCorner;

void FigurePanel::reviseCorners(std::optional<ContourCorner::Kind> kind)
{
    revising_ = kind;
    picked_.reset();
    reviseChamfer_->setChecked(kind == ContourCorner::Kind::Chamfer);
    reviseRounding_->setChecked(kind == ContourCorner::Kind::Round);
    showRevision();
}

void FigurePanel::pickCorner(const QString& contour, int index)
{
    if (!revising_) return;
    const figure::EvaluatedContour* c = evaluation().findContour(contour.toStdString());
    if (!c || index < 0 || index >= static_cast<int>(c->corners.size()) ||
        c->corners[static_cast<std::size_t>(index)].kind != *revising_)
        return;
    picked_ = CornerRef{contour, index};
    showRevision();
    // Its value selected in the text: the number the spin box rewrites.
    updating_ = true;
    editor_->setTextCursor(valueCursor(c->corners[static_cast<std::size_t>(index)]));
    updating_ = false;
    markLines();
    value_->setFocus(Qt::OtherFocusReason);
    value_->selectAll();
}

// Every corner of the kind under revision highlighted, or the one picked
// with its value in the spin box.
void FigurePanel::showRevision()
{
    if (!revising_) {
        view_->setHighlightedCorners({});
        revision_->hide();
        return;
    }
    std::vector<CornerRef> all;
    for (const figure::EvaluatedContour& c : evaluation().contours)
        for (std::size_t i = 0; i < c.corners.size(); ++i)
            if (c.corners[i].kind == *revising_) all.push_back({QString::fromStdString(c.name), static_cast<int>(i)});
    if (picked_ && std::find(all.begin(), all.end(), *picked_) == all.end()) picked_.reset();
    view_->setHighlightedCorners(picked_ ? std::vector<CornerRef>{*picked_} : all);
    revision_->show();
    const bool chamfer = *revising_ == ContourCorner::Kind::Chamfer;
    if (!picked_) {
        value_->setEnabled(false);
        if (all.empty()) revisionText_->setText(chamfer ? tr("The figure's contours have no chamfer.")
                                                        : tr("The figure's contours have no rounding."));
        else revisionText_->setText((chamfer ? tr("Click a chamfer in the view to change it (%1 in the figure).")
                                             : tr("Click a rounding in the view to change it (%1 in the figure)."))
                                        .arg(all.size()));
        return;
    }
    const ContourCorner& corner =
        evaluation().findContour(picked_->contour.toStdString())->corners[static_cast<std::size_t>(picked_->index)];
    revisionText_->setText((chamfer ? tr("%1: chamfer between %2 and %3, length") : tr("%1: rounding between %2 and %3, radius"))
                               .arg(picked_->contour, QString::fromStdString(corner.between[0]),
                                    QString::fromStdString(corner.between[1])));
    updating_ = true;
    value_->setValue(corner.value);
    updating_ = false;
    value_->setEnabled(true);
}

// The picked corner's value rewritten in the text, every other byte kept:
// one undoable edit.
void FigurePanel::reviseValue(double value)
{
    if (updating_ || !picked_) return;
    const Job& job = doc_->job();
    const auto revised = figure::reviseCorner(job.figure, picked_->contour.toStdString(), picked_->index, value);
    if (!revised) {
        revisionText_->setText(tr("The text has a refusal: correct it before revising a corner."));
        return;
    }
    if (*revised == job.figure) return;
    Job j = job;
    j.figure = *revised;
    doc_->breakMerge();
    doc_->edit(j, tr("Revise corner %1 of %2").arg(picked_->index + 1).arg(picked_->contour));
    doc_->breakMerge();
}

}  // namespace taiwa::ui
