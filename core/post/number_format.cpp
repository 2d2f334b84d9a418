// Number formatting for NC words (see number_format.h).
#include "post/number_format.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace taiwa::post {

namespace {
void requireFinite(double value)
{
    if (!std::isfinite(value))
        throw std::invalid_argument("post-processor: a coordinate, feed or speed is not a finite number");
}
}  // namespace

std::string formatNumber(double value, int decimals, bool decimalPointAlways)
{
    requireFinite(value);
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
