// Placeholder of the ui layer until the station window lands.
#pragma once
namespace taiwa::ui {
int runStation(int argc, char** argv);
}
