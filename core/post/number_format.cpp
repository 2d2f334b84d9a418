// Number formatting for NC words (see number_format.h).
#include "post/number_format.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <optional>
#include <string_view>
#include <stdexcept>

namespace taiwa::post {

namespace {
void requireFinite(double value)
{
    if (!std::isfinite(value))
        throw std::invalid_argument("post-processor: a coordinate, feed or speed is not a finite number");
}
}  // namespace

namespace {

constexpr double kPowersOfTen[] = {1, 10, 100, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9};

// The digits of round(value x 10^decimals) as fmt would print them, without
// fmt: the scaled value as an integer, converted with to_chars, the point put
// in, trailing zeros trimmed. nullopt where the fast way could round
// differently from fmt's exact decimal rounding (a scaled value within 1e-6
// of a half, or too large for an integer): fmt decides those.
std::optional<std::string> fastFixed(double value, int decimals, bool decimalPointAlways)
{
    if (decimals < 0 || decimals > 9) return std::nullopt;
    const double scaled = value * kPowersOfTen[decimals];
    if (!(std::abs(scaled) < 9e15)) return std::nullopt;
    const double rounded = std::round(scaled);
    if (std::abs(std::abs(scaled - rounded) - 0.5) < 1e-6) return std::nullopt;
    long long n = static_cast<long long>(rounded);
    char digits[32];
    const bool negative = n < 0;
    if (negative) n = -n;
    const auto [end, ec] = std::to_chars(digits, digits + sizeof digits, n);
    if (ec != std::errc()) return std::nullopt;
    std::string_view d(digits, static_cast<std::size_t>(end - digits));
    const auto width = static_cast<std::size_t>(decimals);
    std::string s;
    s.reserve(d.size() + width + 3);
    if (negative && n != 0) s += '-';
    if (d.size() <= width) {
        s += '0';
        s += '.';
        s.append(width - d.size(), '0');
        s += d;
    } else {
        s.append(d.substr(0, d.size() - width));
        if (width > 0) {
            s += '.';
            s.append(d.substr(d.size() - width));
        }
    }
    if (width > 0) {
        while (s.back() == '0') s.pop_back();
        if (s.back() == '.' && !decimalPointAlways) s.pop_back();
    } else if (decimalPointAlways) {
        s += '.';
    }
    return s;
}

}  // namespace

std::string formatNumber(double value, int decimals, bool decimalPointAlways)
{
    requireFinite(value);
    if (auto fast = fastFixed(value, decimals, decimalPointAlways)) return std::move(*fast);
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

std::string formatInteger(double value)
{
    requireFinite(value);
    const long long n = std::llround(value);
    return fmt::format("{}", n);
}

}  // namespace taiwa::post
