// libFuzzer target for the shop's data files (issue 39): the first byte
// chooses the reader (even: a dialect, readDialect; odd: a machine,
// readMachine), the rest is the file. Neither may crash; a refusal is one
// line of valid UTF-8 naming the file; a dialect read expands every template
// with the fields its writer gives (never throwing) into a block of the
// dialect's line length with no line break and no '%'; a machine read has
// finite limits above zero and an id of the documented characters.
// Run: build-fuzz/tests/fuzz/fuzz_data_files -dict=tests/fuzz/data_files.dict -max_len=4096 -timeout=1
//      -rss_limit_mb=256 CORPUS tests/fuzz/corpus/data_files
#include "machine/machine.h"
#include "post/dialect.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

void fail(const char* what, const std::string& detail = {})
{
    std::fprintf(stderr, "fuzz_data_files: %s %s\n", what, detail.c_str());
    std::abort();
}

void refusal(const std::string& message)
{
    if (!message.starts_with("fuzz.json")) fail("a refusal that does not name the file:", message);
    if (message.find('\n') != std::string::npos) fail("a refusal of two lines:", message);
    static_cast<void>(nlohmann::json(message).dump());  // throws on text that is not UTF-8
}

void block(const taiwa::post::Dialect& d, const std::string& b)
{
    if (b.size() > d.maxLineLength) fail("a block longer than the line:", b);
    for (const char c : b)
        if (c == '\n' || c == '\r' || c == '%') fail("a block with a line break or '%':", b);
}

void dialect(const taiwa::post::Dialect& d)
{
    using fmt::arg;
    using fmt::runtime;
    try {
        if (!d.programNumberLine.empty())
            block(d, fmt::format(runtime(d.programNumberLine), arg("number", 9999), arg("name", std::string(40, 'N'))));
        for (const auto& p : d.preamble)
            block(d, fmt::format(runtime(p), arg("units", d.inchWord), arg("workOffset", "G54")));
        block(d, fmt::format(runtime(d.toolChange), arg("tool", 99)));
        block(d, fmt::format(runtime(d.lengthOffset), arg("tool", 99)));
        if (!d.rigidTapping.empty()) block(d, fmt::format(runtime(d.rigidTapping), arg("rpm", "1200")));
        if (d.extendedWorkOffsets > 0) block(d, fmt::format(runtime(d.extendedWorkOffset), arg("n", d.extendedWorkOffsets)));
    } catch (const fmt::format_error& e) {
        fail("a template read that does not expand:", e.what());
    }
    for (const std::string* w : {&d.spindleClockwise, &d.spindleStop, &d.coolantOn, &d.coolantOff, &d.programEnd, &d.drill})
        if (w->empty()) fail("a required word is empty");
    for (const auto& r : d.retract) block(d, r);
}

void machine(const taiwa::Machine& m)
{
    if (m.id.empty() || m.id.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789-_") != std::string::npos)
        fail("an id outside its characters:", m.id);
    for (const double v : {m.maxSpindleSpeed, m.maxFeed, m.slowestRapid()})
        if (!std::isfinite(v) || !(v >= 1.0) || v > 1e6) fail("a limit out of range");
    for (const auto& [axis, t] : m.travel)
        if (!std::isfinite(t.min) || !std::isfinite(t.max) || !(t.min < t.max)) fail("a travel out of range");
    if (m.lookAhead < 1 || m.lookAhead > 10000) fail("a look-ahead out of range");
    static_cast<void>(nlohmann::json(m.name).dump());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    if (size == 0) return 0;
    const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
    if (data[0] & 1) {
        const auto m = taiwa::readMachine(text, "fuzz.json");
        if (m) machine(*m);
        else refusal(m.error());
    } else {
        const auto d = taiwa::post::readDialect(text, "fuzz.json");
        if (d) dialect(*d);
        else refusal(d.error());
    }
    return 0;
}
