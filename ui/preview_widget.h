// The 3-D preview of the station window: the viz scene of a plan shown
// through vtkGenericOpenGLRenderWindow in a QOpenGLWindow (PreviewWindow)
// that this widget holds in a window container, so that the view's frames
// and the other widgets' repaints do not wait for each other. Left drag
// rotates, middle drag or shift + left drag pans, the wheel zooms; a click
// on a path emits the move under the cursor. QWidget::grab() of a window
// holding it lacks the view: grabWithPreview() puts it in.
#pragma once

#include "viz/render.h"
#include "viz/scene.h"

#include <QImage>
#include <QPoint>
#include <QWidget>

#include <vtkSmartPointer.h>

#include <memory>
#include <optional>

class QWindow;
class vtkGenericOpenGLRenderWindow;
class vtkGenericRenderWindowInteractor;
class vtkObject;

namespace taiwa::ui {

class PreviewWindow;

class PreviewWidget : public QWidget {
    Q_OBJECT
public:
    explicit PreviewWidget(QWidget* parent = nullptr);
    ~PreviewWidget() override;

    // The plan and, if made already, its stock simulation (see viz::Scene).
    void setPlan(std::shared_ptr<const Plan> plan, std::shared_ptr<sim::StockSimulation> stock = nullptr);
    void setSelectedStep(int index /* -1 all */);
    void setShowStock(bool show);
    // viz::Scene::setPathsShown: the tool paths drawn or not.
    void setPathsShown(bool shown);
    // viz::Scene::setPartShown: the part (pockets' outlines, turned part) drawn or not.
    void setPartShown(bool shown);
    // viz::Scene::frameSelectedStep: the camera frames the selected step.
    void frameSelectedStep();
    // The stock before the selected step rather than after it.
    void setStockBefore(bool before);
    // viz::Scene::setSection: the stock cut open by a plane.
    void setSection(std::optional<viz::SectionPlane> plane);
    // viz::Scene::setDeviationMap: the verification's colour map.
    void setDeviationMap(std::shared_ptr<const verify::DeviationMap> map);
    // Camera preset, fitted to the stock and the paths.
    void setView(viz::ViewPreset view);
    void highlightMove(int step, int move);
    // A red ball at a point (a verification finding), the view moved to it;
    // nothing removes it.
    void markPoint(std::optional<taiwa::Point3> p);
    // Viz::Scene::setPlayhead: the stock after moves 0..move of the step.
    void setPlayhead(int step, int move);
    // Viz::Scene::setTurretTools: a two-path job's turrets' tools.
    void setTurretTools(std::optional<viz::TurretTools> tools);
    // The current frame (rendered now if needed).
    QImage grabImage();

    // The GL window the view is drawn in (for tests: the window system's
    // mouse events arrive there).
    QWindow* glWindow() const;

    // The scene, for tests and the NC view's picking.
    const viz::Scene& scene() const { return scene_; }
    // The axes' scale note in the station's language (viz::Scene::setScaleNoteText).
    void setScaleNoteText(std::function<std::string(int mm)> text, std::string fontFile);

    // Whether the view draws its frames now (its GL window is exposed): a
    // frameShown() follows every change then.
    bool drawsFrames() const;

signals:
    void moveClicked(int step, int move);
    // A frame of the view is on screen (swapped).
    void frameShown();

protected:
    void mousePressEvent(QMouseEvent* e) override;
    void mouseMoveEvent(QMouseEvent* e) override;
    void mouseReleaseEvent(QMouseEvent* e) override;
    void wheelEvent(QWheelEvent* e) override;

private:
    void requestFrame();  // a frame of the GL window when the platform next updates it
    // A frame at the next pass of the event loop: a new plan's, which the
    // operator waits for (X11 delivers an update on a 5 ms timer,
    // QWindow::requestUpdate; camera moves keep that pacing). Plate.taiwa,
    // value typed to the frame shown: 34.6-34.9 against 38.8-40.9 ms.
    void requestFrameNow();
    void onResized(int w, int h);
    void onInteractorRender(vtkObject*, unsigned long, void*);
    void onInteraction(vtkObject*, unsigned long event, void*);
    void forwardMouse(QMouseEvent* e, unsigned long vtkEvent);

    viz::Scene scene_;
    vtkSmartPointer<vtkGenericOpenGLRenderWindow> window_;
    vtkSmartPointer<vtkGenericRenderWindowInteractor> interactor_;
    PreviewWindow* gl_ = nullptr;  // owned by its container
    QWidget* container_ = nullptr;  // a child of this widget filling it
    viz::ViewPreset view_ = viz::ViewPreset::Iso;
    std::optional<Stock> fittedStock_;  // the stock the camera was last fitted to
    QPoint pressPos_;
    bool dragged_ = false;
};

// QWidget::grab() of `widget` with the frame of every visible PreviewWidget
// in it painted at its place (the GL window is not in the widgets' backing
// store). For screenshots and tests.
QImage grabWithPreview(QWidget* widget);

}  // namespace taiwa::ui
