// PreviewWidget: the scene, VTK's interactor and the public API of the 3-D
// view around a PreviewWindow (ui/preview_window.h) that renders it. The
// window sits in a container filling this widget, so the two share their
// coordinates: the window's mouse and wheel events arrive here as they are,
// go to a vtkGenericRenderWindowInteractor with the trackball camera style,
// and its render requests become frames of the window. This widget, not the
// window, takes the keyboard focus (StrongFocus, on a click).
#include "ui/preview_widget.h"

#include "ui/preview_window.h"

#include <QCoreApplication>
#include <QMouseEvent>
#include <QPainter>
#include <QVBoxLayout>
#include <QWheelEvent>

#include <vtkCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkInteractorStyleTrackballCamera.h>

#include <algorithm>
#include <cmath>

namespace taiwa::ui {

namespace {
constexpr int kClickSlop = 3;  // pixels the mouse may move and still click
}

PreviewWidget::PreviewWidget(QWidget* parent)
    : QWidget(parent), window_(vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New()),
      interactor_(vtkSmartPointer<vtkGenericRenderWindowInteractor>::New())
{
    setMinimumSize(160, 120);
    setFocusPolicy(Qt::StrongFocus);
    window_->SetReadyForRendering(false);
    window_->SetFrameBlitModeToNoBlit();  // PreviewWindow copies the frame into its own buffer
    window_->SetMultiSamples(0);          // VTK's default multisampling costs 2.4-3.5x on software rendering
    window_->AddRenderer(scene_.renderer());

    interactor_->SetRenderWindow(window_);
    interactor_->EnableRenderOff();  // the window renders in its paintGL only
    interactor_->AddObserver(vtkCommand::RenderEvent, this, &PreviewWidget::onInteractorRender);
    auto style = vtkSmartPointer<vtkInteractorStyleTrackballCamera>::New();
    style->SetDefaultRenderer(scene_.renderer());
    // While the operator drags, the scene draws its level of detail
    // (viz::Scene::setMoving); full detail again in the frame after.
    style->AddObserver(vtkCommand::StartInteractionEvent, this, &PreviewWidget::onInteraction);
    style->AddObserver(vtkCommand::EndInteractionEvent, this, &PreviewWidget::onInteraction);
    interactor_->SetInteractorStyle(style);
    interactor_->Initialize();

    gl_ = new PreviewWindow(window_, this);
    connect(gl_, &PreviewWindow::resized, this, &PreviewWidget::onResized);
    connect(gl_, &QOpenGLWindow::frameSwapped, this, &PreviewWidget::frameShown);
    container_ = QWidget::createWindowContainer(gl_, this);
    container_->setFocusPolicy(Qt::NoFocus);  // the focus stays with this widget
    container_->setMinimumSize(1, 1);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(container_);
}

// The GL window first (it frees VTK's GL objects in its context), while the
// scene and the render window are still there.
PreviewWidget::~PreviewWidget() { delete container_; }

void PreviewWidget::requestFrame()
{
    if (gl_) gl_->update();  // none while the constructor initializes the interactor
}

// A paint event of its own, not update(): that asks the platform for an
// update (a second frame, when the one asked for first is delivered).
void PreviewWidget::requestFrameNow()
{
    if (!gl_) return;
    if (!gl_->isExposed()) return requestFrame();
    QCoreApplication::postEvent(gl_, new QPaintEvent(QRect(QPoint(0, 0), gl_->size())));
}

void PreviewWidget::onInteractorRender(vtkObject*, unsigned long, void*) { requestFrame(); }

void PreviewWidget::onInteraction(vtkObject*, unsigned long event, void*)
{
    scene_.setMoving(event == vtkCommand::StartInteractionEvent);
    requestFrame();
}

void PreviewWidget::onResized(int w, int h)
{
    const double dpr = gl_->devicePixelRatio();
    interactor_->UpdateSize(static_cast<int>(std::lround(w * dpr)), static_cast<int>(std::lround(h * dpr)));
    // Fit the view while nothing is shown yet; afterwards a resize keeps the
    // operator's camera.
    if (!fittedStock_) scene_.setView(view_, static_cast<double>(w) / std::max(h, 1));
}

void PreviewWidget::setPlan(std::shared_ptr<const Plan> plan, std::shared_ptr<sim::StockSimulation> stock)
{
    // An edit of the job keeps the operator's camera; a new stock (another
    // job) is fitted anew with the chosen preset.
    const bool newStock = plan && (!fittedStock_ || !(*fittedStock_ == plan->mmJob.stock));
    if (plan && newStock) fittedStock_ = plan->mmJob.stock;
    scene_.setPlan(std::move(plan), std::move(stock));
    if (newStock) scene_.setView(view_, static_cast<double>(width()) / std::max(height(), 1));
    requestFrameNow();
}

void PreviewWidget::setSelectedStep(int index)
{
    // The step list re-announces its selection with every plan: the same
    // selection draws no frame (a frame of the old plan while the new one is
    // planned would delay the new one's).
    const int before = scene_.selectedStep();
    scene_.setSelectedStep(index);
    if (scene_.selectedStep() != before) requestFrame();
}

void PreviewWidget::setShowStock(bool show)
{
    scene_.setShowStock(show);
    requestFrame();
}

void PreviewWidget::setPathsShown(bool shown)
{
    scene_.setPathsShown(shown);
    requestFrame();
}

void PreviewWidget::setPartShown(bool shown)
{
    scene_.setPartShown(shown);
    requestFrame();
}

void PreviewWidget::frameSelectedStep()
{
    scene_.frameSelectedStep(static_cast<double>(width()) / std::max(height(), 1));
    requestFrame();
}

void PreviewWidget::setStockBefore(bool before)
{
    scene_.setStockBefore(before);
    requestFrame();
}

void PreviewWidget::setSection(std::optional<viz::SectionPlane> plane)
{
    scene_.setSection(plane);
    requestFrame();
}

void PreviewWidget::setScaleNoteText(std::function<std::string(int mm)> text, std::string fontFile)
{
    scene_.setScaleNoteText(std::move(text), std::move(fontFile));
    requestFrame();
}

void PreviewWidget::setDeviationMap(std::shared_ptr<const verify::DeviationMap> map)
{
    // The panel takes its map away on every edit: a frame only when one
    // was shown or is now (a needless frame of the plan being replaced
    // could hold up the new one's).
    const bool shown = scene_.showsDeviation();
    scene_.setDeviationMap(std::move(map));
    if (shown || scene_.showsDeviation()) requestFrame();
}

void PreviewWidget::setView(viz::ViewPreset view)
{
    view_ = view;
    scene_.setView(view_, static_cast<double>(width()) / std::max(height(), 1));
    requestFrame();
}

void PreviewWidget::highlightMove(int step, int move)
{
    scene_.highlightMove(step, move);
    requestFrame();
}

void PreviewWidget::setPlayhead(int step, int move)
{
    scene_.setPlayhead(step, move);
    requestFrame();
}

void PreviewWidget::setTurretTools(std::optional<viz::TurretTools> tools)
{
    scene_.setTurretTools(std::move(tools));
    requestFrame();
}

void PreviewWidget::markPoint(std::optional<Point3> p)
{
    if (!p && !scene_.markedPoint()) return;  // nothing marked, nothing to take away
    scene_.markPoint(p);
    requestFrame();
}

QImage PreviewWidget::grabImage() { return gl_->grabFrame(); }

QWindow* PreviewWidget::glWindow() const { return gl_; }

bool PreviewWidget::drawsFrames() const { return gl_->isExposed(); }

void PreviewWidget::forwardMouse(QMouseEvent* e, unsigned long vtkEvent)
{
    const double dpr = gl_->devicePixelRatio();
    const QPointF p = e->position();
    interactor_->SetEventInformationFlipY(static_cast<int>(p.x() * dpr), static_cast<int>(p.y() * dpr),
                                          e->modifiers() & Qt::ControlModifier ? 1 : 0,
                                          e->modifiers() & Qt::ShiftModifier ? 1 : 0);
    interactor_->InvokeEvent(vtkEvent, e);
}

void PreviewWidget::mousePressEvent(QMouseEvent* e)
{
    setFocus(Qt::MouseFocusReason);
    pressPos_ = e->position().toPoint();
    dragged_ = false;
    switch (e->button()) {
    case Qt::LeftButton: forwardMouse(e, vtkCommand::LeftButtonPressEvent); break;
    case Qt::MiddleButton: forwardMouse(e, vtkCommand::MiddleButtonPressEvent); break;
    case Qt::RightButton: forwardMouse(e, vtkCommand::RightButtonPressEvent); break;
    default: break;
    }
}

void PreviewWidget::mouseMoveEvent(QMouseEvent* e)
{
    if ((e->position().toPoint() - pressPos_).manhattanLength() > kClickSlop) dragged_ = true;
    forwardMouse(e, vtkCommand::MouseMoveEvent);
}

void PreviewWidget::mouseReleaseEvent(QMouseEvent* e)
{
    switch (e->button()) {
    case Qt::LeftButton: forwardMouse(e, vtkCommand::LeftButtonReleaseEvent); break;
    case Qt::MiddleButton: forwardMouse(e, vtkCommand::MiddleButtonReleaseEvent); break;
    case Qt::RightButton: forwardMouse(e, vtkCommand::RightButtonReleaseEvent); break;
    default: break;
    }
    if (e->button() == Qt::LeftButton && !dragged_) {
        const QPointF p = e->position();
        if (auto hit = scene_.pickMove(p.x(), p.y(), width(), height())) emit moveClicked(hit->step, hit->move);
    }
}

// The wheel zooms about the pointer (VTK's own wheel zooms about the
// view's middle): 1.2 times a notch, a touchpad's finer steps in proportion.
void PreviewWidget::wheelEvent(QWheelEvent* e)
{
    const int notches = e->angleDelta().y();
    if (notches == 0) return;
    const QPointF p = e->position();
    scene_.zoomAt(p.x(), p.y(), width(), height(), std::pow(1.2, notches / 120.0));
    e->accept();
    requestFrame();
}

QImage grabWithPreview(QWidget* widget)
{
    QImage image = widget->grab().toImage();
    QPainter painter(&image);
    QList<PreviewWidget*> views = widget->findChildren<PreviewWidget*>();
    if (auto* self = qobject_cast<PreviewWidget*>(widget)) views.push_back(self);
    for (PreviewWidget* view : views) {
        if (!view->isVisible()) continue;
        const QImage frame = view->grabImage();
        if (frame.isNull()) continue;
        // Logical coordinates: the painter follows the image's device pixel ratio.
        painter.drawImage(QRectF(view->mapTo(widget, QPoint(0, 0)), QSizeF(view->size())), frame);
    }
    return image;
}

}  // namespace taiwa::ui
