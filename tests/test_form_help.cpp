// Every module's form describes each of its fields (issue 32): a line of
// help on every field, the same help and drawing symbol on a point's X and
// Y, and the symbols the fields mark in the module's drawing, each one
// drawn there — so that a field whose description is lost fails here.
#include "modules/registry.h"
#include "support/support.h"

#include <QDirIterator>
#include <QFile>
#include <QFileInfo>
#include <QtTest>

using namespace taiwa;

namespace {

// The text of a module's drawing, from its folder in the source tree
// (core/modules/<kind>/<kind>.svg; the drawing() resource names its file).
QString drawingText(const ModuleKind& kind)
{
    const QString file = QFileInfo(QString(kind.drawing())).fileName();
    QDirIterator it(test::sourcePath("core/modules"), {file}, QDir::Files, QDirIterator::Subdirectories);
    if (!it.hasNext()) return {};
    QFile f(it.next());
    return f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll()) : QString();
}

}  // namespace

class TestFormHelp : public QObject {
    Q_OBJECT

private slots:
    void everyFieldHasHelp()
    {
        for (const ModuleKind* kind : moduleKinds())
            for (const FormField& f : kind->fields())
                QVERIFY2(!f.help.empty(), qPrintable(QString("%1 %2").arg(kind->name(), QString::fromStdString(f.key))));
    }

    // "P2.x" and "P2.y" are one point: what the form says of one it says of
    // the other.
    void aPointsCoordinatesShareTheirDescription()
    {
        for (const ModuleKind* kind : moduleKinds())
            for (const FormField& x : kind->fields()) {
                if (!x.key.ends_with(".x")) continue;
                const std::string y = x.key.substr(0, x.key.size() - 1) + "y";
                for (const FormField& f : kind->fields())
                    if (f.key == y)
                        QVERIFY2(f.help == x.help && f.symbol == x.symbol,
                                 qPrintable(QString("%1 %2").arg(kind->name(), QString::fromStdString(y))));
            }
    }

    // The fields that mark a symbol in their module's drawing, and which;
    // each symbol is drawn.
    void theFieldsMarkTheirSymbolsInTheDrawing()
    {
        QStringList marked;
        for (const ModuleKind* kind : moduleKinds()) {
            const QString svg = drawingText(*kind);
            for (const FormField& f : kind->fields()) {
                if (f.symbol.empty()) continue;
                const QString symbol = QString::fromStdString(f.symbol);
                marked << QString("%1 %2 %3").arg(kind->name(), QString::fromStdString(f.key), symbol);
                QVERIFY2(svg.contains(QString("id=\"%1\"").arg(symbol)), qPrintable(marked.back()));
            }
        }
        const QStringList want{
            "M4 P1.x sym-P1", "M4 P1.y sym-P1", "M4 P2.x sym-P2", "M4 P2.y sym-P2", "M4 P3.x sym-P3",
            "M4 P3.y sym-P3", "M4 P4.x sym-P4", "M4 P4.y sym-P4", "M4 r1 sym-r1", "M4 depth sym-T", "M4 taper sym-S",
            "M2D X1 sym-X1Y1", "M2D Y1 sym-X1Y1", "M2D L1 sym-L1", "M2D L2 sym-L2", "M2D depth sym-T",
            "M2D theta1 sym-theta1", "M2D theta2 sym-theta2", "M2D r1 sym-r1",
            "PROBE origin.x sym-P1", "PROBE origin.y sym-P1", "PROBE P2.x sym-P2", "PROBE P2.y sym-P2",
            "PROBE P2.side sym-P2", "PROBE P3.x sym-P3", "PROBE P3.y sym-P3", "PROBE P3.side sym-P3",
            "PROBE P4.x sym-P4", "PROBE P4.y sym-P4", "PROBE P4.side sym-P4",
            "CP outline sym-outline", "CP islands sym-islands", "CP depth sym-T",
            "AREA outline sym-outline", "AREA islands sym-islands", "AREA depth sym-T", "AREA diameter sym-D",
            "AREA points sym-passes",
            "FACE depth sym-depth", "FACE finish sym-finish", "FACE angle sym-angle", "FACE stepOver sym-stepOver",
            "FACE margin sym-margin",
            "SIDE contour sym-contour", "SIDE side sym-side", "SIDE direction sym-direction", "SIDE depth sym-T",
            "SIDE width sym-W"};
        QCOMPARE(marked, want);
    }
};

QTEST_GUILESS_MAIN(TestFormHelp)
#include "test_form_help.moc"
