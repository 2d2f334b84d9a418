// The house's dependency rule, checked on the source tree: folders depend one
// way (app -> ui -> viz -> core), and inside core every stage may include
// only the model and the stages below it (the order of kCoreLayers); only
// core/export may use Qt, no core file uses VTK; a module's input struct is
// named outside its folder only by code above the modules. A new folder in
// core must be given its place here.
#include "support/support.h"

#include <QtTest>

#include <QDirIterator>
#include <QFile>
#include <QRegularExpression>

namespace {

// Lowest first. A folder may include itself and any folder before it.
const QStringList kCoreLayers{"model", "dxf", "figure", "io",   "machine", "tools",   "check",  "occt", "turning", "decompose",
                              "paths", "post",   "sim",  "sheet",   "modules", "verify", "job",  "pipeline", "export"};
const QStringList kTopLayers{"core", "viz", "ui", "app"};

struct Include {
    QString file;  // relative to the source tree
    int line;
    QString target;  // "model/job.h", or "<QString>" for a system include
};

QList<Include> includesBelow(const QString& folder)
{
    QList<Include> out;
    const QString root = QDir(taiwa::test::sourcePath(".")).canonicalPath() + "/";
    QDirIterator it(root + folder, {"*.cpp", "*.h"}, QDir::Files, QDirIterator::Subdirectories);
    static const QRegularExpression re(QStringLiteral("^\\s*#\\s*include\\s*([<\"][^>\"]+[>\"])"));
    while (it.hasNext()) {
        const QString path = it.next();
        QFile f(path);
        if (!f.open(QIODevice::ReadOnly)) continue;
        int n = 0;
        while (!f.atEnd()) {
            ++n;
            const auto m = re.match(QString::fromUtf8(f.readLine()));
            if (m.hasMatch()) out.push_back({path.mid(root.size()), n, m.captured(1)});
        }
    }
    return out;
}

QString firstFolder(const QString& path) { return path.section('/', 0, 0); }

}  // namespace

class TestLayers : public QObject {
    Q_OBJECT
private slots:
    void topLevelFoldersDependOneWay()
    {
        QStringList wrong;
        for (const QString& top : kTopLayers)
            for (const Include& inc : includesBelow(top)) {
                if (!inc.target.startsWith('"')) continue;
                const QString target = inc.target.mid(1, inc.target.size() - 2);
                const QString to = firstFolder(target);
                // viz/ui/app name core headers by their core folder ("model/job.h").
                const qsizetype rankTo = kTopLayers.contains(to) ? kTopLayers.indexOf(to) : 0;
                if (rankTo > kTopLayers.indexOf(top))
                    wrong << QStringLiteral("%1:%2 includes %3").arg(inc.file).arg(inc.line).arg(inc.target);
            }
        QVERIFY2(wrong.isEmpty(), qPrintable(wrong.join('\n')));
    }

    void coreStagesIncludeOnlyLowerStages()
    {
        QStringList wrong;
        for (const Include& inc : includesBelow("core")) {
            const QString from = inc.file.section('/', 1, 1);
            const qsizetype rankFrom = kCoreLayers.indexOf(from);
            if (!inc.file.section('/', 1).contains('/')) continue;  // core/builtin_data.h.in and the like
            QVERIFY2(rankFrom >= 0, qPrintable("core/" + from + " has no place in kCoreLayers (tests/test_layers.cpp)"));
            if (!inc.target.startsWith('"')) {
                const bool qt = inc.target.startsWith("<Q");
                const bool vtk = inc.target.startsWith("<vtk");
                if (vtk || (qt && from != "export"))
                    wrong << QStringLiteral("%1:%2 includes %3 (the core is without VTK, and Qt only in export)")
                                 .arg(inc.file).arg(inc.line).arg(inc.target);
                continue;
            }
            const QString target = inc.target.mid(1, inc.target.size() - 2);
            if (!target.contains('/')) continue;  // generated headers (builtin_data.h)
            const qsizetype rankTo = kCoreLayers.indexOf(firstFolder(target));
            if (rankTo < 0 || rankTo > rankFrom)
                wrong << QStringLiteral("%1:%2 includes %3").arg(inc.file).arg(inc.line).arg(inc.target);
        }
        QVERIFY2(wrong.isEmpty(), qPrintable(wrong.join('\n')));
    }

    void openCascadeOnlyBehindItsDoor()
    {
        // OpenCASCADE's headers (gp_Pnt.hxx, TopoDS_Shape.hxx, …) are
        // included in core/occt/ and nowhere else but the tests that build
        // solids with it.
        QStringList wrong;
        int inDoor = 0;
        for (const QString& top : {QStringLiteral("core"), QStringLiteral("viz"), QStringLiteral("ui"), QStringLiteral("app")})
            for (const Include& inc : includesBelow(top)) {
                if (!inc.target.endsWith(".hxx>")) continue;
                if (inc.file.startsWith("core/occt/")) ++inDoor;
                else wrong << QStringLiteral("%1:%2 includes %3").arg(inc.file).arg(inc.line).arg(inc.target);
            }
        QVERIFY2(wrong.isEmpty(), qPrintable(wrong.join('\n')));
        QVERIFY(inDoor > 10);  // the rule sees the door's includes at all
    }

    void moduleFoldersAreReachedThroughTheDoor()
    {
        // Below the modules no stage names a module; above them only through
        // the registry, except tests and a module's own folder.
        QStringList wrong;
        for (const Include& inc : includesBelow("core")) {
            const QString target = inc.target.mid(1, inc.target.size() - 2);
            if (!target.startsWith("modules/") || target.count('/') < 2) continue;  // modules/registry.h is the door
            const QString module = target.section('/', 1, 1);
            if (inc.file.startsWith("core/modules/" + module + "/")) continue;
            wrong << QStringLiteral("%1:%2 includes %3").arg(inc.file).arg(inc.line).arg(inc.target);
        }
        for (const QString& top : {QStringLiteral("viz"), QStringLiteral("ui"), QStringLiteral("app")})
            for (const Include& inc : includesBelow(top))
                if (inc.target.startsWith("\"modules/") && inc.target.count('/') >= 2)
                    wrong << QStringLiteral("%1:%2 includes %3").arg(inc.file).arg(inc.line).arg(inc.target);
        QVERIFY2(wrong.isEmpty(), qPrintable(wrong.join('\n')));
    }

    void theRuleCatchesAWrongInclude()
    {
        // The negative control: the parser sees includes at all.
        const auto core = includesBelow("core");
        QVERIFY(core.size() > 100);
        QVERIFY(std::any_of(core.begin(), core.end(),
                            [](const Include& i) { return i.file == "core/pipeline/pipeline.cpp" && i.target == "\"modules/registry.h\""; }));
        QVERIFY(kCoreLayers.indexOf("pipeline") > kCoreLayers.indexOf("modules"));
        QVERIFY(kCoreLayers.indexOf("model") < kCoreLayers.indexOf("io"));
    }
};

QTEST_GUILESS_MAIN(TestLayers)
#include "test_layers.moc"
