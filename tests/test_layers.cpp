// The house's dependency rule, checked on the source tree: folders depend one
// way (app -> ui -> viz -> core), and inside core every stage may include
// only the model and the stages below it (TAIWA_CORE_LAYERS of
// core/CMakeLists.txt, whose libraries are linked in that order so that a
// wrong-way call fails to link: test_layer_link); only core/export may use
// Qt, no core file uses VTK; a module's input struct is named outside its
// folder only by code above the modules. docs/modules.md lists the same
// order. A new folder in core must be given its place there.
#include "support/support.h"

#include <QtTest>

#include <QDirIterator>
#include <QFile>
#include <QRegularExpression>

namespace {

// Lowest first. A folder may include itself and any folder before it.
const QStringList kCoreLayers = QString(QStringLiteral(TAIWA_CORE_LAYERS)).split(',');
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
QString described(const Include& inc) { return QStringLiteral("%1:%2 includes %3").arg(inc.file).arg(inc.line).arg(inc.target); }

// The rules, each on a list of includes (the tree's, or planted ones): what
// breaks it, one line each.

// viz/ui/app name core headers by their core folder ("model/job.h").
QStringList wrongBetweenTopFolders(const QList<Include>& includes)
{
    QStringList wrong;
    for (const Include& inc : includes) {
        const QString top = firstFolder(inc.file);
        if (!kTopLayers.contains(top) || !inc.target.startsWith('"')) continue;
        const QString to = firstFolder(inc.target.mid(1, inc.target.size() - 2));
        const qsizetype rankTo = kTopLayers.contains(to) ? kTopLayers.indexOf(to) : 0;
        if (rankTo > kTopLayers.indexOf(top)) wrong << described(inc);
    }
    return wrong;
}

QStringList wrongBetweenCoreStages(const QList<Include>& includes)
{
    QStringList wrong;
    for (const Include& inc : includes) {
        if (!inc.file.startsWith("core/") || !inc.file.section('/', 1).contains('/')) continue;  // core/builtin_data.h.in and the like
        const QString from = inc.file.section('/', 1, 1);
        const qsizetype rankFrom = kCoreLayers.indexOf(from);
        if (rankFrom < 0) {
            wrong << inc.file + ": core/" + from + " has no place in TAIWA_CORE_LAYERS (core/CMakeLists.txt)";
            continue;
        }
        if (!inc.target.startsWith('"')) {
            const bool qt = inc.target.startsWith("<Q");
            const bool vtk = inc.target.startsWith("<vtk");
            if (vtk || (qt && from != "export")) wrong << described(inc) + " (the core is without VTK, and Qt only in export)";
            continue;
        }
        const QString target = inc.target.mid(1, inc.target.size() - 2);
        if (!target.contains('/')) continue;  // generated headers (builtin_data.h)
        const qsizetype rankTo = kCoreLayers.indexOf(firstFolder(target));
        if (rankTo < 0 || rankTo > rankFrom) wrong << described(inc);
    }
    return wrong;
}

// Below the modules no stage names a module; above them only through the
// registry, except tests and a module's own folder.
QStringList wrongModuleIncludes(const QList<Include>& includes)
{
    QStringList wrong;
    for (const Include& inc : includes) {
        const QString target = inc.target.mid(1, inc.target.size() - 2);
        if (!inc.target.startsWith('"') || !target.startsWith("modules/") || target.count('/') < 2) continue;  // modules/registry.h is the door
        if (inc.file.startsWith("core/modules/" + target.section('/', 1, 1) + "/")) continue;
        wrong << described(inc);
    }
    return wrong;
}

// The core's layers as docs/modules.md's "Where things live" gives them: the
// `name`s of its first paragraph outside parentheses, in order.
QStringList layersInTheDocs()
{
    const QString page = QString::fromStdString(taiwa::test::readFile(taiwa::test::sourcePath("docs/modules.md")));
    const qsizetype from = page.indexOf("## Where things live");
    if (from < 0) return {};
    const qsizetype colon = page.indexOf("checks it):", from);
    const qsizetype end = page.indexOf("\n\n", colon + 13);
    QString outside;
    int depth = 0;
    for (const QChar c : page.mid(colon + 11, end - colon - 11)) {
        if (c == '(') ++depth;
        else if (c == ')') --depth;
        else if (depth == 0) outside += c;
    }
    QStringList layers;
    static const QRegularExpression name(QStringLiteral("`([a-z]+)`"));
    for (auto it = name.globalMatch(outside); it.hasNext();) layers << it.next().captured(1);
    return layers;
}

}  // namespace

class TestLayers : public QObject {
    Q_OBJECT
private slots:
    void topLevelFoldersDependOneWay()
    {
        QList<Include> all;
        for (const QString& top : kTopLayers) all += includesBelow(top);
        const QStringList wrong = wrongBetweenTopFolders(all);
        QVERIFY2(wrong.isEmpty(), qPrintable(wrong.join('\n')));
    }

    void coreStagesIncludeOnlyLowerStages()
    {
        const QStringList wrong = wrongBetweenCoreStages(includesBelow("core"));
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
        QList<Include> all;
        for (const QString& top : kTopLayers) all += includesBelow(top);
        const QStringList wrong = wrongModuleIncludes(all);
        QVERIFY2(wrong.isEmpty(), qPrintable(wrong.join('\n')));
    }

    // The negative control: made-up includes, each breaking one rule, are
    // flagged, and their right-way twins are not; and the parser sees the
    // tree's includes at all.
    void theRuleCatchesAWrongInclude()
    {
        const QList<Include> wrongWay{{"core/model/planted.cpp", 3, "\"pipeline/pipeline.h\""},
                                      {"core/paths/planted.h", 4, "\"modules/registry.h\""},
                                      {"core/sim/planted.cpp", 5, "<QString>"},
                                      {"core/tools/planted.cpp", 6, "<vtkActor.h>"},
                                      {"core/nowhere/planted.cpp", 7, "\"model/job.h\""}};
        const QStringList core = wrongBetweenCoreStages(wrongWay);
        QCOMPARE(core.size(), wrongWay.size());
        QCOMPARE(core[0], QString("core/model/planted.cpp:3 includes \"pipeline/pipeline.h\""));
        QVERIFY2(core[4].contains("core/nowhere has no place"), qPrintable(core[4]));
        const QList<Include> rightWay{{"core/pipeline/planted.cpp", 3, "\"model/job.h\""},
                                      {"core/modules/planted.h", 4, "\"paths/cl.h\""},
                                      {"core/export/planted.cpp", 5, "<QString>"},
                                      {"core/model/planted.cpp", 6, "<vector>"}};
        QVERIFY2(wrongBetweenCoreStages(rightWay).isEmpty(), qPrintable(wrongBetweenCoreStages(rightWay).join('\n')));

        QCOMPARE(wrongBetweenTopFolders({{"viz/planted.cpp", 1, "\"ui/station.h\""}}).size(), 1);
        QCOMPARE(wrongBetweenTopFolders({{"core/model/planted.cpp", 1, "\"viz/scene.h\""}}).size(), 1);
        QVERIFY(wrongBetweenTopFolders({{"ui/planted.cpp", 1, "\"viz/scene.h\""}}).isEmpty());

        QCOMPARE(wrongModuleIncludes({{"core/job/planted.cpp", 1, "\"modules/m4/m4.h\""},
                                      {"ui/planted.cpp", 1, "\"modules/cp/cp.h\""},
                                      {"core/modules/m2d/planted.cpp", 1, "\"modules/m4/m4.h\""}})
                     .size(),
                 3);
        QVERIFY(wrongModuleIncludes({{"core/modules/m4/planted.cpp", 1, "\"modules/m4/m4.h\""},
                                     {"core/pipeline/planted.cpp", 1, "\"modules/registry.h\""}})
                    .isEmpty());

        const auto tree = includesBelow("core");
        QVERIFY(tree.size() > 100);
        QVERIFY(std::any_of(tree.begin(), tree.end(),
                            [](const Include& i) { return i.file == "core/pipeline/pipeline.cpp" && i.target == "\"modules/registry.h\""; }));
    }

    // docs/modules.md gives the reader the order the build links in.
    void theDocsListTheSameLayers()
    {
        QVERIFY(kCoreLayers.size() > 10 && kCoreLayers.first() == "model");
        QCOMPARE(layersInTheDocs(), kCoreLayers);
    }
};

QTEST_GUILESS_MAIN(TestLayers)
#include "test_layers.moc"
