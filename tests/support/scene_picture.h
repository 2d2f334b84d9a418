// A scene's picture through a given camera, in an offscreen window of its
// own (header only: the support library does not link VTK's rendering or
// Qt Gui, the tests that render do).
#pragma once

#include "viz/render.h"
#include "viz/scene.h"

#include <QImage>

#include <vtkCamera.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include <string>

namespace taiwa::test {

// Null when there is no offscreen window (no display).
inline QImage scenePicture(viz::Scene& scene, vtkCamera* camera, int width, int height)
{
    viz::OffscreenWindow window(width, height);
    if (window.problem()) return {};
    window.window()->AddRenderer(scene.renderer());
    scene.renderer()->GetActiveCamera()->DeepCopy(camera);
    scene.renderer()->ResetCameraClippingRange();
    window.window()->Render();
    const std::string png = viz::pngOf(window.window());
    window.window()->RemoveRenderer(scene.renderer());
    return QImage::fromData(reinterpret_cast<const uchar*>(png.data()), static_cast<int>(png.size()), "PNG")
        .convertToFormat(QImage::Format_RGB32);
}

}  // namespace taiwa::test
