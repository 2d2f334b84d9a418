// Names in other languages in the shop's data (model/local_name.h): a
// material's and a machine's "names" map read, checked and written back, a
// file without one read as before; the tool library keeps a tool's names
// (table tool_names), an older library gets the default tools' names for
// the tools the shop did not rename; the English names stay as they were.
#include "support/support.h"
#include "model/local_names_json.h"
#include "machine/machine.h"
#include "model/technology.h"
#include "tools/tool_library.h"

#include <QTemporaryDir>
#include <QtTest>

#include <sqlite3.h>

#include <algorithm>

using namespace taiwa;

namespace {

const std::string kMachine = R"({"format": "taiwa-machine", "version": 1, "id": "m", "name": "Shop mill", "kind": "mill",
    "travel": {"x": [0, 1], "y": [0, 1], "z": [-1, 0]}, "maxSpindleSpeed": 1, "maxFeed": 1,
    "rapid": {"x": 1, "y": 1, "z": 1}, "toolChanger": {"pockets": 1})";

std::string material(const std::string& names)
{
    return R"({"format": "taiwa-technology", "version": 1, "materials": [{"id": "s50c", "description": "Carbon steel S50C", )" +
           names + R"("alpha1": 1, "alpha2": 0.4, "alpha3": 0.15, "beta2": 0.25, "gamma": 0.3}]})";
}

}  // namespace

class TestLocalNames : public QObject {
    Q_OBJECT
private slots:
    void materialNamesReadAndOldFilesStillRead()
    {
        const auto table = TechnologyTable::fromJson(material(R"("names": {"ja": "機械構造用炭素鋼 S50C", "zh": "50钢"}, )"));
        const MaterialTechnology& m = table.materials().front();
        QCOMPARE(m.description, std::string("Carbon steel S50C"));
        QCOMPARE(m.names, (LocalNames{{"ja", "機械構造用炭素鋼 S50C"}, {"zh", "50钢"}}));
        QCOMPARE(nameIn(m.names, "ja", m.description), std::string("機械構造用炭素鋼 S50C"));
        QCOMPARE(nameIn(m.names, "de", m.description), std::string("Carbon steel S50C"));  // none: the text
        const auto old = TechnologyTable::fromJson(material(""));
        QVERIFY(old.materials().front().names.empty());
        QCOMPARE(old.materials().front().description, std::string("Carbon steel S50C"));
        try {
            TechnologyTable::fromJson(material(R"("names": {"ja": ""}, )"));
            QFAIL("an empty name was taken");
        } catch (const Refusal& e) {  // the place, and what is wrong there
            QCOMPARE(std::string(e.what()), std::string("technology table:1: material s50c: names: the name in 'ja' must be a text that is not empty"));
            QCOMPARE(e.place().key, std::string("material s50c: names"));
        }
        // The shipped table: every material in Japanese and Chinese, its English as the sheet prints it.
        for (const auto& shipped : TechnologyTable::builtIn().materials()) {
            QVERIFY2(shipped.names.contains("ja") && shipped.names.contains("zh"), shipped.id.c_str());
            QVERIFY(shipped.names.at("ja") != shipped.description);
        }
        QCOMPARE(TechnologyTable::builtIn().find("steel-s45c")->description, std::string("Carbon steel S45C / C45 (normalised)"));
    }

    void machineNamesReadAndOldFilesStillRead()
    {
        const auto m = readMachine(kMachine + R"(, "names": {"ja": "工場のフライス盤", "zh-TW": "工廠銑床"}})", "m.json");
        QVERIFY2(m, m.ok() ? "" : m.error().c_str());
        QCOMPARE(m->name, std::string("Shop mill"));
        QCOMPARE(m->names, (LocalNames{{"ja", "工場のフライス盤"}, {"zh-TW", "工廠銑床"}}));
        const auto old = readMachine(kMachine + "}", "m.json");
        QVERIFY(old && old->names.empty());
        const auto bad = readMachine(kMachine + R"(,
            "names": {"Japanese": "x"}})", "m.json");
        QVERIFY(!bad);
        QCOMPARE(bad.error(), std::string("m.json:4: names: 'Japanese' is not a language code (\"ja\", \"zh\", \"zh-TW\")"));
        const auto list = readMachine(kMachine + R"(, "names": ["ja"]})", "m.json");
        QVERIFY(!list);
        QVERIFY2(QString::fromStdString(list.error()).contains("names: must be an object of language codes"), list.error().c_str());
        for (const Machine& shipped : machineLibrary())
            QVERIFY2(shipped.names.contains("ja") && shipped.names.contains("zh"), shipped.id.c_str());
        QCOMPARE(findMachine("vmc")->name, std::string("Vertical machining centre"));  // what `taiwa machines` prints
    }

    // A names map written as the data files have it reads back the same.
    void namesRoundTrip()
    {
        const LocalNames names{{"ja", "立形マシニングセンタ"}, {"zh", "立式加工中心"}};
        const auto text = localNamesJson(names).dump();
        QCOMPARE(text, std::string(R"({"ja":"立形マシニングセンタ","zh":"立式加工中心"})"));
        const auto back = localNamesFrom(nlohmann::json::parse(text));
        QVERIFY(back);
        QCOMPARE(*back, names);
    }

    // The tool library stores a tool's names and reads them back; the
    // default library's tools have theirs, made from their figures.
    void toolNamesRoundTrip()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("tools.sqlite").toStdString();
        auto lib = ToolLibrary::open(path);
        QVERIFY(lib);
        const auto defaults = defaultToolLibrary();
        const Tool& drill = *std::find_if(defaults.begin(), defaults.end(), [](const Tool& t) { return t.id == 10; });
        QCOMPARE(drill.name, std::string("Twist drill 10 mm carbide 5xD"));
        QCOMPARE(drill.names, (LocalNames{{"ja", "超硬ドリル 10 mm 5xD"}, {"zh", "硬质合金麻花钻 10 mm 5xD"}}));
        Tool own = drill;
        own.id = 0;
        own.name = "Shop drill 10";
        own.names = {{"ja", "工場のドリル 10"}};
        const auto id = lib->save(own);
        QVERIFY(id);
        Tool plain = drill;
        plain.id = 0;
        plain.name = "Bohrer 10";
        plain.names.clear();
        const auto plainId = lib->save(plain);
        QVERIFY(plainId);
        const auto tools = ToolLibrary::open(path)->tools();
        QVERIFY(tools);
        const auto byId = [&](int i) { return *std::find_if(tools->begin(), tools->end(), [i](const Tool& t) { return t.id == i; }); };
        QCOMPARE(byId(10), drill);
        QCOMPARE(byId(*id).names, own.names);
        QVERIFY(byId(*plainId).names.empty());
        for (const Tool& t : defaults)
            QVERIFY2(t.names.contains("ja") && t.names.contains("zh"), t.name.c_str());
    }

    // A version 6 library (no names): on opening, the default tools it has
    // under their own id and name get their names; a renamed one does not.
    void olderLibraryGetsTheDefaultNames()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("v6.sqlite").toStdString();
        {
            auto lib = ToolLibrary::open(path);
            QVERIFY(lib);
            Tool renamed = defaultToolLibrary()[4];
            renamed.name = "Our drill";
            renamed.names.clear();
            QVERIFY(lib->save(renamed));
        }
        sqlite3* db = nullptr;
        sqlite3_open(path.c_str(), &db);
        QCOMPARE(sqlite3_exec(db, "DROP TABLE tool_names; PRAGMA user_version = 6;", nullptr, nullptr, nullptr), SQLITE_OK);
        sqlite3_close(db);
        const auto tools = readToolLibrary(path);
        QVERIFY2(tools, tools.ok() ? "" : tools.error().c_str());
        QCOMPARE(tools->size(), defaultToolLibrary().size());
        for (std::size_t i = 0; i < tools->size(); ++i) {
            if (i == 4) {
                QCOMPARE((*tools)[i].name, std::string("Our drill"));
                QVERIFY((*tools)[i].names.empty());
            } else {
                QCOMPARE((*tools)[i], defaultToolLibrary()[i]);
            }
        }
    }
};

QTEST_APPLESS_MAIN(TestLocalNames)
#include "test_local_names.moc"
