// Measuring a piece of work in a child process of its own, so that its peak
// resident memory (ru_maxrss) is its alone: the scale benchmarks
// (bench_scale, bench_render_scale) run each size this way.
#pragma once

#include <chrono>
#include <functional>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace taiwa::bench {

struct Measured {
    double seconds = 0;
    long peakKb = 0;
    bool ok = false;
    int exitCode = -1;  // the child's, when it exited
};

// Runs `work` in a child; its wall time and peak resident memory. The
// child exits 0 when `work` returns true, 1 when false; `work` may also
// exit with a code of its own (::_exit) to say why it stopped.
inline Measured inChild(const std::function<bool()>& work)
{
    const auto start = std::chrono::steady_clock::now();
    const pid_t pid = ::fork();
    if (pid == 0) ::_exit(work() ? 0 : 1);
    int status = 0;
    rusage usage{};
    ::wait4(pid, &status, 0, &usage);
    Measured m;
    m.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    m.peakKb = usage.ru_maxrss;
    if (WIFEXITED(status)) m.exitCode = WEXITSTATUS(status);
    m.ok = m.exitCode == 0;
    return m;
}

}  // namespace taiwa::bench
