// The SQLite tool library: created with the default library on first use,
// edits persist, and a corrupt, foreign, locked or newer file gives a clear
// message naming the file and is never overwritten. Speeds and feeds.
#include "support/support.h"
#include "model/technology.h"
#include "tools/cutting.h"
#include "tools/tool_library.h"
#include "tools/tool_check.h"
#include "post/tool_table.h"

#include <fmt/format.h>

#include <QElapsedTimer>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include <sqlite3.h>

#include <algorithm>
#include <set>

using namespace taiwa;

class TestToolLibrary : public QObject {
    Q_OBJECT
private slots:
    // Each value a tool may not have is named with its field; the default
    // library has none of them.
    void toolProblemsNameTheField()
    {
        for (const Tool& t : defaultToolLibrary()) QVERIFY2(toolProblems(t).empty(), t.name.c_str());
        Tool t = defaultToolLibrary().front();
        const auto first = [](const Tool& x) { const auto p = toolProblems(x); return p.empty() ? std::string() : p.front().field + ": " + p.front().message; };
        Tool bad = t;
        bad.id = 1000;
        QCOMPARE(first(bad), std::string("id: T number 1000 must be 1 to 999"));
        bad = t;
        bad.name = "  ";
        QCOMPARE(first(bad), std::string("name: the name must not be empty"));
        bad = t;
        bad.diameter = 0;
        QCOMPARE(first(bad), std::string("diameter: diameter 0 mm must be greater than zero"));
        bad = t;
        bad.fluteLength = 30;
        bad.stickout = 20;
        QCOMPARE(first(bad), std::string("stickout: stick-out 20 mm is shorter than the flutes (30 mm)"));
        bad = t;
        bad.taperAngle = 45;
        QCOMPARE(first(bad), std::string("taperAngle: taper 45° per side must be 0 to less than 45°"));
        bad = t;
        bad.flutes = 0;
        QCOMPARE(first(bad), std::string("flutes: flutes 0 must be at least 1"));
    }

    // The machine's tool table: LinuxCNC's tool.tbl (a turning tool with its
    // nose diameter and tip) and FANUC's G10 offsets, lengths left at zero.
    void toolTablesForTheMachine()
    {
        const std::vector<Tool> tools = defaultToolLibrary();
        const std::string tbl = linuxcncToolTable(tools, LengthUnit::Millimetre);
        QVERIFY2(tbl.starts_with(";Taiwa tool library, " + std::to_string(tools.size()) + " tools, mm;"), tbl.c_str());
        QVERIFY(tbl.find("\nT27 P27 Z0 D10 ;Flat end mill 10 mm carbide\n") != std::string::npos);
        QVERIFY(linuxcncToolTable(tools, LengthUnit::Inch).find("\nT27 P27 Z0 D0.3937 ;") != std::string::npos);
        const std::string fanuc = fanucOffsetProgram(tools, LengthUnit::Millimetre);
        QVERIFY(fanuc.starts_with("%\nO9000 (TAIWA TOOL OFFSETS)\n"));
        QVERIFY(fanuc.find("\n(T27 FLAT END MILL 10 MM CARBIDE)\nG10 L12 P27 R5.\n") != std::string::npos);
        QVERIFY(fanuc.ends_with("M30\n%\n"));
        const auto lathe = defaultLatheTools();
        const auto insert = std::find_if(lathe.begin(), lathe.end(), [](const Tool& t) { return t.id == 102; });
        QVERIFY(insert != lathe.end());
        QVERIFY(linuxcncToolTable(lathe, LengthUnit::Millimetre).find("\nT102 P102 X0 Z0 D0.8 Q2 ;") != std::string::npos);
        QVERIFY(fanucOffsetProgram(lathe, LengthUnit::Millimetre).find("\nG10 P102 R0.4 Q2\n") != std::string::npos);
    }

    void defaultLibraryCoversWhatTheShopNeeds()
    {
        const auto tools = defaultToolLibrary();
        auto count = [&](ToolType t) { return std::count_if(tools.begin(), tools.end(), [t](const Tool& x) { return x.type == t; }); };
        QVERIFY(count(ToolType::CentreDrill) >= 1);
        QVERIFY(count(ToolType::Drill) >= 10);
        QVERIFY(count(ToolType::FlatEndMill) >= 10);
        QVERIFY(count(ToolType::BallEndMill) >= 5);
        QVERIFY(count(ToolType::FaceMill) == 1);
        QVERIFY(count(ToolType::Probe) == 1);  // for work-centre probing: a ball, no cutting data, no wear
        for (const double angle : {1.0, 2.0, 3.0, 5.0, 7.0, 10.0})
            QVERIFY(std::any_of(tools.begin(), tools.end(), [&](const Tool& t) { return t.type == ToolType::TaperEndMill && t.taperAngle == angle; }));
        std::set<int> ids;
        for (const auto& t : tools) {
            if (t.type == ToolType::TurningInsert || t.type == ToolType::Grooving || t.type == ToolType::Threading) {
                // Lathe tools (tests/test_turning_tools.cpp checks them in detail).
                QVERIFY2(!t.turning.empty() && t.cornerRadius > 0 && t.diameter > 0, t.name.c_str());
                QVERIFY2(ids.insert(t.id).second, "duplicate tool id");
                for (const auto& m : TechnologyTable::builtIn().materials())
                    QVERIFY2(t.cuttingFor(m.id), qPrintable(QString::fromStdString(t.name + " lacks " + m.id)));
                continue;
            }
            if (t.type == ToolType::Probe) {
                QVERIFY(t.cutting.empty() && t.flutes == 0 && t.diameter > 0);
                QVERIFY2(ids.insert(t.id).second, "duplicate tool id");
                continue;
            }
            QVERIFY2(t.lifeMinutes >= 60 && t.lifeMinutes <= 240 && t.usedMinutes == 0, t.name.c_str());
            QVERIFY2(t.stickout > t.fluteLength && !t.holder.empty(), t.name.c_str());
            if (t.type == ToolType::FlatEndMill)
                QVERIFY2(t.fluteLength >= 2 * t.diameter && t.fluteLength <= 3 * t.diameter && t.flutes >= 2 && t.flutes <= 4,
                         t.name.c_str());
            QVERIFY2(ids.insert(t.id).second, "duplicate tool id");
            for (const auto& m : TechnologyTable::builtIn().materials())
                QVERIFY2(t.cuttingFor(m.id), qPrintable(QString::fromStdString(t.name + " lacks " + m.id)));
        }
    }

    void createdOnFirstOpenAndEditsPersist()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("sub/tools.sqlite").toStdString();
        {
            auto lib = ToolLibrary::open(path);
            QVERIFY2(lib, lib.ok() ? "" : lib.error().c_str());
            const auto tools = lib->tools();
            QVERIFY(tools);
            QCOMPARE(*tools, defaultToolLibrary());
            Tool t = defaultToolLibrary()[5];
            t.id = 0;
            t.name = "Drill 5 mm, regrind";
            t.holderDiameter = 42;  // the holder's nose, measured
            t.holderLength = 35;
            const auto id = lib->save(t);
            QVERIFY(id && *id > 60);
            QVERIFY(lib->remove(21));
            QVERIFY(lib->addUsage(27, 12.5));
            const Result<void> missing = lib->remove(99);
            QVERIFY(!missing);
            QCOMPARE(missing.error(), path + " has no tool T99");
        }
        auto again = ToolLibrary::open(path);
        const auto tools = again->tools();
        QVERIFY(tools);
        QCOMPARE(tools->size(), defaultToolLibrary().size());  // one added, one removed
        QVERIFY(std::none_of(tools->begin(), tools->end(), [](const Tool& t) { return t.id == 21; }));
        const auto t27 = std::find_if(tools->begin(), tools->end(), [](const Tool& t) { return t.id == 27; });
        QCOMPARE(t27->usedMinutes, 12.5);
        QCOMPARE(tools->back().name, std::string("Drill 5 mm, regrind"));
        QCOMPARE(tools->back().cutting, defaultToolLibrary()[5].cutting);
        QCOMPARE(tools->back().holderDiameter, 42.0);
        QCOMPARE(tools->back().holderLength, 35.0);
        QCOMPARE(t27->holderDiameter, 0.0);  // the default library's: read from the holder's name
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
            sqlite3_exec(db, content.isEmpty() ? "PRAGMA user_version = 9" : "CREATE TABLE parts(x)", nullptr, nullptr, nullptr);
            sqlite3_close(db);
        } else {
            test::writeFile(path, content.toStdString());
        }
        const std::string before = test::readFile(path);
        const auto lib = ToolLibrary::open(path.toStdString());
        QVERIFY(!lib);
        const std::string error = lib.error();
        QVERIFY2(QString::fromStdString(error).contains(message) && QString::fromStdString(error).contains(path), error.c_str());
        QCOMPARE(test::readFile(path), before);
    }

    void anEmptyFileIsRefusedNotFilled()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("tools.sqlite");
        test::writeFile(path, "");
        const auto lib = ToolLibrary::open(path.toStdString());
        QVERIFY(!lib);
        QCOMPARE(lib.error(), path.toStdString() + " is empty, not a tool library (delete it to have the default library created)");
        QCOMPARE(QFileInfo(path).size(), 0);  // the operator's file, untouched
    }

    void impossibleToolValuesAreNamed_data()
    {
        QTest::addColumn<QString>("sql");
        QTest::addColumn<QString>("message");
        QTest::newRow("diameter 0") << "UPDATE tools SET diameter = 0 WHERE id = 27"
                                    << ": tool T27 (Flat end mill 10 mm carbide): diameter 0 mm must be greater than zero";
        QTest::newRow("cutting speed 0") << "UPDATE cutting_data SET surface_speed = 0 WHERE tool_id = 27 AND material = 'pom'"
                                         << ": tool T27 (Flat end mill 10 mm carbide): cutting speed for pom 0 m/min must be greater than zero";
        QTest::newRow("negative feed") << "UPDATE cutting_data SET feed_per_tooth = -0.05 WHERE tool_id = 27 AND material = 'pom'"
                                       << ": tool T27 (Flat end mill 10 mm carbide): feed per tooth for pom -0.05 mm must be greater than zero";
        QTest::newRow("holder narrower than the tool") << "UPDATE tools SET holder_diameter = 6 WHERE id = 27"
                                                       << ": tool T27 (Flat end mill 10 mm carbide): holder Ø 6 mm is narrower than the tool (Ø 10 mm)";
    }
    void impossibleToolValuesAreNamed()
    {
        QFETCH(QString, sql);
        QFETCH(QString, message);
        QTemporaryDir dir;
        const std::string path = dir.filePath("tools.sqlite").toStdString();
        QVERIFY(ToolLibrary::open(path));
        sqlite3* db = nullptr;
        sqlite3_open(path.c_str(), &db);
        QCOMPARE(sqlite3_exec(db, sql.toUtf8().constData(), nullptr, nullptr, nullptr), SQLITE_OK);
        QCOMPARE(sqlite3_changes(db), 1);
        sqlite3_close(db);
        const auto tools = readToolLibrary(path);
        QVERIFY(!tools);
        QCOMPARE(QString::fromStdString(tools.error()), QString::fromStdString(path) + message);
    }

    void versionOneLibraryIsUpgradedInPlace()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("v1.sqlite").toStdString();
        sqlite3* db = nullptr;
        sqlite3_open(path.c_str(), &db);
        // The version 1 schema, as Taiwa 0.1 wrote it, with one shop tool.
        QCOMPARE(sqlite3_exec(db, R"sql(
            CREATE TABLE tools (id INTEGER PRIMARY KEY, name TEXT NOT NULL, type TEXT NOT NULL, diameter REAL NOT NULL,
              corner_radius REAL NOT NULL DEFAULT 0, taper_angle REAL NOT NULL DEFAULT 0, point_angle REAL NOT NULL DEFAULT 118,
              flute_length REAL NOT NULL DEFAULT 0, stickout REAL NOT NULL DEFAULT 0, holder TEXT NOT NULL DEFAULT '',
              flutes INTEGER NOT NULL DEFAULT 2, life_minutes REAL NOT NULL DEFAULT 0, used_minutes REAL NOT NULL DEFAULT 0);
            CREATE TABLE cutting_data (tool_id INTEGER NOT NULL REFERENCES tools(id) ON DELETE CASCADE, material TEXT NOT NULL,
              surface_speed REAL NOT NULL, feed_per_tooth REAL NOT NULL, plunge_factor REAL NOT NULL, PRIMARY KEY (tool_id, material));
            INSERT INTO tools VALUES (7, 'Shop end mill 9 mm', 'flat_end_mill', 9, 0, 0, 118, 20, 40, 'ER25', 3, 100, 12);
            INSERT INTO cutting_data VALUES (7, 'pom', 250, 0.09, 0.4);
            PRAGMA user_version = 1;)sql", nullptr, nullptr, nullptr), SQLITE_OK);
        sqlite3_close(db);
        for (int open = 0; open < 2; ++open) {  // the second open finds version 4 and changes nothing
            auto lib = ToolLibrary::open(path);
            QVERIFY2(lib, lib.ok() ? "" : lib.error().c_str());
            const auto tools = lib->tools();
            QVERIFY2(tools, tools.ok() ? "" : tools.error().c_str());
            // The shop's end mill, the touch probe version 3 brings (T90 was
            // free) and the lathe tools of version 4 (T101-T107 were free).
            // And the hole tools of version 6 (their ids were free).
            QCOMPARE(tools->size(), std::size_t(2) + defaultLatheTools().size() + defaultHoleTools().size());
            const auto probe = std::find_if(tools->begin(), tools->end(), [](const Tool& x) { return x.id == 90; });
            QVERIFY(probe != tools->end());
            QCOMPARE(probe->type, ToolType::Probe);
            QVERIFY(probe->cutting.empty());
            QCOMPARE(tools->back(), defaultLatheTools().back());
            const auto tap = std::find_if(tools->begin(), tools->end(), [](const Tool& x) { return x.type == ToolType::Tap; });
            QVERIFY(tap != tools->end() && tap->turning.pitchMin > 0);  // the pitch kept in the lathe data's column
            const Tool& t = tools->front();
            QCOMPARE(t.id, 7);
            QCOMPARE(t.usedMinutes, 12.0);
            QVERIFY(t.centreCutting);  // what every end mill of a version 1 library was taken to be
            QCOMPARE(t.cutting, (std::vector<CuttingData>{{"pom", 250, 0.09, 0.4}}));
        }
        sqlite3_open(path.c_str(), &db);
        sqlite3_stmt* version = nullptr;
        sqlite3_prepare_v2(db, "PRAGMA user_version", -1, &version, nullptr);
        QCOMPARE(sqlite3_step(version), SQLITE_ROW);
        QCOMPARE(sqlite3_column_int(version, 0), 8);
        sqlite3_finalize(version);
        sqlite3_close(db);
    }

    // The change log (issue "the station at the machine", item 4): an edit
    // is a row naming who, the station, when, the tool before and after; a
    // save that changes nothing is none; removal and addition are rows too.
    void changeLogRemembersEdits()
    {
        QTemporaryDir dir;
        qputenv("TAIWA_STATION", "lathe-cell-3");
        auto lib = ToolLibrary::open(dir.filePath("tools.sqlite").toStdString());
        QVERIFY(lib);
        auto tools = lib->tools();
        QVERIFY(tools);
        const auto mill = std::find_if(tools->begin(), tools->end(),
                                       [](const Tool& t) { return t.type == ToolType::FlatEndMill && t.diameter == 8.0; });
        QVERIFY(mill != tools->end());
        Tool wider = *mill;
        wider.diameter = 12.0;
        QVERIFY(lib->save(*mill));  // unchanged: no row
        QVERIFY(lib->history(mill->id)->empty());
        QVERIFY(lib->save(wider));
        auto h = lib->history(mill->id);
        QVERIFY(h && h->size() == 1);
        const ToolChangeRecord& r = h->front();
        QCOMPARE(QString::fromStdString(r.operation), QString("change"));
        QCOMPARE(QString::fromStdString(r.station), QString("lathe-cell-3"));
        QVERIFY(!r.who.empty() && r.who != "?");
        QVERIFY(QRegularExpression(R"(^\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ$)").match(QString::fromStdString(r.at)).hasMatch());
        QCOMPARE(r.oldValues, toolJson(*mill));
        QCOMPARE(r.newValues, toolJson(wider));
        QCOMPARE(toolChanges(*mill, wider), (std::vector<ToolFieldChange>{{"diameter", "8", "12"}}));
        QVERIFY(lib->remove(mill->id));
        h = lib->history(mill->id);
        QVERIFY(h && h->size() == 2 && h->back().operation == "remove" && h->back().newValues.empty());
        Tool fresh = wider;
        fresh.id = 0;
        const auto id = lib->save(fresh);
        QVERIFY(id);
        h = lib->history(*id);
        QVERIFY(h && !h->empty() && h->back().operation == "add" && h->back().oldValues.empty());
        qunsetenv("TAIWA_STATION");
    }

    // A name that states another size than the tool has is named; the
    // default library's names all state their own.
    void nameStatesTheSize()
    {
        Tool t;
        t.type = ToolType::FlatEndMill;
        t.name = "Flat end mill 8 mm carbide";
        t.diameter = 12.0;
        QCOMPARE(QString::fromStdString(nameSizeMismatch(t).value_or("")), QString("the name says 8 mm, the diameter is 12 mm"));
        t.diameter = 8.0;
        QVERIFY(!nameSizeMismatch(t));
        t.name = "Drill Ø6.8 (M8 tap drill)";
        QVERIFY(nameSizeMismatch(t).has_value());
        t.diameter = 6.8;
        QVERIFY(!nameSizeMismatch(t));
        t.name = "End mill D10, 3 flutes";
        QVERIFY(nameSizeMismatch(t).has_value());
        t.name = "Roughing end mill";  // no size stated
        QVERIFY(!nameSizeMismatch(t));
        t.type = ToolType::TurningInsert;  // an insert's millimetres are its holder's or its bore's
        t.name = "Boring bar, min. bore 16 mm";
        QVERIFY(!nameSizeMismatch(t));
        for (const auto& lib : {defaultToolLibrary(), defaultLatheTools(), defaultHoleTools()})
            for (const Tool& d : lib) QVERIFY2(!nameSizeMismatch(d), (d.name + ": " + nameSizeMismatch(d).value_or("")).c_str());
    }

    void centreCuttingIsStored()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("tools.sqlite").toStdString();
        auto lib = ToolLibrary::open(path);
        QVERIFY(lib);
        Tool t = defaultToolLibrary()[20];
        t.id = 0;
        t.centreCutting = false;
        const auto id = lib->save(t);
        QVERIFY(id);
        const auto tools = lib->tools();
        QVERIFY(!tools->back().centreCutting && tools->back().id == *id);
        const auto face = std::find_if(tools->begin(), tools->end(), [](const Tool& x) { return x.type == ToolType::FaceMill; });
        QVERIFY(!face->centreCutting);
    }

    void lockedLibraryIsReportedNotWaitedOnForever()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("tools.sqlite").toStdString();
        auto lib = ToolLibrary::open(path);
        QVERIFY(lib);
        sqlite3* other = nullptr;
        sqlite3_open(path.c_str(), &other);
        QCOMPARE(sqlite3_exec(other, "BEGIN EXCLUSIVE", nullptr, nullptr, nullptr), SQLITE_OK);
        const Result<void> locked = lib->addUsage(27, 1);
        QVERIFY(!locked);
        QVERIFY2(QString::fromStdString(locked.error()).contains("locked by another program"), locked.error().c_str());
        sqlite3_exec(other, "ROLLBACK", nullptr, nullptr, nullptr);
        sqlite3_close(other);
        QVERIFY(lib->addUsage(27, 1));
    }

    void lockedOnOpenIsReportedAfterTheBusyTimeout()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("tools.sqlite").toStdString();
        QVERIFY(ToolLibrary::open(path));
        sqlite3* other = nullptr;
        sqlite3_open(path.c_str(), &other);
        QCOMPARE(sqlite3_exec(other, "BEGIN EXCLUSIVE; UPDATE tools SET used_minutes = 1", nullptr, nullptr, nullptr), SQLITE_OK);
        QElapsedTimer clock;
        clock.start();
        const auto busy = ToolLibrary::open(path);
        QVERIFY(!busy);
        const std::string error = busy.error();
        QVERIFY(clock.elapsed() >= 1400 && clock.elapsed() < 10000);
        QVERIFY2(QString::fromStdString(error).contains(QString::fromStdString(path + " is locked by another program")), error.c_str());
        sqlite3_exec(other, "ROLLBACK", nullptr, nullptr, nullptr);
        sqlite3_close(other);
    }

    void unwritableFolderIsReported()
    {
        QTemporaryDir dir;
        const QString file = dir.filePath("plain-file");
        test::writeFile(file, "not a folder");
        const std::string path = (file + "/tools.sqlite").toStdString();  // a folder that cannot exist
        const auto lib = ToolLibrary::open(path);
        QVERIFY(!lib);
        const std::string error = lib.error();
        QVERIFY2(QString::fromStdString(error).contains(QString::fromStdString("folder of the tool library " + path)),
                 error.c_str());
        QCOMPARE(test::readFile(file), std::string("not a folder"));
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
        QCOMPARE(speedsFeeds(t, "steel-s45c", 24000, 1500)->feed, 1500.0);  // 24000 x 0.05 x 3 = 3600 clamped
        Tool drill;
        drill.type = ToolType::Drill;
        drill.diameter = 10.2;
        drill.cutting = {{"aluminium-6061", 120, 0.2, 1.0}};
        const auto d = speedsFeeds(drill, "aluminium-6061");
        QCOMPARE(d->rpm, 3745.0);              // 1000 x 120 / (pi x 10.2) = 3744.8
        QCOMPARE(d->feed, 749.0);              // 3745 x 0.2 per revolution, not per flute
        QCOMPARE(d->plungeFeed, 749.0);
    }
};

QTEST_APPLESS_MAIN(TestToolLibrary)
#include "test_tool_library.moc"
