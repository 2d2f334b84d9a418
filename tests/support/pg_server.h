// A PostgreSQL 15 server of a test's own: initdb into a temporary folder,
// started with pg_ctl on a free loopback port, torn down with the test. As
// root (CI) it runs as the unprivileged user `nobody`, since PostgreSQL
// refuses root. Trust authentication on 127.0.0.1 only, fsync off.
#pragma once

#include <QProcess>
#include <QString>
#include <QStringList>
#include <QTemporaryDir>

#include <memory>

// A test function's first lines: skipped, saying so, where the binaries are
// absent; else the server `name` started (the test fails when it cannot be).
#define TAIWA_START_PG_SERVER(name)                                                                                                     \
    if (taiwa::test::PgServer::binaries().isEmpty())                                                                                    \
        QSKIP("no PostgreSQL 15 here (/usr/lib/postgresql/15/bin/pg_ctl is absent); packaging/install-deps.sh installs postgresql-15"); \
    taiwa::test::PgServer name;                                                                                                         \
    QVERIFY2(name.start(), qPrintable(name.why()))

namespace taiwa::test {

class PgServer {
public:
    // Where the Debian binaries are; empty when they are absent (the test
    // then skips, saying so).
    static QString binaries();
    PgServer();
    ~PgServer();
    // initdb, start, and create database `taiwa`; false with why() when not.
    bool start();
    // Started again on the same port and data (after kill or stop).
    bool restart();
    // pg_ctl stop -m immediate: the server dies as in a power cut of its process.
    bool kill();
    bool stop();
    int port() const { return port_; }
    // postgresql://taiwa_admin@127.0.0.1:PORT/taiwa (the superuser), or as `user` on `db`.
    std::string uri(const QString& user = "taiwa_admin", const QString& db = "taiwa") const;
    // A new empty database, and its address (empty when it failed: why()).
    std::string createDatabase(const QString& db);
    // Runs SQL through psql as `user` on `db`; its output, and ok.
    bool psql(const QString& sql, QString* out = nullptr, const QString& user = "taiwa_admin", const QString& db = "taiwa");
    QString why() const { return why_; }
    // TLS only: a self-signed certificate for localhost and 127.0.0.1 made
    // by openssl in the test's folder, ssl = on, and pg_hba.conf letting in
    // TLS connections alone (hostssl); the server restarted. The
    // certificate's path (a station's sslrootcert), empty when it failed: why().
    QString requireTls();
    // psql running `sql` as the superuser without waiting for it (a
    // transaction held open while the test goes on); started, or null.
    std::unique_ptr<QProcess> psqlInBackground(const QString& sql);

private:
    bool run(const QString& program, const QStringList& args, int timeoutMs = 60000, QString* out = nullptr);
    void startProcess(QProcess& p, const QString& program, const QStringList& args);
    QStringList psqlArguments(const QString& sql, const QString& user, const QString& db) const;
    bool ctlStart();
    QTemporaryDir dir_;
    QString data_;
    int port_ = 0;
    bool running_ = false;
    QString why_;
};

}  // namespace taiwa::test
