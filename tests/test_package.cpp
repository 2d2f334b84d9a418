// The Debian package, built by CPack from this build tree: its contents, the
// desktop entry (desktop-file-validate), the MIME type (shared-mime-info's own
// update-mime-database reads it; Debian 12 ships no schema file for it), the
// dependencies computed from the binary, and the extracted program run from a
// temporary root: `taiwa --version` and `taiwa export` on an installed sample.
#include "support/support.h"

#include <QtTest>

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>

namespace {

struct Run {
    int code = -1;
    QString out;
};

Run run(const QString& program, const QStringList& args, const QString& dir = {}, const QStringList& env = {})
{
    QProcess p;
    if (!dir.isEmpty()) p.setWorkingDirectory(dir);
    QProcessEnvironment e = QProcessEnvironment::systemEnvironment();
    for (const QString& kv : env) e.insert(kv.section('=', 0, 0), kv.section('=', 1));
    p.setProcessEnvironment(e);
    p.setProcessChannelMode(QProcess::MergedChannels);
    p.start(program, args);
    if (!p.waitForFinished(300'000)) return {-1, "timed out: " + program};
    return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1, QString::fromUtf8(p.readAll())};
}

}  // namespace

class TestPackage : public QObject {
    Q_OBJECT
    QTemporaryDir work_;
    QString deb_;

private slots:
    void initTestCase()
    {
        QVERIFY(work_.isValid());
        const Run r = run("cpack", {"-G", "DEB", "--config", taiwa::test::buildDir() + "/CPackConfig.cmake", "-B",
                                    work_.path()});
        QVERIFY2(r.code == 0, qPrintable(r.out));
        const QStringList debs = QDir(work_.path()).entryList({"taiwa_*.deb"});
        QCOMPARE(debs.size(), 1);
        deb_ = work_.filePath(debs.front());
    }

    void holdsTheProgramAndItsFiles()
    {
        const Run r = run("dpkg-deb", {"-c", deb_});
        QCOMPARE(r.code, 0);
        for (const char* path : {"./usr/bin/taiwa", "./usr/share/taiwa/samples/plate.taiwa",
                                 "./usr/share/taiwa/samples/lathe-shaft-grinding.taiwa",
                                 "./usr/share/taiwa/samples/drive-shaft.step",
                                 "./usr/share/taiwa/schema/taiwa-job.schema.json",
                                 "./usr/share/taiwa/technology/materials.json", "./usr/share/applications/taiwa.desktop",
                                 "./usr/share/mime/packages/taiwa.xml", "./usr/share/icons/hicolor/scalable/apps/taiwa.svg",
                                 "./usr/share/icons/hicolor/scalable/mimetypes/application-x-taiwa-job.svg",
                                 "./usr/share/man/man1/taiwa.1.gz"})
            QVERIFY2(r.out.contains(QString::fromUtf8(path) + '\n'), path);
        // Nothing of the build: no headers, static libraries or tool database.
        for (const char* wrong : {".h\n", ".a\n", ".sqlite"}) QVERIFY2(!r.out.contains(wrong), wrong);
    }

    void dependenciesComeFromTheBinary()
    {
        const Run r = run("dpkg-deb", {"-f", deb_, "Depends"});
        QCOMPARE(r.code, 0);
        // dpkg-shlibdeps names the libraries' packages with versions.
        for (const char* lib : {"libqt6widgets6", "libsqlite3-0", "libc6 (>=", "libocct-data-exchange-7.6",
                                "libocct-modeling-algorithms-7.6"})
            QVERIFY2(r.out.contains(lib), qPrintable(r.out));
    }

    void desktopEntryAndMimeTypeAreValid()
    {
        QTemporaryDir root;
        QCOMPARE(run("dpkg", {"-x", deb_, root.path()}).code, 0);
        const Run desktop = run("desktop-file-validate", {root.filePath("usr/share/applications/taiwa.desktop")});
        QVERIFY2(desktop.code == 0 && desktop.out.trimmed().isEmpty(), qPrintable(desktop.out));
        const QString mime = root.filePath("usr/share/mime");
        const Run db = run("update-mime-database", {"-V", mime});
        QVERIFY2(db.code == 0 && !db.out.contains("rror"), qPrintable(db.out));
        QFile globs(mime + "/globs2");
        QVERIFY(globs.open(QIODevice::ReadOnly));
        QVERIFY(QString::fromUtf8(globs.readAll()).contains("application/x-taiwa-job:*.taiwa"));

        // The check can fail: a broken MIME file is reported.
        QFile broken(mime + "/packages/broken.xml");
        QVERIFY(broken.open(QIODevice::WriteOnly));
        broken.write("<mime-info xmlns=\"http://www.freedesktop.org/standards/shared-mime-info\"><mime-type>");
        broken.close();
        const Run bad = run("update-mime-database", {"-V", mime});
        QVERIFY2(bad.out.contains("broken.xml"), qPrintable(bad.out));
    }

    void extractedProgramRunsAnInstalledSample()
    {
        QTemporaryDir root;
        QCOMPARE(run("dpkg", {"-x", deb_, root.path()}).code, 0);
        const QString taiwa = root.filePath("usr/bin/taiwa");
        const Run version = run(taiwa, {"--version"});
        QVERIFY2(version.code == 0 && version.out.startsWith("taiwa "), qPrintable(version.out));
        const QString sample = root.filePath("usr/share/taiwa/samples/plate.taiwa");
        const Run exported = run(taiwa, {"export", sample, "--out", work_.filePath("out"), "--dialect", "fanuc"}, {},
                                 {"TAIWA_TOOL_DB=" + work_.filePath("tools.sqlite")});
        QVERIFY2(exported.code == 0, qPrintable(exported.out));
        QVERIFY(QFile::exists(work_.filePath("out/plate.nc")));
        QVERIFY(QFile::exists(work_.filePath("out/plate.sheet.pdf")));
        // Every shipped dialect and machine is in the package, and posts from it.
        for (const QString& d : taiwa::test::shippedDialects())
            QVERIFY2(QFile::exists(root.filePath(QString("usr/share/taiwa/dialects/%1.json").arg(d))), qPrintable(d));
        for (const QString& m : taiwa::test::shippedMachines())
            QVERIFY2(QFile::exists(root.filePath(QString("usr/share/taiwa/machines/%1.json").arg(m))), qPrintable(m));
        const Run klartext = run(taiwa, {"export", sample, "--out", work_.filePath("tnc"), "--dialect", "heidenhain"}, {},
                                 {"TAIWA_TOOL_DB=" + work_.filePath("tools.sqlite")});
        QVERIFY2(klartext.code == 0, qPrintable(klartext.out));
        QVERIFY(QFile::exists(work_.filePath("tnc/plate.h")));
        // The tool library went where it was told, not into the package's tree.
        QVERIFY(QFile::exists(work_.filePath("tools.sqlite")));
        QVERIFY(QDir(root.path()).entryList({"*.sqlite"}, QDir::Files).isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestPackage)
#include "test_package.moc"
