// A PostgreSQL 15 server of a test's own: initdb into a temporary folder,
// started with pg_ctl on a free loopback port, torn down with the test. As
// root (CI) it runs as the unprivileged user `nobody`, since PostgreSQL
// refuses root. Trust authentication on 127.0.0.1 only, fsync off.
#pragma once

#include <QString>
#include <QStringList>
#include <QTemporaryDir>

#include <memory>

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

private:
    bool run(const QString& program, const QStringList& args, int timeoutMs = 60000, QString* out = nullptr);
    bool ctlStart();
    QTemporaryDir dir_;
    QString data_;
    int port_ = 0;
    bool running_ = false;
    QString why_;
};

}  // namespace taiwa::test
