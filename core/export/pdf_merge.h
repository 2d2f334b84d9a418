// PDF documents made apart joined into one, pages in order (qpdf): the
// instruction sheet's pages are painted by two PDF writers at once on a
// large job (export/sheet_pdf.cpp).
#pragma once

#include "model/result.h"

#include <string>
#include <vector>

namespace taiwa {

// One PDF with the pages of `parts` in order; the first part's document
// information (title, creator) is the whole's. The page streams are copied
// as they are, not compressed again.
Result<std::string> joinPdfs(const std::vector<std::string>& parts);

}  // namespace taiwa
