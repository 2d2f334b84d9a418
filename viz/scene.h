// The 3-D preview scene of a plan, as a vtkRenderer: the stock (a
// translucent block, or the simulated stock after the selected step), the
// finished pockets' outlines at the top face and the floor, the tool paths
// of every step (feeds and rapids in their colours, the selected step
// emphasised, the others dimmed), the tool at the selected path's
// start or at the end of the highlighted move (the NC block the operator
// is on), one highlighted move, axes with a scale note, camera presets,
// a section plane through the stock and the verification's colour map; a
// two-path lathe's balanced roughing with every turret's tool where core's
// timeline has it (setTurretTools). The
// offscreen renderer and the preview widget both show this scene; it is the
// one door between the core's types and VTK.
#pragma once

#include "model/plan.h"
#include "verify/two_path_timeline.h"
#include "viz/path_geometry.h"
#include "viz/render.h"
#include "viz/solids.h"
#include "viz/surface_light.h"

#include <vtkActor.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace taiwa::sim {
class HeightField;
class StockSimulation;
}
namespace taiwa::verify {
struct DeviationMap;
}

class vtkAxesActor;
class vtkMatrix4x4;
class vtkTextActor;

namespace taiwa::viz {

// A two-path job's turrets (docs/two-path-lathe.md "In the station"): the
// balanced roughing's step, the side of the spindle axis each path's
// turret stands on, and where each path's tool tip is at each of the step's
// moves (core's timeline: toolPlaces, verify/two_path_timeline.h).
struct TurretTools {
    int step = -1;          // the roughing step, an index into Plan::steps
    std::vector<int> side;  // by path: +1 path 1's side of the axis, -1 the other (X mirrored)
    ToolPlaces places;      // in path 1's coordinates, by the step's move
};

struct MoveRef {
    int step = -1;  // index into Plan::steps
    int move = -1;  // index into the step's ToolPath::moves
    friend bool operator==(const MoveRef&, const MoveRef&) = default;
};

class Scene {
public:
    Scene();
    ~Scene();
    Scene(const Scene&) = delete;
    Scene& operator=(const Scene&) = delete;

    vtkRenderer* renderer() const { return renderer_; }

    // Builds the scene for the plan (nullptr: an empty scene). Keeps the
    // selection, stock and view settings when they still apply. `stock`, if
    // given, is the plan's stock simulation made elsewhere (the station
    // makes it on its planning thread); otherwise the scene makes one when
    // the stock is first shown.
    //
    // A plan of the same kind as the one shown (milling) updates the scene
    // in place (viz/scene_update.cpp): each block of units whose paths are
    // unchanged keeps its actors and their GPU buffers, and so does each
    // step's own (the selected step's), the stock's edges and the axes stay
    // while the stock does, the camera is not touched; the picture is the
    // one a new scene would draw of the plan.
    void setPlan(std::shared_ptr<const Plan> plan, std::shared_ptr<sim::StockSimulation> stock = nullptr);
    const Plan* plan() const { return plan_.get(); }
    // What the last setPlan did: built anew, or updated in place keeping
    // `pathsKept` steps' own path actors (a selected step's), and of the
    // merged path blocks (below) keeping `blocksKept` with their actors and
    // making `blocksMade`.
    struct PlanUpdate {
        bool inPlace = false;
        int pathsKept = 0;
        int blocksKept = 0, blocksMade = 0;
    };
    const PlanUpdate& lastPlanUpdate() const { return lastUpdate_; }
    // -1: every step alike; k: step k emphasised, the tool at its start,
    // the stock (when shown) as it is after step k.
    void setSelectedStep(int index);
    int selectedStep() const { return selected_; }
    // With a step selected, only its paths: the other steps' are hidden,
    // not dimmed (the sheet's pictures; a large job's other paths cost the
    // renderer more than the picture shows of them).
    void setOtherPathsHidden(bool hidden);
    // The tool paths drawn or not (the View menu's and the view's own
    // switch): off, the colour map and the stock show unhidden. The
    // highlighted move goes with them; the tool stays. viz/scene_camera.cpp.
    void setPathsShown(bool shown);
    bool pathsShown() const { return pathsShown_; }
    // The part drawn or not: a milling job's finished pockets' outlines, a
    // lathe job's turned part (viz/scene_camera.cpp). There are no fixtures
    // in the station's view to switch (the sheet's setup picture has them).
    void setPartShown(bool shown);
    bool partShown() const { return partShown_; }
    // The probing units' touches and fitted centres, drawn in work
    // coordinates (viz/scene_probe.cpp); nullptr when the job has none.
    vtkActor* probeActor() const { return probe_.Get(); }
    // The simulated stock instead of the translucent block.
    void setShowStock(bool show);
    // The simulated stock as it is before the selected step instead of
    // after it (with no step selected: the fresh stock instead of the
    // finished part).
    void setStockBefore(bool before);
    bool stockBefore() const { return stockBefore_; }
    // The move drawn in the highlight colour, the tool (of its step) at its
    // end; (-1, -1) for none (the tool back at the selected step's start).
    void highlightMove(int step, int move);
    MoveRef highlightedMove() const { return highlighted_; }
    // Play block by block: the stock as it is after moves 0..move of step
    // `step` (what they cut in palette::kRemoved), the step selected, the
    // move highlighted with the tool at its end; step -1 ends it (the
    // stock as the selection says again).
    void setPlayhead(int step, int move);
    MoveRef playhead() const { return playhead_; }
    // Where the tool is drawn (its tip), if it is.
    std::optional<Point3> toolPosition() const { return toolAt_; }
    // A two-path job's turrets (nothing: a job of one path). With its
    // roughing step selected, each path's tool is drawn where `places` has
    // it at the highlighted move's end (at the start with none), in its
    // turret's colour (palette::kTool, kTool2, kTool3), on its side of the
    // axis; on the other steps the step's tool alone, as on a one-path
    // lathe. A new plan (setPlan) drops it.
    void setTurretTools(std::optional<TurretTools> tools);
    // Where each path's tool is drawn (its tip: X along the spindle, Z the
    // radius, below zero on the other side), by path; empty: not drawn.
    const std::vector<Point3>& turretToolPositions() const { return turretAt_; }
    // A marker (a small red ball) at a point of interest, a verification
    // finding, the camera moved (not turned) to put it in the middle of the
    // view; nothing removes it. viz/scene_marker.cpp.
    void markPoint(std::optional<Point3> p);
    std::optional<Point3> markedPoint() const { return marked_; }
    // A section through the stock (nothing: none): the simulated stock, or
    // the colour map, shown cut open by the plane, the face it cuts in
    // palette::kSection; the paths stay whole. A lathe job's view is a
    // section already: there it changes nothing.
    void setSection(std::optional<SectionPlane> plane);
    const std::optional<SectionPlane>& section() const { return section_; }
    // The verification's colour map (verify/deviation.h) on the finished
    // part in place of the stock, whatever step is selected; nullptr: the
    // stock again. A new plan (setPlan) drops it.
    void setDeviationMap(std::shared_ptr<const verify::DeviationMap> map);
    bool showsDeviation() const { return deviation_ != nullptr; }
    // While the operator turns, pans or zooms the camera (the preview
    // widget's interaction start and end): the path lines one pixel wide,
    // the glass tray hidden (the stock's edges show it), the axes' labels,
    // the scale note and the tool left out and, above
    // kLodAbove path segments, each path actor of kLodMin segments or more
    // drawn from its decimated twin (viz/path_lod.h, at most kLodBudget
    // segments, within a thousandth of the scene's diagonal), made on the
    // first motion and kept with the plan. Full detail and widths again
    // when it stops. viz/scene_lod.cpp.
    void setMoving(bool moving);
    bool moving() const { return moving_; }
    // The simulated stock and the colour map lit on the processor, per
    // quad for the camera, and drawn unlit (viz/surface_light.h: on a
    // software renderer half the frame's cost), or (false) lit by VTK per
    // pixel; the same picture either way, within a level of a colour.
    void setLightOnProcessor(bool on);
    bool lightOnProcessor() const { return lightOnProcessor_; }
    // Path segments drawn now (the decimated twins' while moving).
    std::size_t drawnPathSegments() const;
    static constexpr std::size_t kLodAbove = 200'000;
    static constexpr std::size_t kLodMin = 10'000;
    static constexpr std::size_t kLodBudget = 100'000;
    // Camera preset fitted to the stock and the paths for a viewport of
    // width / height = aspect.
    void setView(ViewPreset preset, double aspect);
    // The union of the stock's box and the paths (xmin, xmax, ymin, ymax, zmin, zmax).
    std::array<double, 6> bounds() const;

    // Zoom by `factor` (> 1 nearer) about pixel (x, y) of a viewport of
    // width x height pixels (x to the right, y downward): the point of the
    // focal plane under that pixel stays under it, in perspective and in
    // parallel projection. viz/scene_camera.cpp.
    void zoomAt(double x, double y, int width, int height, double factor);
    // The camera turned as it is, moved and zoomed to frame the selected
    // step's path (a lathe step: its path in the section), or the whole
    // scene when no step with a path is selected. viz/scene_camera.cpp.
    void frameSelectedStep(double aspect);
    // Where a world point appears in a viewport of width x height pixels
    // (x to the right, y downward from the top-left corner), for the
    // current camera.
    std::array<double, 2> toPixel(const Point3& p, int width, int height) const;
    // The move whose drawn path passes nearest to pixel (x, y) within
    // `tolerance` pixels, among the steps shown emphasised; nothing if none.
    std::optional<MoveRef> pickMove(double x, double y, int width, int height, double tolerance = 6.0) const;

    // The axes' scale note for axes of `mm` millimetres, in its caller's
    // language: "axes 50 mm" (taiwa render's pictures) unless given its
    // translation (the station's 3-D view), written with `fontFile` (a
    // TrueType font with its glyphs, "軸") when given. This scene's only;
    // the note shown changes with it.
    void setScaleNoteText(std::function<std::string(int mm)> text, std::string fontFile = {});
    // The note shown.
    std::string scaleNote() const;

    // A milling plan's path actors (viz/scene_blocks.cpp): per block, its
    // feeds and its rapids actor; empty for a lathe job.
    std::vector<std::array<const vtkActor*, 2>> pathBlockActors() const;
    // The steps of each block (indices into Plan::steps, in plan order).
    std::vector<std::vector<int>> pathBlockSteps() const;
    // The machined free-form surfaces' actor (viz/scene_surface.h; null:
    // none) and its triangles; hidden while the colour map is shown.
    const vtkActor* machinedSurfaceActor() const { return surface_; }
    std::size_t machinedSurfaceTriangles() const { return surfaceTriangles_; }

private:
    struct StepActors {
        PathGeometry geometry;
        vtkSmartPointer<vtkActor> feeds, rapids;
    };
    // Step k's own geometry and actors (made on first use: to draw it
    // selected, to pick or highlight its moves); null actors for a step
    // without a path.
    StepActors& stepActors(int k);
    vtkMatrix4x4* worldToView(int width, int height) const;
    // The path line actors made so far (merged pair, steps' own).
    std::vector<vtkActor*> pathActors() const;
    // Each path actor drawn from its full or decimated geometry as
    // moving_ says (scene_lod.cpp).
    void updateLod();
    // The glass tray drawn in the opaque pass at the far plane's depth.
    static void drawAsBackdrop(vtkActor* actor);
    // The axes' labels, the scale note and the tool: hidden while the
    // camera moves (scene_lod.cpp).
    void showWhenStill();
    // A path line's width: `still`, or 1 while the camera moves.
    float pathWidth(float still) const { return moving_ ? 1.0f : still; }
    void clear();
    // setPlan's in-place update, when canUpdateInPlace (scene_update.cpp).
    bool canUpdateInPlace(const Plan& next) const;
    void updateInPlace(std::shared_ptr<const Plan> plan, std::shared_ptr<sim::StockSimulation> stock);
    // The scale note and axes for a stock of this size (made once per length).
    void makeAxes(double axisLength);
    // The scale note's text and font for axes of axisLength_.
    void writeScaleNote();
    // Takes a prop out of the renderer keeping its GPU resources (it is
    // shown again later); RemoveActor frees them.
    void detach(vtkProp* prop);
    void updateEmphasis();
    void updateStock();
    void updateTool();
    // The turrets' tools of a selected roughing step (true), or nothing to draw.
    bool updateTurretTools(const Tool& tool, const TurnStep& step, int move);
    void updateHighlight();
    // A lathe job (a bar, turned profiles): the part revolved, the grinding
    // stock in its own colour, the bar as glass.
    void buildLathe();
    // A lathe job's selected step: the bar as that step leaves it, revolved
    // (sim/turned_stock.h), and the step's path in the half-plane drawn
    // over it; the finished part again when no step is selected.
    void updateLatheStep();
    // Merged mode (viz/scene_blocks.cpp): the paths of the plan's steps
    // with a path, in blocks of units (blocks_, blockOf_, pathSegments_);
    // the blocks of `kept` whose steps have the same paths are taken over
    // with their actors (counted in lastUpdate_), the others made. Not yet
    // in the renderer.
    struct PathBlock {
        std::vector<int> steps;  // indices into Plan::steps, in plan order
        MergedPaths paths;       // first/count per position in `steps`
        vtkSmartPointer<vtkActor> feeds, rapids;
        std::size_t key = 0;  // of its steps' paths
    };
    void mergePaths(std::vector<PathBlock> kept = {}, const Plan* old = nullptr);
    // Frees a dropped block's GPU resources and twins.
    void releaseBlock(PathBlock& block);

    vtkSmartPointer<vtkRenderer> renderer_;
    std::shared_ptr<const Plan> plan_;
    std::shared_ptr<sim::StockSimulation> simulation_;
    std::vector<StepActors> steps_;
    // A milling plan's paths are drawn merged: one feeds and one rapids
    // actor per block of units (at most kMaxBlocks blocks), and only the
    // selected step's own. Every actor costs the renderer more than its
    // segments: thousands of them far more, and even plate.taiwa's 59 path
    // actors (2,499 segments) cost llvmpipe 3-5 ms a frame more than its 13
    // merged ones; making and freeing a few VTK objects per step took
    // longer than drawing them (3,000 units: 11,600 steps); one pair for
    // all paths made every edit merge them all again.
    static constexpr int kMaxBlocks = 64;
    std::vector<PathBlock> blocks_;
    // Per step: its block and place in it (-1: no path).
    std::vector<std::pair<int, int>> blockOf_;
    int shownStep_ = -1;  // the step whose own actors are in the renderer
    vtkSmartPointer<vtkActor> stock_, stockEdges_, partEdges_, tool_, highlight_, marker_, cap_;
    vtkSmartPointer<vtkActor> surface_;  // the machined free-form surfaces
    vtkSmartPointer<vtkActor> probe_;    // the probing units' touches and fitted centres
    // Made from the plan's setups (viz/scene_probe.cpp); nullptr: no probing unit with a fit.
    vtkSmartPointer<vtkActor> probeMarks() const;
    std::size_t surfaceTriangles_ = 0;
    std::optional<SectionPlane> section_;
    std::shared_ptr<const verify::DeviationMap> deviation_;
    std::optional<Point3> marked_;
    vtkSmartPointer<vtkAxesActor> axes_;
    vtkSmartPointer<vtkTextActor> scaleNote_;
    int selected_ = -1;
    MoveRef playhead_;
    bool showStock_ = false;
    bool othersHidden_ = false;
    bool pathsShown_ = true;
    bool partShown_ = true;
    bool stockBefore_ = false;
    bool lathe_ = false;  // the plan is a lathe job's: no height field; turning paths in the half-plane
    std::vector<vtkSmartPointer<vtkActor>> latheParts_, latheStep_;
    MoveRef highlighted_;
    std::optional<Point3> toolAt_;
    std::optional<TurretTools> turrets_;
    std::vector<vtkSmartPointer<vtkActor>> turretTools_;  // paths 2, 3's (path 1's: tool_)
    std::vector<Point3> turretAt_;
    bool moving_ = false;
    bool tray_ = false;  // stock_ is the glass tray (the stock hidden)
    std::size_t pathSegments_ = 0;  // of the plan's paths (each once)
    // A path actor's own mapper and its decimated twin's, once made.
    struct Twin {
        vtkSmartPointer<vtkMapper> full, lod;
    };
    std::map<vtkActor*, Twin> twins_;
    double twinTolerance_ = 0;  // the twins' decimation tolerance
    PlanUpdate lastUpdate_;
    OutlineCache outlines_;  // the pockets' sampled outlines, per unit
    double axisLength_ = 0.0;  // of axes_, milling jobs
    std::function<std::string(int mm)> scaleNoteText_ = [](int mm) { return "axes " + std::to_string(mm) + " mm"; };
    std::string scaleNoteFont_;  // empty: VTK's own font
    bool lightOnProcessor_ = true;
    SurfaceLighting stockLight_;  // stock_ when it is a surface lit on the processor
    unsigned long lightObserver_ = 0;  // the renderer's start event: stockLight_.update
};

}  // namespace taiwa::viz
