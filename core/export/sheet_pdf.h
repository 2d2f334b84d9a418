// The instruction sheet as an A4 landscape PDF, painted with Qt (the only
// part of the sheet that needs Qt; sheet/ builds its content without it).
#pragma once

#include "sheet/sheet.h"

#include <optional>
#include <string>

namespace taiwa {

// Writes the sheet to `path`. Needs a QGuiApplication (the command line runs
// one on the offscreen platform). Returns an error message or nothing on
// success.
std::optional<std::string> writeSheetPdf(const Plan& plan, const SheetOptions& options, const std::string& path);

}  // namespace taiwa
