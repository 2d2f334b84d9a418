// Placeholder of the viz layer until the scene code lands.
#include "viz/viz.h"
#include <vtkVersion.h>
namespace taiwa::viz {
const char* backendName() { return vtkVersion::GetVTKVersion(); }
}
