// Locale-independent number parsing and formatting for the station forms.
#include "ui/number_text.h"

#include <charconv>
#include <algorithm>
#include <cmath>
#include <string>

namespace taiwa::ui {

std::optional<double> parseNumber(const QString& text)
{
    const std::string s = text.trimmed().toStdString();
    if (s.empty()) return std::nullopt;
    const char* first = s.data();
    if (*first == '+') ++first;  // from_chars does not take a leading '+'
    double v = 0.0;
    const auto [end, ec] = std::from_chars(first, s.data() + s.size(), v, std::chars_format::general);
    if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
    return v;
}

QString formatNumber(double v)
{
    char buf[64];
    const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
    if (ec != std::errc()) return QString::number(v, 'g', 17);
    return QString::fromLatin1(buf, static_cast<int>(end - buf));
}

QString formatShown(double v)
{
    const QString exact = formatNumber(v);
    const auto point = exact.indexOf('.');
    const bool long_ = point >= 0 && !exact.contains('e') && exact.size() - point - 1 > kShownDecimals;
    if (!long_ || std::abs(v) >= 1e9) return exact;
    const double scale = std::pow(10.0, kShownDecimals);
    return formatNumber(std::round(v * scale) / scale);
}

QString clockTime(double minutes)
{
    const long long total = std::llround(std::max(minutes, 0.0) * 60);
    const long long h = total / 3600, m = total / 60 % 60, sec = total % 60;
    if (h > 0) return QStringLiteral("%1:%2:%3").arg(h).arg(m, 2, 10, QLatin1Char('0')).arg(sec, 2, 10, QLatin1Char('0'));
    return QStringLiteral("%1:%2").arg(m).arg(sec, 2, 10, QLatin1Char('0'));
}

}  // namespace taiwa::ui
