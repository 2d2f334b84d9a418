// Number formatting of the G-code writer: the one place a value becomes the
// characters of a word. Fixed decimals, trailing zeros trimmed, never "-0",
// NaN and infinity refused.
#pragma once

#include <string>

namespace taiwa::post {

// "12.5", "-0.001", "10" (or "10." with a decimal point always, the FANUC
// habit where "X10" may mean 10 µm). Throws std::invalid_argument for NaN or
// infinity: a non-number never reaches a tape.
std::string formatNumber(double value, int decimals, bool decimalPointAlways);

// A whole number (spindle speed, tool and offset numbers): rounded, no point.
std::string formatInteger(double value);

}  // namespace taiwa::post
