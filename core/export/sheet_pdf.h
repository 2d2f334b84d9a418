// The instruction sheet as an A4 landscape PDF, painted with Qt (the only
// part of the sheet that needs Qt; sheet/ builds its content without it).
#pragma once

#include "model/result.h"
#include "sheet/sheet.h"

#include <optional>
#include <string>

namespace taiwa {

// How many PDF writers paint the sheet: two at once for a large steps table
// (BySize), or as a test asks: one, or two wherever the table spans pages.
enum class PdfParts { BySize, One, Two };
// The sheet's PDF, as bytes. Needs a QGuiApplication (the command line runs
// one on the offscreen platform).
Result<std::string> sheetPdf(const Plan& plan, const SheetOptions& options, PdfParts parts = PdfParts::BySize);
// The same, written atomically to `path`.
Result<void> writeSheetPdf(const Plan& plan, const SheetOptions& options, const std::string& path);

}  // namespace taiwa
