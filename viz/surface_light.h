// The stock surface's light, computed on the processor: the colours VTK's
// own lighting gives it (ambient and diffuse from the renderer's
// directional lights, both sides lit), one factor per flat quad for the
// camera, drawn unlit. Mesa's llvmpipe, the station's usual renderer,
// shades a lit pixel at about twice the cost of an unlit one: on
// plate.taiwa's view (836 x 425, the stock shown) VTK's lighting of the
// stock took 8 of a frame's 17.6 ms (bench_viz_step BM_FrameParts). Here a
// surface of a few thousand quads is lit in a fraction of a millisecond,
// again only when the camera or the lights have changed.
#pragma once

#include <vtkSmartPointer.h>

#include <vector>

class vtkActor;
class vtkPolyData;
class vtkRenderer;

namespace taiwa::viz {

// A surface lit here has, per point, its unlit colours (RGB, unsigned
// char) and, per cell, the cell's outward unit normal; each cell has
// points of its own, so one cell's light never changes another's. Its
// point scalars ("Colors") are what is drawn.
inline constexpr const char* kBaseColours = "BaseColors";
inline constexpr const char* kQuadNormals = "QuadNormals";

// The surface's drawn colours, lit as VTK lights them for `renderer`'s
// active camera and lights: a material of `ambient` and `diffuse` (no
// specular), every light switched on taken as directional (VTK's default;
// the scene's lights are headlight and camera lights), a face seen from
// behind lit on its back (VTK's two-sided lighting). The actor drawing it
// has no transform of its own. False, and nothing changed, when the
// surface lacks the arrays above.
bool lightSurface(vtkPolyData* surface, vtkRenderer* renderer, double ambient, double diffuse);

// Keeps one actor's surface lit for the camera: set() it and call update()
// before each frame (viz::Scene does, on the renderer's start event).
class SurfaceLighting {
public:
    // The actor drawn with its surface lit here (its property's lighting
    // turned off, its colours shown as they are); nullptr: none.
    void set(vtkActor* actor, double ambient, double diffuse);
    // Lights the surface again when the camera's orientation (its position
    // too, in perspective), the lights or the surface changed since.
    void update(vtkRenderer* renderer);

private:
    vtkSmartPointer<vtkActor> actor_;
    double ambient_ = 0, diffuse_ = 0;
    std::vector<double> litFor_;  // what the colours were lit for
};

}  // namespace taiwa::viz
