// runStation: the QApplication, the translator and the station window.
#include "ui/ui.h"

#include "ui/language.h"
#include "ui/station_window.h"

#include <QApplication>

namespace taiwa::ui {

int runStation(int& argc, char** argv, const QString& jobPath)
{
    QApplication app(argc, argv);
    QApplication::setOrganizationName("Taiwa");
    QApplication::setApplicationName("taiwa");
    installTranslator(app);
    StationWindow window(jobPath);
    window.show();
    return QApplication::exec();
}

}  // namespace taiwa::ui
