// Placeholder of the viz layer until the scene code lands.
#pragma once
namespace taiwa::viz {
const char* backendName();
}
