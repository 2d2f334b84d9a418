// libFuzzer target for the job reader: any bytes go to readJob, which must
// not crash and must either read a job (and then nothing else) or say why
// not, within the diagnostic cap. A job read must survive writeJob/readJob
// unchanged, and its written text must be canonical. Diagnostics are one
// line of valid UTF-8 each.
// Run: build-fuzz/tests/fuzz/fuzz_job_reader -dict=tests/fuzz/job.dict -max_len=4096 CORPUS resources/samples
// Keep every crashing input, and a corpus minimized with -merge=1 (at most 40
// files), in tests/data/fuzz-regressions: the tests replay that folder.
#include "job/job_file.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

namespace {
void fail(const char* what)
{
    std::fprintf(stderr, "fuzz_job_reader: %s\n", what);
    std::abort();
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const taiwa::JobReadResult read = taiwa::readJob(text);
    if (read.diagnostics.size() > 100) fail("more diagnostics than the cap");
    for (const auto& d : read.diagnostics) {
        const std::string line = taiwa::format("fuzz.taiwa", d);
        if (line.find('\n') != std::string::npos) fail("a diagnostic spans two lines");
        // Messages quote the file: they must stay valid UTF-8 (dump throws otherwise).
        static_cast<void>(nlohmann::json(line).dump());
    }
    if (!read.job) {
        if (read.diagnostics.empty()) fail("no job and no diagnostic");
        return 0;
    }
    if (!read.diagnostics.empty()) fail("a job read with diagnostics");
    const std::string written = taiwa::writeJob(*read.job);
    const taiwa::JobReadResult again = taiwa::readJob(written);
    if (!again.job) fail("the written job does not read back");
    if (!(*again.job == *read.job)) fail("the job changed on writeJob/readJob");
    if (taiwa::writeJob(*again.job) != written) fail("writeJob is not canonical");
    return 0;
}
