// The shop's tool crib on a real PostgreSQL 15 the test starts itself
// (support/pg_server.h; skipped, saying so, where the binaries are absent):
// migrations from empty and from every older SQLite library, two stations
// racing on one tool, NOTIFY reaching a second station, the server killed
// mid-transaction, the server away at start-up and coming back, hostile
// values, the stations' roles; and the SQLite store unchanged.
#include "support/pg_server.h"
#include "support/support.h"
#include "tools/pg_job_store.h"
#include "tools/pg_tool_store.h"
#include "tools/tool_library.h"
#include "tools/tool_store.h"

#include <QElapsedTimer>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <sqlite3.h>

#include <atomic>
#include <thread>

using namespace taiwa;
using taiwa::test::PgServer;

#define NEED_SERVER()                                                                                                                   \
    if (!server()) QSKIP(qPrintable("no PostgreSQL 15 here (" + serverWhy_ + "); packaging/install-deps.sh installs postgresql-15"))

namespace {

const Tool& toolOf(const std::vector<VersionedTool>& tools, int id, std::int64_t* version = nullptr)
{
    for (const auto& v : tools)
        if (v.tool.id == id) {
            if (version) *version = v.version;
            return v.tool;
        }
    throw std::logic_error("no tool " + std::to_string(id));
}

std::vector<Tool> plain(const std::vector<VersionedTool>& tools)
{
    std::vector<Tool> out;
    for (const auto& v : tools) out.push_back(v.tool);
    return out;
}

}  // namespace

class TestToolStorePg : public QObject {
    Q_OBJECT

    std::unique_ptr<PgServer> server_;
    QString serverWhy_;
    QTemporaryDir home_;
    int databases_ = 0;

    // The shared server, started on first use; null (with serverWhy_) when
    // the binaries are absent. A server that fails to start fails the test.
    PgServer* server()
    {
        if (server_) return server_.get();
        if (PgServer::binaries().isEmpty()) {
            serverWhy_ = "/usr/lib/postgresql/15/bin/pg_ctl is absent";
            return nullptr;
        }
        server_ = std::make_unique<PgServer>();
        if (!server_->start()) qFatal("the test's PostgreSQL did not start: %s", qPrintable(server_->why()));
        return server_.get();
    }
    // A new empty database on the server, its address.
    std::string freshDatabase()
    {
        const std::string uri = server_->createDatabase(QString("shop%1").arg(++databases_));
        if (uri.empty()) qFatal("CREATE DATABASE failed: %s", qPrintable(server_->why()));
        return uri;
    }
    std::string copyPath(const QString& name) const { return home_.filePath(name).toStdString(); }
    std::unique_ptr<PgToolStore> openStore(const std::string& uri, const std::string& copy = {}, const std::string& station = "test")
    {
        auto s = PgToolStore::open(uri, {copy, station, 3});
        if (!s) qFatal("open %s: %s", uri.c_str(), s.error().c_str());
        return std::move(*s);
    }

private slots:
    void initTestCase()
    {
        // Nothing here writes to the user's data folder.
        qputenv("XDG_DATA_HOME", home_.path().toLocal8Bit());
    }
    void cleanupTestCase() { server_.reset(); }

    // The SQLite store is the ToolLibrary as it was: same tools, a save
    // replaces whatever version is named, ids as before.
    void sqliteStoreIsTheLibraryAsBefore()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("tools.sqlite").toStdString();
        auto store = openToolStore(path);
        QVERIFY2(store, store.ok() ? "" : store.error().c_str());
        QCOMPARE((*store)->name(), path);
        QVERIFY(!(*store)->readOnly());
        auto tools = (*store)->tools();
        QVERIFY(tools);
        QVERIFY(*tools == defaultToolLibrary());
        Tool t = defaultToolLibrary().front();
        t.name = "renamed";
        auto saved = (*store)->save(t, 12345);
        QVERIFY(saved && saved->saved());
        QCOMPARE(readToolLibrary(path)->front().name, std::string("renamed"));
        QVERIFY(!isServerSetting(path));
        QVERIFY(isServerSetting("postgresql://h/db") && isServerSetting("service=shop"));
    }

    // A password in the address is refused, and not repeated in the message.
    void aPasswordInTheAddressIsRefused()
    {
        auto s = PgToolStore::open("postgresql://office:s3cret@127.0.0.1:1/taiwa", {copyPath("never.sqlite"), "t", 1});
        QVERIFY(!s);
        QVERIFY2(s.error().find("holds a password") != std::string::npos, s.error().c_str());
        QVERIFY2(s.error().find("s3cret") == std::string::npos, s.error().c_str());
        auto kw = PgToolStore::open("host=127.0.0.1 port=1 password=s3cret", {});
        QVERIFY(!kw);
        QVERIFY(kw.error().find("s3cret") == std::string::npos);
    }

    // From an empty database: every migration of resources/db/, recorded,
    // and the default library; opening again changes nothing; a database of
    // a newer Taiwa is refused.
    void migratesFromEmpty()
    {
        NEED_SERVER();
        const std::string uri = freshDatabase();
        auto store = openStore(uri);
        auto version = store->schemaVersion();
        QVERIFY(version);
        QCOMPARE(*version, latestShopSchemaVersion());
        QVERIFY(latestShopSchemaVersion() >= 3);
        auto tools = store->versionedTools();
        QVERIFY2(tools, tools.ok() ? "" : tools.error().c_str());
        QVERIFY(plain(*tools) == defaultToolLibrary());
        for (const auto& v : *tools) QCOMPARE(v.version, std::int64_t{1});
        QString files;
        QVERIFY(server_->psql("SELECT string_agg(file, ',' ORDER BY version) FROM taiwa_schema", &files, "taiwa_admin", "shop1"));
        QCOMPARE(files.trimmed(), QString("001_tools.sql,002_jobs.sql,003_grants.sql"));
        store.reset();
        auto again = openStore(uri);
        QVERIFY(plain(*again->versionedTools()) == defaultToolLibrary());
        QVERIFY(server_->psql(QString("INSERT INTO taiwa_schema (version, file) VALUES (%1, 'future.sql')").arg(latestShopSchemaVersion() + 1),
                              nullptr, "taiwa_admin", "shop1"));
        auto newer = PgToolStore::open(uri, {});
        QVERIFY(!newer);
        QVERIFY2(newer.error().find("set up by a newer Taiwa") != std::string::npos, newer.error().c_str());
    }

    // Each older SQLite library (versions 1 to 7) onto the server: the tools
    // a station on that file reads, and the file itself left as it was.
    void importsEveryOlderSqliteLibrary()
    {
        NEED_SERVER();
        // Version 1 as Taiwa 0.1 wrote it, then the schema steps of the
        // SQLite library (core/tools/tool_library.cpp, kMigrations).
        const char* v1 = R"sql(
            CREATE TABLE tools (id INTEGER PRIMARY KEY, name TEXT NOT NULL, type TEXT NOT NULL, diameter REAL NOT NULL,
              corner_radius REAL NOT NULL DEFAULT 0, taper_angle REAL NOT NULL DEFAULT 0, point_angle REAL NOT NULL DEFAULT 118,
              flute_length REAL NOT NULL DEFAULT 0, stickout REAL NOT NULL DEFAULT 0, holder TEXT NOT NULL DEFAULT '',
              flutes INTEGER NOT NULL DEFAULT 2, life_minutes REAL NOT NULL DEFAULT 0, used_minutes REAL NOT NULL DEFAULT 0);
            CREATE TABLE cutting_data (tool_id INTEGER NOT NULL REFERENCES tools(id) ON DELETE CASCADE, material TEXT NOT NULL,
              surface_speed REAL NOT NULL, feed_per_tooth REAL NOT NULL, plunge_factor REAL NOT NULL, PRIMARY KEY (tool_id, material));
            INSERT INTO tools VALUES (7, 'Shop end mill 9 mm', 'flat_end_mill', 9, 0, 0, 118, 20, 40, 'ER25', 3, 100, 12);
            INSERT INTO cutting_data VALUES (7, 'pom', 250, 0.09, 0.4);
            PRAGMA user_version = 1;)sql";
        const char* steps[] = {
            "ALTER TABLE tools ADD COLUMN centre_cutting INTEGER NOT NULL DEFAULT 1; PRAGMA user_version = 2;",
            "PRAGMA user_version = 3;",
            "ALTER TABLE tools ADD COLUMN turning TEXT NOT NULL DEFAULT ''; PRAGMA user_version = 4;",
            "ALTER TABLE tools ADD COLUMN holder_diameter REAL NOT NULL DEFAULT 0; "
            "ALTER TABLE tools ADD COLUMN holder_length REAL NOT NULL DEFAULT 0; PRAGMA user_version = 5;",
            "PRAGMA user_version = 6;",
            "CREATE TABLE tool_names (tool_id INTEGER NOT NULL REFERENCES tools(id) ON DELETE CASCADE, language TEXT NOT NULL, "
            "name TEXT NOT NULL, PRIMARY KEY (tool_id, language)); PRAGMA user_version = 7;",
            "CREATE TABLE tool_changes (tool_id INTEGER NOT NULL, operation TEXT NOT NULL, who TEXT NOT NULL, "
            "station TEXT NOT NULL, at TEXT NOT NULL, old_values TEXT NOT NULL, new_values TEXT NOT NULL); "
            "PRAGMA user_version = 8;",
        };
        const std::string uri = freshDatabase();
        auto store = openStore(uri);
        QTemporaryDir dir;
        for (int version = 1; version <= 8; ++version) {
            const std::string path = dir.filePath(QString("v%1.sqlite").arg(version)).toStdString();
            sqlite3* db = nullptr;
            QCOMPARE(sqlite3_open(path.c_str(), &db), SQLITE_OK);
            QCOMPARE(sqlite3_exec(db, v1, nullptr, nullptr, nullptr), SQLITE_OK);
            for (int s = 0; s + 1 < version; ++s) QCOMPARE(sqlite3_exec(db, steps[s], nullptr, nullptr, nullptr), SQLITE_OK);
            sqlite3_close(db);
            QFile::copy(QString::fromStdString(path), QString::fromStdString(path + ".station"));
            const auto expected = readToolLibrary(path + ".station");  // what a station on that file reads
            QVERIFY(expected);
            auto imported = store->importSqliteLibrary(path);
            QVERIFY2(imported, imported.ok() ? "" : imported.error().c_str());
            QCOMPARE(*imported, static_cast<int>(expected->size()));
            const auto onServer = store->tools();
            QVERIFY(onServer);
            QVERIFY2(*onServer == *expected, qPrintable(QString("version %1").arg(version)));
            QCOMPARE(onServer->front().name, std::string("Shop end mill 9 mm"));
            QCOMPARE(onServer->front().cutting.size(), size_t{1});
            QCOMPARE(onServer->front().usedMinutes, 12.0);
            sqlite3_open(path.c_str(), &db);
            sqlite3_stmt* s = nullptr;
            sqlite3_prepare_v2(db, "PRAGMA user_version", -1, &s, nullptr);
            QCOMPARE(sqlite3_step(s), SQLITE_ROW);
            QCOMPARE(sqlite3_column_int(s, 0), version);  // the shop's file is left as it was
            sqlite3_finalize(s);
            sqlite3_close(db);
        }
    }

    // Two stations editing one tool in strict turns: each read, then both
    // save; the second save is refused every time with both values, and
    // keeping its edit on top of theirs loses nothing: 1,000 edits, 1,000
    // minutes added, 500 conflicts.
    void twoStationsInTurnsLoseNoUpdate()
    {
        NEED_SERVER();
        const std::string uri = freshDatabase();
        auto a = openStore(uri, {}, "office");
        auto b = openStore(uri, {}, "machine-2");
        std::int64_t v0 = 0;
        const double start = toolOf(*a->versionedTools(), 27, &v0).usedMinutes;
        int conflicts = 0, saves = 0;
        for (int round = 0; round < 500; ++round) {
            std::int64_t va = 0, vb = 0;
            Tool ta = toolOf(*a->versionedTools(), 27, &va);
            Tool tb = toolOf(*b->versionedTools(), 27, &vb);
            QCOMPARE(va, vb);
            ta.usedMinutes += 1;
            tb.usedMinutes += 1;
            auto sa = a->save(ta, va);
            QVERIFY(sa && sa->saved());
            QCOMPARE(sa->version, va + 1);
            ++saves;
            auto sb = b->save(tb, vb);
            QVERIFY(sb);
            QVERIFY(!sb->saved());  // never a silent overwrite
            ++conflicts;
            const ToolConflict& c = *sb->conflict;
            QCOMPARE(c.mine.usedMinutes, tb.usedMinutes);
            QVERIFY(c.theirs);
            QCOMPARE(c.theirs->usedMinutes, ta.usedMinutes);
            QCOMPARE(c.theirVersion, sa->version);
            QCOMPARE(c.station, std::string("office"));
            QCOMPARE(c.changedBy, std::string("taiwa_admin"));
            // "Keep mine" on top of theirs: their edit and mine both count.
            Tool merged = *c.theirs;
            merged.usedMinutes += 1;
            auto again = b->save(merged, c.theirVersion);
            QVERIFY(again && again->saved());
            ++saves;
        }
        std::int64_t vEnd = 0;
        const Tool end = toolOf(*a->versionedTools(), 27, &vEnd);
        QCOMPARE(saves, 1000);
        QCOMPARE(conflicts, 500);
        QCOMPARE(end.usedMinutes, start + 1000);
        QCOMPARE(vEnd, v0 + 1000);
        // Negative control: a save at a version long gone is refused too.
        auto stale = a->save(end, v0);
        QVERIFY(stale && !stale->saved());
    }

    // The same race in two threads at once: every edit retried after its
    // conflict until saved; the sum shows no update lost, and the number
    // of conflicts reported equals the number of retries.
    void twoStationsRacingLoseNoUpdate()
    {
        NEED_SERVER();
        const std::string uri = freshDatabase();
        auto a = openStore(uri, {}, "office");
        auto b = openStore(uri, {}, "machine-2");
        const double start = toolOf(*a->versionedTools(), 27).usedMinutes;
        std::atomic<int> conflicts{0}, failures{0}, retries{0};
        const auto edit = [&](PgToolStore& s) {
            for (int i = 0; i < 500; ++i)
                for (bool first = true;; first = false) {
                    if (!first) ++retries;
                    std::int64_t v = 0;
                    auto tools = s.versionedTools();
                    if (!tools) {
                        ++failures;
                        return;
                    }
                    Tool t = toolOf(*tools, 27, &v);
                    t.usedMinutes += 1;
                    auto r = s.save(t, v);
                    if (!r) {
                        ++failures;
                        return;
                    }
                    if (r->saved()) break;
                    if (r->conflict->theirVersion > v) ++conflicts;  // their newer value, shown
                }
        };
        std::thread ta(edit, std::ref(*a)), tb(edit, std::ref(*b));
        ta.join();
        tb.join();
        QCOMPARE(failures.load(), 0);
        QCOMPARE(conflicts.load(), retries.load());
        QCOMPARE(toolOf(*a->versionedTools(), 27).usedMinutes, start + 1000);
        qInfo("1,000 edits racing in two threads: %d conflicts reported and retried", conflicts.load());
    }

    // A change at one station reaches another by NOTIFY within seconds,
    // naming the tool, who and which station; the change log holds the old
    // and new values. A station does not hear its own saves.
    void aChangeReachesTheSecondStation()
    {
        NEED_SERVER();
        const std::string uri = freshDatabase();
        auto office = openStore(uri, {}, "office");
        auto machine = openStore(uri, {}, "machine-2");
        QVERIFY(machine->listen());
        QVERIFY(office->listen());
        QVERIFY(machine->changes(0).empty());
        std::int64_t v = 0;
        Tool t = toolOf(*office->versionedTools(), 27, &v);
        const std::string before = t.name;
        t.name = "Flat end mill 10 mm, reground";
        QElapsedTimer clock;
        clock.start();
        QVERIFY(office->save(t, v)->saved());
        const auto heard = machine->changes(5000);
        QVERIFY2(!heard.empty(), "no NOTIFY within 5 s");
        QVERIFY(clock.elapsed() < 5000);
        QCOMPARE(heard.front().id, 27);
        QCOMPARE(heard.front().station, std::string("office"));
        QCOMPARE(heard.front().who, std::string("taiwa_admin"));
        QCOMPARE(heard.front().version, v + 1);
        QCOMPARE(heard.front().operation, std::string("UPDATE"));
        QVERIFY(office->changes(200).empty());  // its own save
        const auto log = machine->history(27);
        QVERIFY(log);
        QCOMPARE(log->back().station, std::string("office"));
        QVERIFY(log->back().oldValues.find(before) != std::string::npos);
        QVERIFY(log->back().newValues.find("reground") != std::string::npos);
    }

    // The server dies between a save's statements and its COMMIT: the save
    // fails naming the server, the station goes on read-only from its copy,
    // and after the restart the tool is as it was, not half written.
    void serverKilledMidTransaction()
    {
        NEED_SERVER();
        const std::string uri = freshDatabase();
        auto store = openStore(uri, copyPath("killed.sqlite"), "office");
        std::int64_t v = 0;
        const Tool before = toolOf(*store->versionedTools(), 27, &v);
        Tool t = before;
        t.name = "half written";
        t.cutting.clear();
        t.names.clear();
        store->beforeCommit = [&] { QVERIFY(server_->kill()); };
        auto saved = store->save(t, v);
        store->beforeCommit = nullptr;
        QVERIFY(!saved);
        QVERIFY2(saved.error().find("saving tool T27 failed") != std::string::npos, saved.error().c_str());
        QVERIFY(store->readOnly());
        QVERIFY2(store->status().find("tools as of") != std::string::npos, store->status().c_str());
        QVERIFY(server_->restart());
        auto after = openStore(uri, {}, "machine-2");
        std::int64_t vAfter = 0;
        const Tool now = toolOf(*after->versionedTools(), 27, &vAfter);
        QVERIFY(now == before);
        QCOMPARE(vAfter, v);
        QVERIFY(store->reconnect());
        QVERIFY(!store->readOnly());
    }

    // The server away at start-up: the station reads its copy, read-only,
    // says since when, and refuses edits; back, it reads and saves again.
    // Without a copy it says so.
    void serverAwayAtStartUpAndBack()
    {
        NEED_SERVER();
        const std::string uri = freshDatabase();
        const std::string copy = copyPath("away.sqlite");
        {
            auto store = openStore(uri, copy, "office");
            std::int64_t v = 0;
            Tool t = toolOf(*store->versionedTools(), 27, &v);
            t.name = "synchronised name";
            QVERIFY(store->save(t, v)->saved());
            QVERIFY(store->versionedTools());  // the copy follows the server
        }
        QVERIFY(server_->stop());
        auto away = PgToolStore::open(uri, {copy, "office", 2});
        QVERIFY2(away, away.ok() ? "" : away.error().c_str());
        PgToolStore& s = **away;
        QVERIFY(s.readOnly());
        QVERIFY(!s.asOf().empty());
        QVERIFY2(s.status().starts_with("tools as of " + s.asOf()), s.status().c_str());
        const auto tools = s.tools();
        QVERIFY(tools);
        QCOMPARE(toolOf(*s.versionedTools(), 27).name, std::string("synchronised name"));
        Tool t = toolOf(*s.versionedTools(), 27);
        auto refused = s.save(t, 2);
        QVERIFY(!refused);
        QVERIFY2(refused.error().find("cannot be edited until it is back") != std::string::npos, refused.error().c_str());
        QVERIFY(!s.addUsage(27, 1));
        QVERIFY(!s.remove(27));
        QVERIFY(!s.reconnect());  // still away
        auto noCopy = PgToolStore::open(uri, {copyPath("none.sqlite"), "office", 2});
        QVERIFY(!noCopy);
        QVERIFY2(noCopy.error().find("has no copy of its tools yet") != std::string::npos, noCopy.error().c_str());
        QVERIFY(server_->restart());
        auto back = s.reconnect();
        QVERIFY2(back, back.ok() ? "" : back.error().c_str());
        QVERIFY(!s.readOnly());
        std::int64_t v = 0;
        t = toolOf(*s.versionedTools(), 27, &v);
        t.name = "edited again";
        QVERIFY(s.save(t, v)->saved());
    }

    // Hostile values are data: quotes, semicolons, SQL, control characters
    // and 10 MB of text stored and read back as they were; NUL, which the
    // server cannot store, is refused naming the field.
    void hostileValuesAreData()
    {
        NEED_SERVER();
        const std::string uri = freshDatabase();
        auto store = openStore(uri);
        Tool t = defaultToolLibrary().front();
        t.id = 500;
        t.name = "O'Brien\"; DROP TABLE tools; -- \x01\x02\x1b[31m\t\r\n' OR '1'='1";
        t.holder = "$1 $$ \\x00 %s";
        t.names["ja"] = "'); DELETE FROM tool_names; --";
        auto saved = store->save(t, 0);
        QVERIFY2(saved && saved->saved(), saved.ok() ? "" : saved.error().c_str());
        std::int64_t v = 0;
        QVERIFY(toolOf(*store->versionedTools(), 500, &v) == t);
        t.name = std::string(10 * 1024 * 1024, 'x');
        for (size_t i = 0; i < t.name.size(); i += 997) t.name[i] = "';\\\n\x7f"[i % 5];
        saved = store->save(t, v);
        QVERIFY2(saved && saved->saved(), saved.ok() ? "" : saved.error().c_str());
        QVERIFY(toolOf(*store->versionedTools(), 500) == t);
        QCOMPARE(store->tools()->size(), defaultToolLibrary().size() + 1);  // nothing dropped or deleted
        Tool nul = t;
        nul.name = std::string("before\0after", 12);
        auto refused = store->save(nul, saved->version);
        QVERIFY(!refused);
        QVERIFY2(refused.error().find("(name) holds a NUL character") != std::string::npos, refused.error().c_str());
    }

    // The roles of docs/shop-server.md: a reader reads and cannot write, a
    // tool writer writes tools but not the change log, nor jobs.
    void rolesGiveOnlyTheirRights()
    {
        NEED_SERVER();
        const std::string uri = freshDatabase();
        const QString db = QString::fromStdString(uri.substr(uri.rfind('/') + 1));
        auto owner = openStore(uri);  // the owner sets the schema up
        QFile roles(test::sourcePath("resources/db/roles.sql"));
        QVERIFY(roles.open(QIODevice::ReadOnly));
        QVERIFY2(server_->psql(QString::fromUtf8(roles.readAll()), nullptr, "taiwa_admin", db), qPrintable(server_->why()));
        server_->psql("CREATE ROLE presetter LOGIN IN ROLE taiwa_tool_reader", nullptr, "taiwa_admin", db);
        server_->psql("CREATE ROLE machine2 LOGIN IN ROLE taiwa_tool_writer", nullptr, "taiwa_admin", db);
        auto reader = PgToolStore::open(server_->uri("presetter", db), {});
        QVERIFY2(reader, reader.ok() ? "" : reader.error().c_str());
        std::int64_t v = 0;
        Tool t = toolOf(*(*reader)->versionedTools(), 27, &v);
        t.name = "by the presetter";
        auto denied = (*reader)->save(t, v);
        QVERIFY(!denied);
        QVERIFY2(denied.error().find("permission denied") != std::string::npos, denied.error().c_str());
        auto writer = PgToolStore::open(server_->uri("machine2", db), {});
        QVERIFY2(writer, writer.ok() ? "" : writer.error().c_str());
        auto ok = (*writer)->save(t, v);
        QVERIFY2(ok && ok->saved(), ok.ok() ? "" : ok.error().c_str());
        QCOMPARE((*writer)->history(27)->back().who, std::string("machine2"));  // the trigger logs as the station's role
        QVERIFY(!server_->psql("INSERT INTO tool_changes (tool_id, operation) VALUES (27, 'forged')", nullptr, "machine2", db));
        QVERIFY(!server_->psql("INSERT INTO jobs (name) VALUES ('x')", nullptr, "machine2", db));
        QVERIFY(server_->psql("SELECT count(*) FROM tools", nullptr, "presetter", db));  // control: the reader does read
    }

    // The job store: versions with who and which station, any version
    // opened again, the shop-wide lock refusing another station's save and
    // lock (naming the holder) until given back; a hostile name is data.
    void jobStoreKeepsVersionsAndLocks()
    {
        NEED_SERVER();
        const std::string uri = freshDatabase();
        auto office = openStore(uri, {}, "office");
        auto machine = openStore(uri, {}, "machine-2");
        PgJobStore a(*office), b(*machine);
        QCOMPARE(*a.save("plate", "{\"version\": 1}"), 1);
        QCOMPARE(*b.save("plate", "{\"version\": 2}"), 2);
        QCOMPARE(*a.load("plate"), std::string("{\"version\": 2}"));
        QCOMPARE(*a.load("plate", 1), std::string("{\"version\": 1}"));
        auto history = b.history("plate");
        QVERIFY(history);
        QCOMPARE(history->size(), size_t{2});
        QCOMPARE((*history)[0].station, std::string("office"));
        QCOMPARE((*history)[1].station, std::string("machine-2"));
        QCOMPARE((*history)[1].who, std::string("taiwa_admin"));
        QVERIFY(!(*history)[1].at.empty());
        QVERIFY(a.lock("plate"));
        QVERIFY(a.lock("plate"));  // taken again by its holder: fine
        auto refused = b.lock("plate");
        QVERIFY(!refused);
        QVERIFY2(refused.error().find("open at station office (by taiwa_admin since ") != std::string::npos, refused.error().c_str());
        auto notSaved = b.save("plate", "overwrite");
        QVERIFY(!notSaved);
        QVERIFY2(notSaved.error().find("it was not saved") != std::string::npos, notSaved.error().c_str());
        QCOMPARE(*a.save("plate", "{\"version\": 3}"), 3);  // the holder saves
        QVERIFY(b.unlock("plate"));                            // not b's lock: nothing changes
        QVERIFY(!b.lock("plate"));
        QVERIFY(a.unlock("plate"));
        QVERIFY(b.lock("plate"));
        const std::string hostile = "it's; DROP TABLE jobs; --\x1b";
        QCOMPARE(*a.save(hostile, "x'y"), 1);
        QCOMPARE(*b.load(hostile), std::string("x'y"));
        QCOMPARE(*a.names(), (std::vector<std::string>{hostile, "plate"}));
        auto missing = a.load("nothing");
        QVERIFY(!missing);
        QVERIFY2(missing.error().find("has no job 'nothing'") != std::string::npos, missing.error().c_str());
    }

    // The setting reaches the plain reading the command line uses.
    void theSettingReadsTheServer()
    {
        NEED_SERVER();
        const std::string uri = freshDatabase();
        auto read = readToolLibrary(uri);
        QVERIFY2(read, read.ok() ? "" : read.error().c_str());
        QVERIFY(*read == defaultToolLibrary());
        QVERIFY(QFile::exists(QString::fromStdString(defaultServerCopyPath())));
        QVERIFY(defaultServerCopyPath().starts_with(home_.path().toStdString()));
    }
};

QTEST_GUILESS_MAIN(TestToolStorePg)
#include "test_tool_store_pg.moc"
