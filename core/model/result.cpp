// The words of a Place ("haas.json:12:3: lineLength") and the text of a
// Refusal (model/result.h).
#include "model/result.h"

namespace taiwa {

std::string Place::text() const
{
    std::string s;
    const auto part = [&s](const std::string& p) {
        if (p.empty()) return;
        if (!s.empty()) s += ": ";
        s += p;
    };
    if (unit > 0) part("unit " + std::to_string(unit));
    std::string at = file;
    if (line > 0) {
        at += file.empty() ? "line " + std::to_string(line) : ":" + std::to_string(line);
        if (column > 0) at += file.empty() ? ", column " + std::to_string(column) : ":" + std::to_string(column);
    }
    part(at);
    part(key);
    return s;
}

Refusal::Refusal(std::string message, Place place)
    : message_(std::move(message)), place_(std::move(place)),
      text_(place_.empty() ? message_ : place_.text() + ": " + message_)
{
}

}  // namespace taiwa
