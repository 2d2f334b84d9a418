// The machine's speed in the same run, for figures that have no anchor of
// their own: lines like a tape's ("G1 X.. Y.. Z.. F.."), formatted from
// scaled integers with std::to_chars into one growing buffer, nothing else.
// bench_post reports the post-processor's lines/s over this loop's;
// bench_scale prints it beside its times, so that a run on a slower or busier
// machine can be told from a slower program.
#pragma once

#include <algorithm>
#include <charconv>
#include <chrono>
#include <string>

namespace taiwa::bench {

// Writes `lines` lines; the text's size in bytes.
inline std::size_t toCharsLines(int lines)
{
    std::string out;
    out.reserve(lines * 30);
    char buf[32];
    const auto number = [&](long long scaled) {
        // Three decimals, the point put in, trailing zeros kept: the
        // cheapest fixed-point text to_chars allows.
        const bool negative = scaled < 0;
        const long long n = negative ? -scaled : scaled;
        auto [end, ec] = std::to_chars(buf, buf + sizeof buf, n / 1000);
        if (negative) out += '-';
        out.append(buf, end);
        out += '.';
        const long long frac = n % 1000;
        out += static_cast<char>('0' + frac / 100);
        out += static_cast<char>('0' + frac / 10 % 10);
        out += static_cast<char>('0' + frac % 10);
    };
    for (int i = 0; i < lines; ++i) {
        out += "G1 X";
        number(12345 + i * 7);
        out += " Y";
        number(-6789 + i * 3);
        out += " Z";
        number(-2500);
        out += " F1200\n";
    }
    return out.size();
}

// Lines per second of toCharsLines, best of `runs` runs of 1 M lines.
inline double toCharsLinesPerSecond(int runs = 5)
{
    double best = 0;
    for (int r = 0; r < runs; ++r) {
        const auto start = std::chrono::steady_clock::now();
        volatile std::size_t bytes = toCharsLines(1'000'000);
        (void)bytes;
        const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        best = std::max(best, 1e6 / s);
    }
    return best;
}

}  // namespace taiwa::bench
