// The scene's shared actor helpers (viz/actors.h).
#include "viz/actors.h"

#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>

#include <algorithm>
#include <cmath>

namespace taiwa::viz {

vtkSmartPointer<vtkActor> actorFor(vtkPolyData* pd, Rgb colour)
{
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputData(pd);
    mapper->ScalarVisibilityOff();
    mapper->StaticOn();  // its data never changes: no pipeline update per frame
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(colour.red(), colour.green(), colour.blue());
    return actor;
}

vtkSmartPointer<vtkActor> lineActor(vtkPolyData* pd, Rgb colour, double width)
{
    auto actor = actorFor(pd, colour);
    actor->GetProperty()->LightingOff();  // lines show their colour exactly
    actor->GetProperty()->SetLineWidth(static_cast<float>(width));
    return actor;
}

double niceLength(double size)
{
    const double target = std::max(size / 5.0, 1.0);
    const double decade = std::pow(10.0, std::floor(std::log10(target)));
    for (double f : {1.0, 2.0, 5.0})
        if (f * decade >= target * 0.7) return f * decade;
    return 10.0 * decade;
}

}  // namespace taiwa::viz
