// Number formatting of the G-code writer: the one place a value becomes the
// characters of a word. Fixed decimals, trailing zeros trimmed, never "-0",
// NaN and infinity refused.
#pragma once

#include <cstddef>
#include <string>

namespace taiwa::post {

// "12.5", "-0.001", "10" (or "10." with a decimal point always, the FANUC
// habit where "X10" may mean 10 µm). Throws std::logic_error for NaN or
// infinity (a bug upstream): a non-number never reaches a tape.
std::string formatNumber(double value, int decimals, bool decimalPointAlways);

// The same characters written into `out` (at least kNumberChars long); their
// count. `asRead` gets the value a controller reads back from them (the
// scaled integer over the power of ten: what a correctly rounded parse of
// the text gives, without parsing it). The writer's hot path: no string.
constexpr std::size_t kNumberChars = 48;
std::size_t formatNumberInto(char* out, double value, int decimals, bool decimalPointAlways, double* asRead = nullptr);

// A whole number (spindle speed, tool and offset numbers): rounded, no point.
std::string formatInteger(double value);

}  // namespace taiwa::post
