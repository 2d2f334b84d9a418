// Placeholder of the ui layer until the station window lands.
#include "ui/ui.h"
#include <cstdio>
namespace taiwa::ui {
int runStation(int, char**) { std::fputs("taiwa: the station window is not built yet\n", stderr); return 1; }
}
