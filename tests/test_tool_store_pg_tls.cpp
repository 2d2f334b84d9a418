// A shop server that takes TLS connections only (docs/shop-server.md,
// "TLS"): a PostgreSQL 15 the test starts itself (support/pg_server.h) with
// ssl = on, a self-signed certificate made by openssl in the test's folder
// and pg_hba.conf holding `hostssl` lines alone. A station asking for TLS
// (sslmode=require; verify-full with the certificate as its root) connects
// and reads the tools over it; one asking for none (sslmode=disable) is
// refused with a message naming the server and saying why. Skipped, saying
// so, where the PostgreSQL binaries or openssl are absent.
#include "support/pg_server.h"
#include "tools/pg_tool_store.h"
#include "tools/tool_library.h"

#include <QFileInfo>
#include <QTemporaryDir>
#include <QtTest>

using namespace taiwa;
using taiwa::test::PgServer;

class TestToolStorePgTls : public QObject {
    Q_OBJECT
private slots:
    void onlyTlsConnectionsAreLetIn()
    {
        if (!QFileInfo("/usr/bin/openssl").isExecutable()) QSKIP("no /usr/bin/openssl here to make the server's certificate");
        TAIWA_START_PG_SERVER(server);
        const QString certificate = server.requireTls();
        QVERIFY2(!certificate.isEmpty(), qPrintable(server.why()));
        QTemporaryDir home;
        const std::string copy = home.filePath("copy.sqlite").toStdString();
        const std::string display = server.uri();  // postgresql://taiwa_admin@127.0.0.1:PORT/taiwa: how messages name it

        // sslmode=require: in, the tools read, and the connection is TLS.
        {
            auto store = PgToolStore::open(server.uri() + "?sslmode=require", {copy, "machine-2", 3});
            QVERIFY2(store, store.ok() ? "" : store.error().c_str());
            QVERIFY2(!(*store)->readOnly(), (*store)->whyOffline().c_str());
            QCOMPARE(QString::fromStdString((*store)->name()), QString::fromStdString(display));
            const auto tools = (*store)->tools();
            QVERIFY2(tools, tools.ok() ? "" : tools.error().c_str());
            QCOMPARE(tools->size(), defaultToolLibrary().size());
            QString ssl;
            QVERIFY2(server.psql("SELECT s.ssl FROM pg_stat_ssl s JOIN pg_stat_activity a USING (pid) WHERE a.application_name = 'machine-2'", &ssl),
                     qPrintable(server.why()));
            QCOMPARE(ssl.trimmed(), QString("t"));
        }
        // verify-full: the server's certificate checked against the shop's
        // root (here the self-signed certificate itself) and its name.
        {
            const std::string uri = QString("postgresql://taiwa_admin@localhost:%1/taiwa?sslmode=verify-full&sslrootcert=%2")
                                        .arg(server.port())
                                        .arg(certificate)
                                        .toStdString();
            auto store = PgToolStore::open(uri, {copy, "machine-2", 3});
            QVERIFY2(store, store.ok() ? "" : store.error().c_str());
            QVERIFY2(!(*store)->readOnly(), (*store)->whyOffline().c_str());
            QVERIFY((*store)->tools());
        }
        // sslmode=disable, no copy: refused, naming the server and TLS.
        {
            auto store = PgToolStore::open(server.uri() + "?sslmode=disable", {{}, "machine-2", 3});
            QVERIFY(!store);
            const QString why = QString::fromStdString(store.error());
            QVERIFY2(why.startsWith(QString::fromStdString(display) + " cannot be reached"), qPrintable(why));
            QVERIFY2(why.contains("lets this station in over TLS only") && why.contains("sslmode=disable"), qPrintable(why));
        }
        // With the copy of the first connection: read-only on it, an edit
        // refused with the same reason.
        {
            auto store = PgToolStore::open(server.uri() + "?sslmode=disable", {copy, "machine-2", 3});
            QVERIFY2(store, store.ok() ? "" : store.error().c_str());
            QVERIFY((*store)->readOnly());
            QVERIFY2(QString::fromStdString((*store)->whyOffline()).contains("over TLS only"), (*store)->whyOffline().c_str());
            const auto tools = (*store)->tools();
            QVERIFY(tools && tools->size() == defaultToolLibrary().size());
            const auto saved = (*store)->save(tools->front(), 1);
            QVERIFY(!saved);
            QVERIFY2(QString::fromStdString(saved.error()).contains("over TLS only"), saved.error().c_str());
        }
    }
};

QTEST_GUILESS_MAIN(TestToolStorePgTls)
#include "test_tool_store_pg_tls.moc"
