// Ten stations (processes) at once against one shop server: each reads the
// tool library over and over for a few seconds (tool look-ups per second:
// one look-up is the whole library read, as a plan reads it) and then plans
// resources/samples/plate.taiwa with the tools it read, timed; the same ten
// against one SQLite file in the same run. Starts its own PostgreSQL 15
// (tests/support/pg_server.h); prints the figures, or why it could not.
#include "job/job_file.h"
#include "model/technology.h"
#include "pipeline/pipeline.h"
#include "support/pg_server.h"
#include "tools/pg_tool_store.h"
#include "tools/tool_library.h"
#include "tools/tool_store.h"
#include "bench_paths.h"

#include <QTemporaryDir>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

using namespace taiwa;

namespace {

constexpr int kStations = 10;
constexpr double kLookupSeconds = 5.0;
constexpr int kPlans = 3;

struct StationFigures {
    double lookups = 0, seconds = 0, tools = 0, planMs = 0, readMs = 0;
    int ok = 0;
};

double now()
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// One station's work, in the child: look-ups for kLookupSeconds, then
// kPlans plans each reading the library first. Written to `fd`.
void station(const std::string& setting, const std::string& copy, const Job& job, int fd)
{
    StationFigures f;
    auto store = openToolStore(setting, copy);
    if (store) {
        const double start = now();
        while (now() - start < kLookupSeconds) {
            auto tools = (*store)->tools();
            if (!tools) break;
            f.tools = static_cast<double>(tools->size());
            ++f.lookups;
        }
        f.seconds = now() - start;
        for (int i = 0; i < kPlans; ++i) {
            const double t0 = now();
            auto tools = (*store)->tools();
            if (!tools) break;
            const double t1 = now();
            const Plan plan = planJob(job, TechnologyTable::builtIn(), *tools);
            f.readMs += (t1 - t0) * 1e3 / kPlans;
            f.planMs += (now() - t0) * 1e3 / kPlans;
            f.ok = plan.ok() ? 1 : 0;
        }
    }
    (void)::write(fd, &f, sizeof f);
}

// kStations processes at once on `setting`; their figures.
std::vector<StationFigures> stations(const std::string& setting, const std::string& copyDir, const Job& job)
{
    std::vector<std::pair<pid_t, int>> children;
    for (int i = 0; i < kStations; ++i) {
        int p[2];
        if (::pipe(p) != 0) break;
        const pid_t pid = ::fork();
        if (pid == 0) {
            ::close(p[0]);
            ::setenv("TAIWA_STATION", ("bench-" + std::to_string(i)).c_str(), 1);
            station(setting, copyDir + "/copy-" + std::to_string(i) + ".sqlite", job, p[1]);
            ::_exit(0);
        }
        ::close(p[1]);
        children.push_back({pid, p[0]});
    }
    std::vector<StationFigures> out;
    for (auto [pid, fd] : children) {
        StationFigures f;
        if (::read(fd, &f, sizeof f) == static_cast<ssize_t>(sizeof f)) out.push_back(f);
        ::close(fd);
        ::waitpid(pid, nullptr, 0);
    }
    return out;
}

void print(const char* store, const std::vector<StationFigures>& fs)
{
    double lookups = 0, planMs = 0, readMs = 0, worstPlan = 0, tools = 0;
    int ok = 0;
    for (const auto& f : fs) {
        lookups += f.seconds > 0 ? f.lookups / f.seconds : 0;
        planMs += f.planMs / static_cast<double>(fs.size());
        readMs += f.readMs / static_cast<double>(fs.size());
        worstPlan = std::max(worstPlan, f.planMs);
        tools = f.tools;
        ok += f.ok;
    }
    std::printf("%-10s %2zu stations  %8.0f look-ups/s in all (%6.0f tools/s per station)  library read %6.2f ms  "
                "plan of plate.taiwa %7.1f ms mean, %7.1f ms worst  %d/%zu plans ok\n",
                store, fs.size(), lookups, fs.empty() ? 0.0 : lookups * tools / static_cast<double>(fs.size()), readMs, planMs, worstPlan, ok,
                fs.size());
}

}  // namespace

int main()
{
    const JobReadResult read = readJobFile(taiwa::bench::sample("plate"));
    if (!read.job) {
        std::printf("bench_shop_server: plate.taiwa cannot be read\n");
        return 1;
    }
    if (test::PgServer::binaries().isEmpty()) {
        std::printf("bench_shop_server: no PostgreSQL 15 (/usr/lib/postgresql/15/bin); packaging/install-deps.sh installs postgresql-15\n");
        return 0;
    }
    test::PgServer server;
    if (!server.start()) {
        std::printf("bench_shop_server: the server did not start:\n%s\n", qPrintable(server.why()));
        return 1;
    }
    QTemporaryDir dir;
    {
        auto setUp = PgToolStore::open(server.uri(), {});  // migrations and the default library, once
        if (!setUp) {
            std::printf("bench_shop_server: %s\n", setUp.error().c_str());
            return 1;
        }
    }
    const std::string sqlite = dir.filePath("tools.sqlite").toStdString();
    if (!readToolLibrary(sqlite)) return 1;  // created once, before the stations
    std::printf("bench_shop_server: %d stations (processes) on %ld cores, %.0f s of look-ups then %d plans each\n", kStations,
                ::sysconf(_SC_NPROCESSORS_ONLN), kLookupSeconds, kPlans);
    print("postgresql", stations(server.uri(), dir.path().toStdString(), *read.job));
    print("sqlite", stations(sqlite, dir.path().toStdString(), *read.job));
    return 0;
}
