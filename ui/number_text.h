// Locale-independent number text for the forms: '.' is the only decimal
// separator whatever the system locale says, and numbers are shown in their
// shortest round-trip form so that a value read back is the value typed.
#pragma once

#include <QString>

#include <optional>

namespace taiwa::ui {

// The number in `text` (surrounding blanks allowed); nullopt when the text is
// not one finite number ("12,5", "1e", "abc", "").
std::optional<double> parseNumber(const QString& text);

// Shortest text that parses back to exactly `v` ("12.5", "-3", "0.01").
QString formatNumber(double v);

// A time in minutes as the operator reads a clock: "0:25", "12:05",
// "1:02:30" from an hour on; rounded to the second.
QString clockTime(double minutes);

// What a form shows of a stored value: formatNumber, but at most
// kShownDecimals decimals (6 mm converted to inch is stored exactly as
// 0.23622047244094488 and shown as 0.23622). Display only: the job keeps the
// exact value, so converting units never changes what the machine cuts.
constexpr int kShownDecimals = 6;
QString formatShown(double v);

}  // namespace taiwa::ui
