// Helpers shared by the tests: paths of the source tree, running the taiwa
// executable, temporary folders, reading files.
#pragma once

#include <QString>
#include <QStringList>

#include <string>

namespace taiwa::test {

// Absolute path below the source tree, e.g. sourcePath("resources/samples/x.taiwa").
QString sourcePath(const QString& relative);
// Absolute path below tests/data.
QString dataPath(const QString& relative);

struct RunResult {
    int exitCode = -1;
    QString out;
    QString err;
};
// Runs the built `taiwa` executable with the arguments; 120 s at most.
RunResult runTaiwa(const QStringList& args);

std::string readFile(const QString& path);
void writeFile(const QString& path, const std::string& text);

}  // namespace taiwa::test
