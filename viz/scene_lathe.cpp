// A lathe job's scene (viz::Scene): the turned part revolved about the
// spindle axis, the grinding stock in its own colour, the bar as glass, and
// the selected step's bar and path in the half-section.
#include "viz/scene.h"

#include "model/turned_geometry.h"
#include "sim/turned_stock.h"
#include "viz/actors.h"
#include "viz/palette.h"
#include "viz/solids.h"

#include <vtkAxesActor.h>
#include <vtkCellArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace taiwa::viz {

void Scene::buildLathe()
{
    const BarStock& bar = *plan_->mmJob.bar;
    // The part: each turned unit's deformed profile (what the lathe cuts),
    // the edges as drawn in the part's colour, the grinding stock (moved
    // and side edges) and the relief grooves in the machined colour.
    for (const TurnedPart& part : plan_->turned) {
        std::vector<turning::Segment> finished, ground;
        for (const auto& e : part.deformed.edges)
            (e.origin == turning::Origin::Original ? finished : ground).push_back(e.geometry);
        for (const auto* chain : {&finished, &ground}) {
            if (chain->empty()) continue;
            // Each run of consecutive edges revolved on its own.
            std::vector<turning::Segment> run;
            const auto flush = [&] {
                if (run.empty()) return;
                auto actor = actorFor(revolvedChain(run), chain == &ground ? palette::kMachined : palette::kStock);
                actor->GetProperty()->SetAmbient(0.3);
                actor->GetProperty()->SetDiffuse(0.7);
                actor->SetVisibility(partShown_);
                renderer_->AddActor(actor);
                latheParts_.push_back(actor);
                run.clear();
            };
            for (const auto& seg : *chain) {
                if (!run.empty() && turning::dist(run.back().b, seg.a) > 1e-6) flush();
                run.push_back(seg);
            }
            flush();
        }
    }
    // The bar as glass: its outline revolved.
    const double r = bar.diameter / 2, b = bar.bore / 2, z0 = bar.face - bar.length, z1 = bar.face;
    const std::vector<turning::Segment> outline{turning::lineSegment({z1, b}, {z1, r}), turning::lineSegment({z1, r}, {z0, r}),
                                                turning::lineSegment({z0, r}, {z0, b})};
    stock_ = actorFor(revolvedChain(outline), palette::kStockEdges);
    stock_->GetProperty()->SetOpacity(0.15);
    renderer_->AddActor(stock_);
    const double axisLength = niceLength(bar.diameter);
    axes_ = labelledAxes(axisLength, 14, "Z", "", "X");  // the spindle axis runs along the view's X
    showWhenStill();
    renderer_->AddActor(axes_);
}

void Scene::updateLatheStep()
{
    for (auto& a : latheStep_) renderer_->RemoveActor(a);
    latheStep_.clear();
    const Step* step = selected_ >= 0 ? &plan_->steps[static_cast<std::size_t>(selected_)] : nullptr;
    const bool show = step && turnOf(*step);
    for (auto& a : latheParts_) a->SetVisibility(partShown_ && !show);
    if (!show) return;
    // The stock after the step, each loop of the half-section revolved over
    // the half turn behind the section, so that the section shows.
    for (const auto& loop : sim::turnedStockAfter(*plan_, selected_)) {
        std::vector<turning::Segment> chain;
        for (std::size_t i = 0; i < loop.size(); ++i) {
            const turning::ZR a = loop[i], b = loop[(i + 1) % loop.size()];
            if (turning::dist(a, b) > 1e-9) chain.push_back(turning::lineSegment(a, b));
        }
        if (chain.empty()) continue;
        auto actor = actorFor(revolvedChain(chain, true), palette::kStock);
        actor->GetProperty()->SetAmbient(0.3);
        actor->GetProperty()->SetDiffuse(0.7);
        renderer_->AddActor(actor);
        latheStep_.push_back(actor);
    }
    // The step's path in the section's upper half-plane ((z, 0, r), a hair
    // in front of it): feeds and rapids through the programmed points.
    const TurnPath& p = turnOf(*step)->path;
    for (const bool rapids : {false, true}) {
        auto points = vtkSmartPointer<vtkPoints>::New();
        auto lines = vtkSmartPointer<vtkCellArray>::New();
        turning::ZR at = p.start;
        for (const auto& m : p.moves) {
            if ((m.kind == TurnMove::Rapid) == rapids) {
                std::vector<turning::ZR> pts{at, m.end};
                if (m.kind == TurnMove::ArcCW || m.kind == TurnMove::ArcCCW) {
                    const auto arc = turning::arcSegment(at, m.end, m.centre, m.kind == TurnMove::ArcCCW);
                    pts.clear();
                    const int n = std::max(2, static_cast<int>(std::ceil(turning::sweep(arc) / 0.05)));
                    for (int i = 0; i <= n; ++i) pts.push_back(turning::pointAt(arc, turning::length(arc) * i / n));
                }
                lines->InsertNextCell(static_cast<int>(pts.size()));
                for (const auto& q : pts) lines->InsertCellPoint(points->InsertNextPoint(q.z, -0.05, q.r));
            }
            at = m.end;
        }
        auto pd = vtkSmartPointer<vtkPolyData>::New();
        pd->SetPoints(points);
        pd->SetLines(lines);
        auto actor = lineActor(pd, rapids ? palette::kRapid : palette::kFeed, rapids ? 1.0 : 2.0);
        actor->SetVisibility(pathsShown_);
        renderer_->AddActor(actor);
        latheStep_.push_back(actor);
    }
}

}  // namespace taiwa::viz
