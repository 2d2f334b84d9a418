// The instruction sheet as an A4 landscape PDF, painted with Qt (the only
// part of the sheet that needs Qt; sheet/ builds its content without it).
#pragma once

#include "model/result.h"
#include "sheet/sheet.h"

#include <optional>
#include <string>

namespace taiwa {

// The sheet's PDF, as bytes. Needs a QGuiApplication (the command line runs
// one on the offscreen platform).
Result<std::string> sheetPdf(const Plan& plan, const SheetOptions& options);
// The same, written atomically to `path`.
Result<void> writeSheetPdf(const Plan& plan, const SheetOptions& options, const std::string& path);

}  // namespace taiwa
