// PreviewWindow: VTK rendering inside a QOpenGLWindow. The generic render
// window uses this window's context: it asks to be made current
// (WindowMakeCurrentEvent) and whether it is (WindowIsCurrentEvent), renders
// only inside paintGL or grabFrame (ReadyForRendering) into its own
// framebuffer, which is then blitted into the window's back buffer (Qt swaps
// after paintGL) or into the grab's framebuffer object. Mouse and wheel
// events are sent on to the holding widget (as VTK's QVTKOpenGLStereoWidget
// does, QTBUG-61836); the window never takes the keyboard focus, so keys and
// shortcuts stay with the widgets.
#include "ui/preview_window.h"

#include <QCoreApplication>
#include <QOpenGLContext>
#include <QOpenGLFramebufferObject>
#include <QWidget>

#include <vtkCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkOpenGLState.h>

#include <cmath>

namespace taiwa::ui {

PreviewWindow::PreviewWindow(vtkGenericOpenGLRenderWindow* vtkWindow, QWidget* forwardTo)
    : QOpenGLWindow(QOpenGLWindow::NoPartialUpdate), vtk_(vtkWindow), forwardTo_(forwardTo)
{
    setFlag(Qt::WindowDoesNotAcceptFocus);
    observers_[0] = vtk_->AddObserver(vtkCommand::WindowMakeCurrentEvent, this, &PreviewWindow::onMakeCurrent);
    observers_[1] = vtk_->AddObserver(vtkCommand::WindowIsCurrentEvent, this, &PreviewWindow::onIsCurrent);
}

PreviewWindow::~PreviewWindow()
{
    finalize();
    vtk_->RemoveObserver(observers_[0]);
    vtk_->RemoveObserver(observers_[1]);
}

void PreviewWindow::finalize()
{
    if (!isValid()) return;
    makeCurrent();
    grabBuffer_.reset();
    vtk_->Finalize();  // frees VTK's GL objects while the context is current
    doneCurrent();
}

// The context only: QOpenGLWindow::makeCurrent() would also rebind the
// window's framebuffer behind VTK's cached state.
void PreviewWindow::onMakeCurrent(vtkObject*, unsigned long, void*)
{
    QOpenGLContext* ctx = context();
    if (ctx && QOpenGLContext::currentContext() != ctx && handle()) ctx->makeCurrent(this);
}

void PreviewWindow::onIsCurrent(vtkObject*, unsigned long, void* callData)
{
    *static_cast<bool*>(callData) = context() && QOpenGLContext::currentContext() == context();
}

void PreviewWindow::initializeGL()
{
    vtk_->SetOwnContext(false);
    vtk_->OpenGLInitContext();
}

void PreviewWindow::resizeGL(int w, int h)
{
    const double dpr = devicePixelRatio();
    vtk_->SetSize(static_cast<int>(std::lround(w * dpr)), static_cast<int>(std::lround(h * dpr)));
    emit resized(w, h);
}

void PreviewWindow::render(unsigned framebuffer)
{
    // Qt may have bound its own framebuffer and set GL state: VTK's cached
    // state is stale. Render, then copy VTK's frame into the target.
    vtkOpenGLState* state = vtk_->GetState();
    state->Reset();
    state->ResetFramebufferBindings();
    state->Push();
    state->vtkglDepthFunc(GL_LEQUAL);  // VTK expects GL_LEQUAL
    vtk_->SetReadyForRendering(true);
    vtk_->Render();
    vtk_->SetReadyForRendering(false);
    state->PushDrawFramebufferBinding();
    state->vtkglBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
    state->vtkglDrawBuffer(framebuffer == 0 ? GL_BACK : GL_COLOR_ATTACHMENT0);
    vtk_->BlitDisplayFramebuffer();
    // VTK leaves alpha below 1 where the background and the translucent
    // stock are; the window ignores it, but a grabbed image would
    // premultiply it into near-black. Make it opaque.
    state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
    state->vtkglClearColor(0.0, 0.0, 0.0, 1.0);
    state->vtkglClear(GL_COLOR_BUFFER_BIT);
    state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    state->PopDrawFramebufferBinding();
    state->Pop();
}

void PreviewWindow::paintGL() { render(defaultFramebufferObject()); }

QImage PreviewWindow::grabFrame()
{
    if (!isValid()) return {};
    makeCurrent();
    const int* px = vtk_->GetSize();
    const QSize size(px[0], px[1]);
    if (!grabBuffer_ || grabBuffer_->size() != size) grabBuffer_ = std::make_unique<QOpenGLFramebufferObject>(size);
    render(grabBuffer_->handle());
    QImage image = grabBuffer_->toImage();
    image.setDevicePixelRatio(devicePixelRatio());
    return image;
}

bool PreviewWindow::event(QEvent* e)
{
    switch (e->type()) {
    case QEvent::MouseButtonPress:
    case QEvent::MouseButtonRelease:
    case QEvent::MouseButtonDblClick:
    case QEvent::MouseMove:
    case QEvent::Wheel:
        // Same place in the widget: the container fills it.
        if (forwardTo_) return QCoreApplication::sendEvent(forwardTo_, e);
        return false;
    default: return QOpenGLWindow::event(e);
    }
}

}  // namespace taiwa::ui
