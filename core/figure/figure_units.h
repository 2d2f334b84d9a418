// The figure text's lengths converted between units (a job switched between
// mm and inch): every length of every statement passed through a map,
// angles (ATANGL) left alone, each statement rewritten in its canonical form
// on its own line; comment lines, blank lines and a statement's trailing
// comment stay as they were.
#pragma once

#include <functional>
#include <string>
#include <string_view>

namespace taiwa::figure {

// `text` with its lengths through `f`; a text that does not parse is given
// back unchanged (its refusal stands and nothing of it is lost).
std::string convertFigureLengths(std::string_view text, const std::function<double(double)>& f);

}  // namespace taiwa::figure
