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
// The build folder (build/), and the taiwa executable built in it.
QString buildDir();
QString taiwaBinary();

struct RunResult {
    int exitCode = -1;
    QString out;
    QString err;
};
// Runs the built `taiwa` executable with the arguments; 120 s at most. Unless
// `env` sets it, TAIWA_TOOL_DB points at a fresh library in a temporary folder
// shared by the test process, so tests never touch the user's library.
RunResult runTaiwa(const QStringList& args, const QStringList& env = {});

// The path of that per-test-process tool library (created on first use by taiwa).
QString testToolDb();

// For tests that open the station: QStandardPaths' test mode, autosave,
// the tool library and the verification cache in `dir` (a temporary
// folder), no questions asked (TAIWA_NO_PROMPTS).
void isolateStation(const QString& dir);

// The shipped dialects' and machines' file stems ("fanuc", "vmc"): every
// resources/dialects/*.json and resources/machines/*.json, in the order the
// program lists them (core/builtin_data.cmake hands its list to the tests).
QStringList shippedDialects();
QStringList shippedMachines();
// The shipped dialects that write milling tapes (all), lathe tapes (all but
// Klartext's), a probing unit's programs or a two-path lathe's (the ISO
// ones), by each file's "syntax".
enum class DialectWrites { MillingTapes, LatheTapes, ProbingPrograms, TwoPathPrograms };
QStringList shippedDialectsWriting(DialectWrites what);

std::string readFile(const QString& path);
void writeFile(const QString& path, const std::string& text);

// m4-standard.taiwa with a second pocket 850 mm along X on a 1,000 mm plate,
// written as FOLDER/wide.taiwa: its paths span more than the vmc's 800 mm
// of X travel (a fatal finding of the verification). Its path.
QString writeWideJob(const QString& folder);

// TAIWA_UPDATE_GOLDEN=1 rewrites a golden or expected file with `actual`
// instead of comparing, and fails the check (so no run that rewrote a file
// passes unseen): true when it did, and the caller returns.
bool rewroteGolden(const QString& path, const std::string& actual);

}  // namespace taiwa::test
