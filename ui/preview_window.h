// The GL surface of the 3-D preview: a QOpenGLWindow that a VTK generic
// render window draws into, embedded by PreviewWidget through
// QWidget::createWindowContainer. As a window of its own it is drawn and
// swapped alone: a QOpenGLWidget would make Qt compose the whole top-level
// window with OpenGL on every repaint of any widget in it (docs/preview.md
// "Edits"). It takes no keyboard focus and hands its mouse and wheel events
// to the widget that holds it, which drives VTK's interactor.
#pragma once

#include <QImage>
#include <QOpenGLWindow>
#include <QPointer>

#include <vtkSmartPointer.h>

#include <memory>

class QOpenGLFramebufferObject;
class QWidget;
class vtkGenericOpenGLRenderWindow;
class vtkObject;

namespace taiwa::ui {

class PreviewWindow : public QOpenGLWindow {
    Q_OBJECT
public:
    // `vtkWindow` is rendered in paintGL; mouse and wheel events go to
    // `forwardTo` (the widget holding this window).
    PreviewWindow(vtkGenericOpenGLRenderWindow* vtkWindow, QWidget* forwardTo);
    ~PreviewWindow() override;

    // The frame rendered now into an offscreen buffer of the window's size
    // (device pixels), opaque; null before the window was first exposed.
    QImage grabFrame();
    // Frees VTK's GL objects while this window's context is current.
    void finalize();

signals:
    // The window's size in logical pixels, once GL is ready and at each resize.
    void resized(int w, int h);

protected:
    void initializeGL() override;
    void resizeGL(int w, int h) override;
    void paintGL() override;
    bool event(QEvent* e) override;

private:
    void onMakeCurrent(vtkObject*, unsigned long, void*);
    void onIsCurrent(vtkObject*, unsigned long, void* callData);
    // VTK's frame drawn and copied into `framebuffer` (0: the window's back buffer).
    void render(unsigned framebuffer);

    vtkSmartPointer<vtkGenericOpenGLRenderWindow> vtk_;
    QPointer<QWidget> forwardTo_;
    std::unique_ptr<QOpenGLFramebufferObject> grabBuffer_;
    unsigned long observers_[2] = {0, 0};
};

}  // namespace taiwa::ui
