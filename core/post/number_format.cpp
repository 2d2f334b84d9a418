// Number formatting for NC words (see number_format.h).
#include "post/number_format.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>

namespace taiwa::post {

namespace {
void requireFinite(double value)
{
    if (!std::isfinite(value))
        throw std::logic_error("post-processor: a coordinate, feed or speed is not a finite number");
}
}  // namespace

namespace {

constexpr double kPowersOfTen[] = {1, 10, 100, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9};

// The digits of round(value x 10^decimals) as fmt would print them, without
// fmt: the scaled value as an integer, converted with to_chars, the point put
// in, trailing zeros trimmed, written to `out`; the count, or 0 where the
// fast way could round differently from fmt's exact decimal rounding (a
// scaled value within 1e-6 of a half, or too large for an integer): fmt
// decides those. `scaled` gets the rounded integer.
std::size_t fastFixed(char* out, double value, int decimals, bool decimalPointAlways, long long& scaledOut)
{
    if (decimals < 0 || decimals > 9) return 0;
    const double scaled = value * kPowersOfTen[decimals];
    if (!(std::abs(scaled) < 9e15)) return 0;
    const double rounded = std::round(scaled);
    if (std::abs(std::abs(scaled - rounded) - 0.5) < 1e-6) return 0;
    long long n = static_cast<long long>(rounded);
    scaledOut = n;
    char digits[24];
    const bool negative = n < 0;
    if (negative) n = -n;
    const auto [end, ec] = std::to_chars(digits, digits + sizeof digits, n);
    if (ec != std::errc()) return 0;
    const auto count = static_cast<std::size_t>(end - digits);
    const auto width = static_cast<std::size_t>(decimals);
    char* o = out;
    if (negative && n != 0) *o++ = '-';
    if (count <= width) {
        *o++ = '0';
        *o++ = '.';
        for (std::size_t k = count; k < width; ++k) *o++ = '0';
        for (std::size_t k = 0; k < count; ++k) *o++ = digits[k];
    } else {
        for (std::size_t k = 0; k < count - width; ++k) *o++ = digits[k];
        if (width > 0) {
            *o++ = '.';
            for (std::size_t k = count - width; k < count; ++k) *o++ = digits[k];
        }
    }
    if (width > 0) {
        while (o[-1] == '0') --o;
        if (o[-1] == '.' && !decimalPointAlways) --o;
    } else if (decimalPointAlways) {
        *o++ = '.';
    }
    return static_cast<std::size_t>(o - out);
}

// fmt's exact decimal rounding, trimmed the same way.
std::string slowFixed(double value, int decimals, bool decimalPointAlways)
{
    std::string s = fmt::format("{:.{}f}", value, decimals);
    if (s.find('.') != std::string::npos) {
        while (s.back() == '0') s.pop_back();
        if (s.back() == '.' && !decimalPointAlways) s.pop_back();
    } else if (decimalPointAlways) {
        s += '.';
    }
    if (s == "-0" || s == "-0.") s.erase(0, 1);
    return s;
}

}  // namespace

std::size_t formatNumberInto(char* out, double value, int decimals, bool decimalPointAlways, double* asRead)
{
    requireFinite(value);
    long long scaled = 0;
    if (const std::size_t n = fastFixed(out, value, decimals, decimalPointAlways, scaled)) {
        // Both exact in a double (|scaled| < 9e15, a power of ten up to 1e9):
        // the quotient is the correctly rounded value of the decimal text.
        if (asRead) *asRead = static_cast<double>(scaled) / kPowersOfTen[decimals];
        return n;
    }
    const std::string s = slowFixed(value, decimals, decimalPointAlways);
    if (s.size() > kNumberChars) throw std::logic_error("post-processor: a number too long for a word: " + s);
    std::copy(s.begin(), s.end(), out);
    if (asRead) std::from_chars(s.data(), s.data() + s.size(), *asRead);
    return s.size();
}

std::string formatNumber(double value, int decimals, bool decimalPointAlways)
{
    char buf[kNumberChars];
    return std::string(buf, formatNumberInto(buf, value, decimals, decimalPointAlways));
}

std::string formatInteger(double value)
{
    requireFinite(value);
    const long long n = std::llround(value);
    return fmt::format("{}", n);
}

}  // namespace taiwa::post
