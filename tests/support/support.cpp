// Shared test helpers: source paths, running the command line, file I/O.
#include "support/support.h"

#include <QTest>

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QProcessEnvironment>
#include <QStandardPaths>
#include <QTemporaryDir>

#include <nlohmann/json.hpp>

#include <stdexcept>

namespace taiwa::test {

QString sourcePath(const QString& relative) { return QDir(QStringLiteral(TAIWA_SOURCE_DIR)).filePath(relative); }
QString dataPath(const QString& relative) { return QDir(QStringLiteral(TAIWA_TEST_DATA)).filePath(relative); }
QString buildDir() { return QStringLiteral(TAIWA_BUILD_DIR); }
QString taiwaBinary() { return QStringLiteral(TAIWA_BINARY); }

QStringList shippedDialects() { return QString(QStringLiteral(TAIWA_SHIPPED_DIALECTS)).split(',', Qt::SkipEmptyParts); }
QStringList shippedMachines() { return QString(QStringLiteral(TAIWA_SHIPPED_MACHINES)).split(',', Qt::SkipEmptyParts); }

QStringList shippedDialectsWriting(DialectWrites what)
{
    QStringList out;
    for (const QString& d : shippedDialects()) {
        const auto j = nlohmann::json::parse(readFile(sourcePath("resources/dialects/" + d + ".json")));
        const std::string syntax = j.value("syntax", "iso");
        if (what == DialectWrites::MillingTapes || (what == DialectWrites::LatheTapes && syntax != "klartext") ||
            ((what == DialectWrites::ProbingPrograms || what == DialectWrites::TwoPathPrograms) && syntax == "iso"))
            out << d;
    }
    return out;
}

void isolateStation(const QString& dir)
{
    QStandardPaths::setTestModeEnabled(true);
    qputenv("TAIWA_AUTOSAVE_DIR", QDir(dir).filePath(QStringLiteral("autosave")).toUtf8());
    qputenv("TAIWA_NO_PROMPTS", "1");
    qputenv("TAIWA_CACHE_DIR", QDir(dir).filePath(QStringLiteral("cache")).toUtf8());  // the verification cache
    qputenv("TAIWA_TOOL_DB", QDir(dir).filePath(QStringLiteral("tools.sqlite")).toUtf8());
}

QString testToolDb()
{
    static QTemporaryDir dir;
    return dir.filePath(QStringLiteral("tools.sqlite"));
}

RunResult runTaiwa(const QStringList& args, const QStringList& env)
{
    QProcess p;
    QProcessEnvironment e = QProcessEnvironment::systemEnvironment();
    e.insert(QStringLiteral("TAIWA_TOOL_DB"), testToolDb());
    for (const auto& kv : env) {
        const auto eq = kv.indexOf(QLatin1Char('='));
        e.insert(kv.left(eq), kv.mid(eq + 1));
    }
    p.setProcessEnvironment(e);
    p.start(taiwaBinary(), args);
    RunResult r;
    if (!p.waitForFinished(120000)) {
        p.kill();
        r.err = QStringLiteral("taiwa did not finish in 120 s");
        return r;
    }
    r.exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
    r.out = QString::fromUtf8(p.readAllStandardOutput());
    r.err = QString::fromUtf8(p.readAllStandardError());
    return r;
}

std::string readFile(const QString& path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) throw std::runtime_error("cannot read " + path.toStdString());
    const QByteArray b = f.readAll();
    return std::string(b.constData(), static_cast<std::size_t>(b.size()));
}

void writeFile(const QString& path, const std::string& text)
{
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly | QIODevice::Truncate)) throw std::runtime_error("cannot write " + path.toStdString());
    f.write(text.data(), static_cast<qint64>(text.size()));
}

bool rewroteGolden(const QString& path, const std::string& actual)
{
    if (!qEnvironmentVariableIsSet("TAIWA_UPDATE_GOLDEN")) return false;
    writeFile(path, actual);
    QTest::qFail(qPrintable("golden rewritten: " + path +
                            "; review the diff and run again without TAIWA_UPDATE_GOLDEN"),
                 __FILE__, __LINE__);
    return true;
}

QString writeWideJob(const QString& folder)
{
    nlohmann::json job = nlohmann::json::parse(readFile(sourcePath("resources/samples/m4-standard.taiwa")));
    job["stock"]["width"] = 1000;
    nlohmann::json far = job["units"][0];
    far["name"] = "far";
    for (auto& c : far["corners"]) c[0] = c[0].get<double>() + 850;
    job["units"].push_back(far);
    const QString path = QDir(folder).filePath("wide.taiwa");
    writeFile(path, job.dump(2));
    return path;
}

}  // namespace taiwa::test
