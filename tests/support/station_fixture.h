// The station windows of the GUI tests: a job file opened and its full plan
// run and delivered before the test looks (header only: the support library
// does not link the widgets, the GUI tests do).
#pragma once

#include "support/support.h"
#include "ui/file_actions.h"
#include "ui/plan_runner.h"
#include "ui/station_window.h"

#include <QCoreApplication>
#include <QtTest>

namespace taiwa::test {

// The pending full plan run now and its results (tape, preview, lists)
// delivered.
inline void settle(ui::StationWindow& w)
{
    w.planRunner()->flush();
    QTRY_VERIFY(!w.planRunner()->isBusy());
    QCoreApplication::sendPostedEvents();
}

// The window shown with the job at `path` (relative to the source tree)
// opened and settled; false when it could not be opened.
inline bool showSettled(ui::StationWindow& w, const QString& path)
{
    w.show();
    if (!w.fileActions()->openPath(sourcePath(path))) return false;
    settle(w);
    return true;
}

}  // namespace taiwa::test
