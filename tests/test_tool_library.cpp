// The SQLite tool library: created with the default library on first use,
// edits persist, and a corrupt, foreign, locked or newer file gives a clear
// message naming the file and is never overwritten. Speeds and feeds.
#include "support/support.h"
#include "model/technology.h"
#include "tools/cutting.h"
#include "tools/tool_library.h"

#include <QTemporaryDir>
#include <QtTest>

#include <sqlite3.h>

#include <set>

using namespace taiwa;

class TestToolLibrary : public QObject {
    Q_OBJECT
private slots:
    void defaultLibraryCoversWhatTheShopNeeds()
    {
        const auto tools = defaultToolLibrary();
        auto count = [&](ToolType t) { return std::count_if(tools.begin(), tools.end(), [t](const Tool& x) { return x.type == t; }); };
        QVERIFY(count(ToolType::CentreDrill) >= 1);
        QVERIFY(count(ToolType::Drill) >= 10);
        QVERIFY(count(ToolType::FlatEndMill) >= 10);
        QVERIFY(count(ToolType::BallEndMill) >= 5);
        QVERIFY(count(ToolType::FaceMill) == 1);
        for (const double angle : {1.0, 2.0, 3.0, 5.0, 7.0, 10.0})
            QVERIFY(std::any_of(tools.begin(), tools.end(), [&](const Tool& t) { return t.type == ToolType::TaperEndMill && t.taperAngle == angle; }));
        std::set<int> ids;
        for (const auto& t : tools) {
            QVERIFY2(ids.insert(t.id).second, "duplicate tool id");
            for (const auto& m : TechnologyTable::builtIn().materials())
                QVERIFY2(t.cuttingFor(m.id), qPrintable(QString::fromStdString(t.name + " lacks " + m.id)));
        }
    }

    void createdOnFirstOpenAndEditsPersist()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("sub/tools.sqlite").toStdString();
        std::string error;
        {
            auto lib = ToolLibrary::open(path, error);
            QVERIFY2(lib, error.c_str());
            const auto tools = lib->tools(error);
            QVERIFY(tools);
            QCOMPARE(*tools, defaultToolLibrary());
            Tool t = defaultToolLibrary()[5];
            t.id = 0;
            t.name = "Drill 5 mm, regrind";
            const auto id = lib->save(t, error);
            QVERIFY(id && *id > 60);
            QVERIFY(lib->remove(21, error));
            QVERIFY(lib->addUsage(27, 12.5, error));
        }
        auto again = ToolLibrary::open(path, error);
        const auto tools = again->tools(error);
        QVERIFY(tools);
        QCOMPARE(tools->size(), defaultToolLibrary().size());  // one added, one removed
        QVERIFY(std::none_of(tools->begin(), tools->end(), [](const Tool& t) { return t.id == 21; }));
        const auto t27 = std::find_if(tools->begin(), tools->end(), [](const Tool& t) { return t.id == 27; });
        QCOMPARE(t27->usedMinutes, 12.5);
        QCOMPARE(tools->back().name, std::string("Drill 5 mm, regrind"));
        QCOMPARE(tools->back().cutting, defaultToolLibrary()[5].cutting);
    }

    void badFilesAreReportedAndLeftAlone_data()
    {
        QTest::addColumn<QByteArray>("content");
        QTest::addColumn<QString>("message");
        QTest::newRow("random bytes") << QByteArray(8192, 'x') << "is not a tool library";
        QTest::newRow("future version") << QByteArray() << "written by a newer Taiwa";
        QTest::newRow("foreign database") << QByteArray("foreign") << "not a tool library";
    }
    void badFilesAreReportedAndLeftAlone()
    {
        QFETCH(QByteArray, content);
        QFETCH(QString, message);
        QTemporaryDir dir;
        const QString path = dir.filePath("tools.sqlite");
        if (content.isEmpty() || content == "foreign") {
            sqlite3* db = nullptr;
            sqlite3_open(path.toUtf8().constData(), &db);
            sqlite3_exec(db, content.isEmpty() ? "PRAGMA user_version = 7" : "CREATE TABLE parts(x)", nullptr, nullptr, nullptr);
            sqlite3_close(db);
        } else {
            test::writeFile(path, content.toStdString());
        }
        const std::string before = test::readFile(path);
        std::string error;
        QVERIFY(!ToolLibrary::open(path.toStdString(), error));
        QVERIFY2(QString::fromStdString(error).contains(message) && QString::fromStdString(error).contains(path), error.c_str());
        QCOMPARE(test::readFile(path), before);
    }

    void lockedLibraryIsReportedNotWaitedOnForever()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("tools.sqlite").toStdString();
        std::string error;
        auto lib = ToolLibrary::open(path, error);
        QVERIFY(lib);
        sqlite3* other = nullptr;
        sqlite3_open(path.c_str(), &other);
        QCOMPARE(sqlite3_exec(other, "BEGIN EXCLUSIVE", nullptr, nullptr, nullptr), SQLITE_OK);
        QVERIFY(!lib->addUsage(27, 1, error));
        QVERIFY2(QString::fromStdString(error).contains("locked by another program"), error.c_str());
        sqlite3_exec(other, "ROLLBACK", nullptr, nullptr, nullptr);
        sqlite3_close(other);
        QVERIFY(lib->addUsage(27, 1, error));
    }

    void speedsAndFeedsFromCuttingData()
    {
        Tool t;
        t.type = ToolType::FlatEndMill;
        t.diameter = 10;
        t.flutes = 3;
        t.cutting = {{"steel-s45c", 120, 0.05, 0.4}};
        const auto sf = speedsFeeds(t, "steel-s45c");
        QVERIFY(sf);
        QCOMPARE(sf->rpm, 3820.0);             // 1000 x 120 / (pi x 10)
        QCOMPARE(sf->feed, 573.0);             // 3820 x 0.05 x 3
        QCOMPARE(sf->plungeFeed, 229.0);       // 0.4 x 573
        QVERIFY(!speedsFeeds(t, "pom"));
        t.diameter = 1;                        // 38197 rpm clamped to the spindle's 12000
        QCOMPARE(speedsFeeds(t, "steel-s45c")->rpm, 12000.0);
    }
};

QTEST_APPLESS_MAIN(TestToolLibrary)
#include "test_tool_library.moc"
