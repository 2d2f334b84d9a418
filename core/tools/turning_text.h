// A lathe tool's TurningSpec as the tool library's `turning` column holds
// it (JSON, empty for other tools), written and read back.
#pragma once

#include "model/tool.h"

#include <optional>
#include <string>

namespace taiwa {

std::string turningText(const TurningSpec& t);
// The spec of a column's text; nothing when the text is not such JSON.
std::optional<TurningSpec> turningFrom(const std::string& text);

}  // namespace taiwa
