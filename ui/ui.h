// Entry point of the station window for app/cli.cpp: creates the
// QApplication (with the chosen language) and the StationWindow, and runs
// the event loop.
#pragma once

#include <QString>

namespace taiwa::ui {

// jobPath empty = a new job.
int runStation(int& argc, char** argv, const QString& jobPath);

}  // namespace taiwa::ui
