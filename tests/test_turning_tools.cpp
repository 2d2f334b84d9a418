// Lathe tools in the tool library: ISO 1832 insert codes read into their
// numbers (shape, inscribed circle, thickness, nose radius) and refused with
// the letter or digits to blame; the lathe data stored and read back; a
// version 3 library upgraded to version 4 with the default lathe tools where
// their ids are free (the shop's own tools untouched); the finishing tool
// whose nose radius the grinding allowance takes.
#include "support/support.h"
#include "tools/insert_code.h"
#include "tools/tool_library.h"
#include "tools/turning_tools.h"

#include <QTemporaryDir>
#include <QtTest>

#include <sqlite3.h>

using namespace taiwa;

class TestTurningTools : public QObject {
    Q_OBJECT

private slots:
    void isoCodesAreRead_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("code");
        QTest::addColumn<double>("angle");
        QTest::addColumn<double>("ic");
        QTest::addColumn<double>("thickness");
        QTest::addColumn<double>("nose");
        QTest::newRow("CNMG 120408") << "CNMG 120408" << "CNMG 120408" << 80.0 << 12.7 << 4.76 << 0.8;
        QTest::newRow("no space") << "CNMG120408" << "CNMG 120408" << 80.0 << 12.7 << 4.76 << 0.8;
        QTest::newRow("lower case, spaced") << "cnmg 12 04 08" << "CNMG 120408" << 80.0 << 12.7 << 4.76 << 0.8;
        QTest::newRow("DNMG 150604") << "DNMG 150604" << "DNMG 150604" << 55.0 << 12.7 << 6.35 << 0.4;
        QTest::newRow("VCMT 160404") << "VCMT 160404" << "VCMT 160404" << 35.0 << 9.525 << 4.76 << 0.4;
        QTest::newRow("TNMG 160408") << "TNMG 160408" << "TNMG 160408" << 60.0 << 9.525 << 4.76 << 0.8;
        QTest::newRow("WNMG 080408") << "WNMG 080408" << "WNMG 080408" << 80.0 << 12.7 << 4.76 << 0.8;
        QTest::newRow("DCMT 11T304") << "DCMT 11T304" << "DCMT 11T304" << 55.0 << 9.525 << 3.97 << 0.4;
        QTest::newRow("CCMT 09T304") << "CCMT 09T304" << "CCMT 09T304" << 80.0 << 9.525 << 3.97 << 0.4;
        QTest::newRow("VNMG 110404") << "VNMG 110404" << "VNMG 110404" << 35.0 << 6.35 << 4.76 << 0.4;
        QTest::newRow("SNMG 120412") << "SNMG 120412" << "SNMG 120412" << 90.0 << 12.7 << 4.76 << 1.2;
        QTest::newRow("chip breaker") << "CNMG 120408-PM" << "CNMG 120408-PM" << 80.0 << 12.7 << 4.76 << 0.8;
        QTest::newRow("chip breaker, glued") << "DNMG150604MF" << "DNMG 150604-MF" << 55.0 << 12.7 << 6.35 << 0.4;
        QTest::newRow("round RCMT 1204M0") << "RCMT 1204M0" << "RCMT 1204M0" << 0.0 << 12.0 << 4.76 << 0.0;
    }
    void isoCodesAreRead()
    {
        QFETCH(QString, text);
        QFETCH(QString, code);
        QFETCH(double, angle);
        QFETCH(double, ic);
        QFETCH(double, thickness);
        QFETCH(double, nose);
        const auto c = parseInsertCode(text.toStdString());
        QVERIFY2(c, c.ok() ? "" : c.error().c_str());
        QCOMPARE(QString::fromStdString(c->code), code);
        QCOMPARE(c->tipAngle, angle);
        QCOMPARE(c->inscribedCircle, ic);
        QCOMPARE(c->thickness, thickness);
        QCOMPARE(c->noseRadius, nose);
    }

    void clearanceToleranceAndType()
    {
        const auto c = parseInsertCode("VCMT 160404");
        QVERIFY(c);
        QCOMPARE(c->clearance, 'C');
        QCOMPARE(c->clearanceAngle, 7.0);
        QCOMPARE(c->tolerance, 'M');
        QCOMPARE(c->type, 'T');
        QCOMPARE(c->edgeLength, 16.0);
    }

    void badCodesAreRefusedNamingWhatIsWrong_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("message");
        QTest::newRow("shape") << "XNMG 120408"
                               << "'XNMG 120408': X is not an ISO insert shape this program knows (C, D, K, R, S, T, V, W)";
        QTest::newRow("short") << "CNMG 1204" << "'CNMG 1204': an ISO insert code has four letters and six digits, as in CNMG 120408";
        QTest::newRow("size") << "CNMG 130408" << "'CNMG 130408': size 13 is not a C insert's (06, 09, 12, 16, 19)";
        QTest::newRow("clearance") << "CZMG 120408" << "'CZMG 120408': Z is not an ISO clearance letter (N 0°, B 5°, C 7°, P 11°, …)";
        QTest::newRow("thickness") << "CNMG 129908" << "'CNMG 129908': thickness 99 is not an ISO thickness code (02, 03, T3, 04, 06, …)";
        QTest::newRow("nose") << "CNMG 1204X8" << "'CNMG 1204X8': the nose radius X8 must be two digits in tenths of a mm (04 = 0.4 mm) or M0";
        QTest::newRow("M0 on a rhombic insert") << "CNMG 1204M0" << "'CNMG 1204M0': M0 (no corner) is for round inserts only";
        QTest::newRow("garbage suffix") << "CNMG 120408-P/M" << "'CNMG 120408-P/M': the chip breaker 'P/M' must be letters and digits";
    }
    void badCodesAreRefusedNamingWhatIsWrong()
    {
        QFETCH(QString, text);
        QFETCH(QString, message);
        const auto c = parseInsertCode(text.toStdString());
        QVERIFY(!c);
        QCOMPARE(QString::fromStdString(c.error()), message);
    }

    // The default lathe tools carry what their codes say.
    void defaultLatheToolsMatchTheirCodes()
    {
        for (const Tool& t : defaultLatheTools()) {
            QVERIFY2(t.id > 100 && t.id < 200, t.name.c_str());
            if (t.turning.insertCode.empty()) continue;  // blades and the threading insert
            const auto c = parseInsertCode(t.turning.insertCode);
            QVERIFY2(c, t.name.c_str());
            QCOMPARE(t.cornerRadius, c->noseRadius);
            QCOMPARE(t.diameter, c->inscribedCircle);
        }
    }

    void latheDataIsStoredAndReadBack()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("tools.sqlite").toStdString();
        auto lib = ToolLibrary::open(path);
        QVERIFY(lib);
        Tool t = defaultLatheTools()[3];  // the boring bar
        t.id = 0;
        t.turning.minBore = 18.5;
        t.turning.hand = "left";
        const auto id = lib->save(t);
        QVERIFY(id);
        const auto tools = lib->tools();
        QVERIFY(tools);
        const Tool* back = findTool(*tools, *id);
        QVERIFY(back);
        QCOMPARE(back->turning, t.turning);
        QVERIFY(back->turning.inside);
        QCOMPARE(back->turning.insertCode, std::string("DCMT 11T304"));
    }

    // A version 3 library (Taiwa before lathe tools) with a shop tool at
    // T102: upgraded to version 4, the shop's tools untouched, the default
    // lathe tools added where their ids are free.
    void versionThreeLibraryGetsTheLatheTools()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("v3.sqlite").toStdString();
        sqlite3* db = nullptr;
        sqlite3_open(path.c_str(), &db);
        QCOMPARE(sqlite3_exec(db, R"sql(
            CREATE TABLE tools (id INTEGER PRIMARY KEY, name TEXT NOT NULL, type TEXT NOT NULL, diameter REAL NOT NULL,
              corner_radius REAL NOT NULL DEFAULT 0, taper_angle REAL NOT NULL DEFAULT 0, point_angle REAL NOT NULL DEFAULT 118,
              flute_length REAL NOT NULL DEFAULT 0, stickout REAL NOT NULL DEFAULT 0, holder TEXT NOT NULL DEFAULT '',
              flutes INTEGER NOT NULL DEFAULT 2, life_minutes REAL NOT NULL DEFAULT 0, used_minutes REAL NOT NULL DEFAULT 0,
              centre_cutting INTEGER NOT NULL DEFAULT 1);
            CREATE TABLE cutting_data (tool_id INTEGER NOT NULL REFERENCES tools(id) ON DELETE CASCADE, material TEXT NOT NULL,
              surface_speed REAL NOT NULL, feed_per_tooth REAL NOT NULL, plunge_factor REAL NOT NULL, PRIMARY KEY (tool_id, material));
            INSERT INTO tools VALUES (102, 'Shop end mill 11 mm', 'flat_end_mill', 11, 0, 0, 118, 25, 45, 'ER25', 3, 100, 5, 1);
            INSERT INTO cutting_data VALUES (102, 'pom', 250, 0.09, 0.4);
            PRAGMA user_version = 3;)sql", nullptr, nullptr, nullptr), SQLITE_OK);
        sqlite3_close(db);
        auto lib = ToolLibrary::open(path);
        QVERIFY2(lib, lib.ok() ? "" : lib.error().c_str());
        const auto tools = lib->tools();
        QVERIFY2(tools, tools.ok() ? "" : tools.error().c_str());
        // The shop's tool, every lathe tool but T102 (schema 4), and the hole
        // tools (schema 6: taps, reamers, boring heads, their drills).
        QCOMPARE(tools->size(), defaultLatheTools().size() + defaultHoleTools().size());
        for (const Tool& t : defaultHoleTools()) QCOMPARE(*findTool(*tools, t.id), t);
        const Tool* shop = findTool(*tools, 102);
        QVERIFY(shop);
        QCOMPARE(shop->name, std::string("Shop end mill 11 mm"));
        QCOMPARE(shop->usedMinutes, 5.0);
        QVERIFY(shop->turning.empty());
        for (const Tool& t : defaultLatheTools())
            if (t.id != 102) QCOMPARE(*findTool(*tools, t.id), t);
        // With T102 taken, the finishing OD tool is VCMT T103 (0.4 as well, next id).
        QCOMPARE(finishingTurningTool(*tools, false)->id, 103);
    }

    void finishingToolIsTheSmallestNoseRadiusOfItsSide()
    {
        const std::vector<Tool> lib = defaultLatheTools();
        QCOMPARE(finishingTurningTool(lib, false)->id, 102);  // 0.4, ties with T103 broken by id
        QCOMPARE(finishingTurningTool(lib, true)->id, 104);   // the boring bar
        std::vector<Tool> odOnly;
        for (const Tool& t : lib)
            if (!t.turning.inside) odOnly.push_back(t);
        QVERIFY(!finishingTurningTool(odOnly, true));
        QVERIFY(!finishingTurningTool({}, false));
        // Grooving and threading tools never count, however small their nose.
        for (const Tool& t : lib)
            if (t.type != ToolType::TurningInsert) QVERIFY(t.id != finishingTurningTool(lib, false)->id);
    }
};

QTEST_APPLESS_MAIN(TestTurningTools)
#include "test_turning_tools.moc"
