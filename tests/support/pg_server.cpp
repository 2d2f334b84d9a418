// A PostgreSQL 15 server of a test's own (pg_server.h): initdb, pg_ctl and
// psql of /usr/lib/postgresql/15/bin, as `nobody` when the test runs as root.
#include "support/pg_server.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>

#include <pwd.h>
#include <unistd.h>

namespace taiwa::test {

namespace {

const char* kBin = "/usr/lib/postgresql/15/bin";

// The user the server runs as, when it cannot run as us.
const passwd* serverUser() { return ::getuid() == 0 ? ::getpwnam("nobody") : nullptr; }

// A port no one listens on now (the kernel's choice for port 0).
int freePort()
{
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t len = sizeof a;
    int port = 0;
    if (fd >= 0 && ::bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0 && ::getsockname(fd, reinterpret_cast<sockaddr*>(&a), &len) == 0)
        port = ntohs(a.sin_port);
    if (fd >= 0) ::close(fd);
    return port;
}

}  // namespace

QString PgServer::binaries()
{
    return QFileInfo(QString(kBin) + "/pg_ctl").isExecutable() && QFileInfo(QString(kBin) + "/initdb").isExecutable() ? QString(kBin) : QString();
}

PgServer::PgServer() : data_(dir_.path() + "/data") {}

PgServer::~PgServer()
{
    if (running_) kill();
}

void PgServer::startProcess(QProcess& p, const QString& program, const QStringList& args)
{
    p.setWorkingDirectory(dir_.path());
    p.setProcessChannelMode(QProcess::MergedChannels);
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert("LC_ALL", "C");
    env.remove("PGPASSWORD");
    env.remove("PGSERVICE");
    p.setProcessEnvironment(env);
    if (const passwd* u = serverUser())
        p.start("/usr/sbin/runuser", QStringList{"-u", u->pw_name, "--", program} + args);
    else
        p.start(program, args);
}

bool PgServer::run(const QString& program, const QStringList& args, int timeoutMs, QString* out)
{
    QProcess p;
    startProcess(p, program, args);
    const bool done = p.waitForFinished(timeoutMs);
    const QString text = QString::fromUtf8(p.readAll());
    if (out) *out = text;
    if (!done || p.exitStatus() != QProcess::NormalExit || p.exitCode() != 0) {
        why_ = program + " " + args.join(' ') + ":\n" + text;
        return false;
    }
    return true;
}

bool PgServer::ctlStart()
{
    const QString options = QString("-p %1 -k %2 -c listen_addresses=127.0.0.1 -c fsync=off -c full_page_writes=off").arg(port_).arg(dir_.path());
    running_ = run(QString(kBin) + "/pg_ctl", {"-D", data_, "-l", dir_.path() + "/server.log", "-w", "-t", "60", "-o", options, "start"});
    if (!running_) {
        QFile log(dir_.path() + "/server.log");
        if (log.open(QIODevice::ReadOnly)) why_ += "\nserver.log:\n" + QString::fromUtf8(log.readAll());
    }
    return running_;
}

bool PgServer::start()
{
    if (!dir_.isValid()) {
        why_ = "no temporary folder";
        return false;
    }
    if (const passwd* u = serverUser())
        if (::chown(dir_.path().toLocal8Bit().constData(), u->pw_uid, u->pw_gid) != 0) {
            why_ = "cannot hand the temporary folder to nobody";
            return false;
        }
    port_ = freePort();
    if (!run(QString(kBin) + "/initdb", {"-D", data_, "-U", "taiwa_admin", "-A", "trust", "-E", "UTF8", "--locale=C", "--no-sync"}, 120000))
        return false;
    return ctlStart() && run(QString(kBin) + "/createdb", {"-h", "127.0.0.1", "-p", QString::number(port_), "-U", "taiwa_admin", "taiwa"});
}

bool PgServer::restart() { return ctlStart(); }

bool PgServer::kill()
{
    running_ = false;
    return run(QString(kBin) + "/pg_ctl", {"-D", data_, "-m", "immediate", "-w", "stop"});
}

bool PgServer::stop()
{
    running_ = false;
    return run(QString(kBin) + "/pg_ctl", {"-D", data_, "-m", "fast", "-w", "stop"});
}

std::string PgServer::uri(const QString& user, const QString& db) const
{
    return QString("postgresql://%1@127.0.0.1:%2/%3").arg(user).arg(port_).arg(db).toStdString();
}

std::string PgServer::createDatabase(const QString& db)
{
    return psql(QString("CREATE DATABASE %1").arg(db)) ? uri("taiwa_admin", db) : std::string();
}

QStringList PgServer::psqlArguments(const QString& sql, const QString& user, const QString& db) const
{
    return {"-X", "-q", "-t", "-A", "-v", "ON_ERROR_STOP=1", "-h", "127.0.0.1", "-p", QString::number(port_), "-U", user, "-d", db, "-c", sql};
}

bool PgServer::psql(const QString& sql, QString* out, const QString& user, const QString& db)
{
    return run(QString(kBin) + "/psql", psqlArguments(sql, user, db), 60000, out);
}

std::unique_ptr<QProcess> PgServer::psqlInBackground(const QString& sql)
{
    auto p = std::make_unique<QProcess>();
    startProcess(*p, QString(kBin) + "/psql", psqlArguments(sql, "taiwa_admin", "taiwa"));
    if (!p->waitForStarted(10000)) {
        why_ = "psql did not start";
        return nullptr;
    }
    return p;
}

QString PgServer::requireTls()
{
    const QString crt = dir_.path() + "/server.crt", key = dir_.path() + "/server.key";
    if (!run("/usr/bin/openssl", {"req", "-x509", "-newkey", "rsa:2048", "-nodes", "-days", "2", "-subj", "/CN=localhost", "-addext",
                                  "subjectAltName=DNS:localhost,IP:127.0.0.1", "-keyout", key, "-out", crt}))
        return {};
    // The server refuses a key others may read.
    QFile::setPermissions(key, QFile::ReadOwner | QFile::WriteOwner);
    QFile conf(data_ + "/postgresql.conf"), hba(data_ + "/pg_hba.conf");
    if (!conf.open(QIODevice::Append) ||
        conf.write(QString("ssl = on\nssl_cert_file = '%1'\nssl_key_file = '%2'\n").arg(crt, key).toUtf8()) < 0 ||
        !hba.open(QIODevice::WriteOnly | QIODevice::Truncate) || hba.write("hostssl all all 127.0.0.1/32 trust\n") < 0) {
        why_ = "cannot write the server's configuration";
        return {};
    }
    conf.close();
    hba.close();
    return stop() && restart() ? crt : QString();
}

}  // namespace taiwa::test
