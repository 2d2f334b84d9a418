// PreviewWidget: VTK rendering inside a QOpenGLWidget. The generic render
// window uses Qt's context: it asks to be made current (WindowMakeCurrentEvent)
// and whether it is (WindowIsCurrentEvent), renders only inside paintGL
// (ReadyForRendering), after which its display framebuffer is blitted into
// the widget's (defaultFramebufferObject()). Frame presentation is Qt's, so
// WindowFrameEvent needs no answer. Mouse events go to a
// vtkGenericRenderWindowInteractor with the trackball camera style; its
// render requests become update() calls.
#include "ui/preview_widget.h"

#include <QMouseEvent>
#include <QOpenGLContext>
#include <QWheelEvent>

#include <vtkCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkOpenGLState.h>

#include <algorithm>
#include <cmath>

namespace taiwa::ui {

namespace {
constexpr int kClickSlop = 3;  // pixels the mouse may move and still click
}

PreviewWidget::PreviewWidget(QWidget* parent)
    : QOpenGLWidget(parent), window_(vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New()),
      interactor_(vtkSmartPointer<vtkGenericRenderWindowInteractor>::New())
{
    setMinimumSize(160, 120);
    setFocusPolicy(Qt::StrongFocus);
    window_->SetReadyForRendering(false);
    window_->SetFrameBlitModeToNoBlit();  // paintGL copies the frame into Qt's framebuffer
    window_->SetMultiSamples(0);          // VTK's default multisampling costs 2.4-3.5x on software rendering
    window_->AddRenderer(scene_.renderer());
    window_->AddObserver(vtkCommand::WindowMakeCurrentEvent, this, &PreviewWidget::onMakeCurrent);
    window_->AddObserver(vtkCommand::WindowIsCurrentEvent, this, &PreviewWidget::onIsCurrent);

    interactor_->SetRenderWindow(window_);
    interactor_->EnableRenderOff();  // we render in paintGL only
    interactor_->AddObserver(vtkCommand::RenderEvent, this, &PreviewWidget::onInteractorRender);
    auto style = vtkSmartPointer<vtkInteractorStyleTrackballCamera>::New();
    style->SetDefaultRenderer(scene_.renderer());
    // While the operator drags, the scene draws its level of detail
    // (viz::Scene::setMoving); full detail again in the frame after.
    style->AddObserver(vtkCommand::StartInteractionEvent, this, &PreviewWidget::onInteraction);
    style->AddObserver(vtkCommand::EndInteractionEvent, this, &PreviewWidget::onInteraction);
    interactor_->SetInteractorStyle(style);
    interactor_->Initialize();
}

PreviewWidget::~PreviewWidget()
{
    makeCurrent();
    window_->Finalize();  // frees VTK's GL objects while Qt's context is current
    doneCurrent();
}

// The context only: QOpenGLWidget::makeCurrent() would also rebind the
// widget's framebuffer behind VTK's cached state, and VTK would then attach
// its own buffers to Qt's framebuffer.
void PreviewWidget::onMakeCurrent(vtkObject*, unsigned long, void*)
{
    if (context() && QOpenGLContext::currentContext() != context()) context()->makeCurrent(context()->surface());
}

void PreviewWidget::onIsCurrent(vtkObject*, unsigned long, void* callData)
{
    *static_cast<bool*>(callData) = context() && QOpenGLContext::currentContext() == context();
}

void PreviewWidget::onInteractorRender(vtkObject*, unsigned long, void*) { update(); }

void PreviewWidget::onInteraction(vtkObject*, unsigned long event, void*)
{
    scene_.setMoving(event == vtkCommand::StartInteractionEvent);
    update();
}

void PreviewWidget::initializeGL()
{
    window_->SetOwnContext(false);
    window_->OpenGLInitContext();
}

void PreviewWidget::resizeGL(int w, int h)
{
    const double dpr = devicePixelRatioF();
    const int pw = static_cast<int>(std::lround(w * dpr)), ph = static_cast<int>(std::lround(h * dpr));
    window_->SetSize(pw, ph);
    interactor_->UpdateSize(pw, ph);
    // Fit the view while nothing is shown yet; afterwards a resize keeps the
    // operator's camera.
    if (!fittedStock_) scene_.setView(view_, static_cast<double>(w) / std::max(h, 1));
}

void PreviewWidget::paintGL()
{
    // Qt has bound the widget's framebuffer and set its own GL state: VTK's
    // cached state is stale. Render, then copy VTK's frame into Qt's buffer.
    vtkOpenGLState* state = window_->GetState();
    state->Reset();
    state->ResetFramebufferBindings();
    state->Push();
    state->vtkglDepthFunc(GL_LEQUAL);  // Qt leaves GL_LESS; VTK expects GL_LEQUAL
    window_->SetReadyForRendering(true);
    window_->Render();
    window_->SetReadyForRendering(false);
    state->PushDrawFramebufferBinding();
    state->vtkglBindFramebuffer(GL_DRAW_FRAMEBUFFER, defaultFramebufferObject());
    state->vtkglDrawBuffer(GL_COLOR_ATTACHMENT0);
    window_->BlitDisplayFramebuffer();
    // VTK leaves alpha below 1 where the background and the translucent
    // stock are; an opaque window ignores it, but grabFramebuffer() (and so
    // QWidget::grab) would premultiply it into near-black. Make it opaque.
    state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
    state->vtkglClearColor(0.0, 0.0, 0.0, 1.0);
    state->vtkglClear(GL_COLOR_BUFFER_BIT);
    state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    state->PopDrawFramebufferBinding();
    state->Pop();
}

void PreviewWidget::setPlan(std::shared_ptr<const Plan> plan, std::shared_ptr<sim::StockSimulation> stock)
{
    // An edit of the job keeps the operator's camera; a new stock (another
    // job) is fitted anew with the chosen preset.
    const bool newStock = plan && (!fittedStock_ || !(*fittedStock_ == plan->mmJob.stock));
    if (plan && newStock) fittedStock_ = plan->mmJob.stock;
    scene_.setPlan(std::move(plan), std::move(stock));
    if (newStock) scene_.setView(view_, static_cast<double>(width()) / std::max(height(), 1));
    update();
}

void PreviewWidget::setSelectedStep(int index)
{
    // The step list re-announces its selection with every plan: the same
    // selection draws no frame (a frame of the old plan while the new one is
    // planned would delay the new one's).
    const int before = scene_.selectedStep();
    scene_.setSelectedStep(index);
    if (scene_.selectedStep() != before) update();
}

void PreviewWidget::setShowStock(bool show)
{
    scene_.setShowStock(show);
    update();
}

void PreviewWidget::setStockBefore(bool before)
{
    scene_.setStockBefore(before);
    update();
}

void PreviewWidget::setSection(std::optional<viz::SectionPlane> plane)
{
    scene_.setSection(plane);
    update();
}

void PreviewWidget::setDeviationMap(std::shared_ptr<const verify::DeviationMap> map)
{
    scene_.setDeviationMap(std::move(map));
    update();
}

void PreviewWidget::setView(viz::ViewPreset view)
{
    view_ = view;
    scene_.setView(view_, static_cast<double>(width()) / std::max(height(), 1));
    update();
}

void PreviewWidget::highlightMove(int step, int move)
{
    scene_.highlightMove(step, move);
    update();
}

void PreviewWidget::setPlayhead(int step, int move)
{
    scene_.setPlayhead(step, move);
    update();
}

void PreviewWidget::markPoint(std::optional<Point3> p)
{
    if (!p && !scene_.markedPoint()) return;  // nothing marked, nothing to take away
    scene_.markPoint(p);
    update();
}

QImage PreviewWidget::grabImage() { return grabFramebuffer(); }

void PreviewWidget::forwardMouse(QMouseEvent* e, unsigned long vtkEvent)
{
    const double dpr = devicePixelRatioF();
    const QPointF p = e->position();
    interactor_->SetEventInformationFlipY(static_cast<int>(p.x() * dpr), static_cast<int>(p.y() * dpr),
                                          e->modifiers() & Qt::ControlModifier ? 1 : 0,
                                          e->modifiers() & Qt::ShiftModifier ? 1 : 0);
    interactor_->InvokeEvent(vtkEvent, e);
}

void PreviewWidget::mousePressEvent(QMouseEvent* e)
{
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

void PreviewWidget::wheelEvent(QWheelEvent* e)
{
    const double dpr = devicePixelRatioF();
    const QPointF p = e->position();
    interactor_->SetEventInformationFlipY(static_cast<int>(p.x() * dpr), static_cast<int>(p.y() * dpr));
    if (e->angleDelta().y() > 0) interactor_->InvokeEvent(vtkCommand::MouseWheelForwardEvent, e);
    else if (e->angleDelta().y() < 0) interactor_->InvokeEvent(vtkCommand::MouseWheelBackwardEvent, e);
}

}  // namespace taiwa::ui
