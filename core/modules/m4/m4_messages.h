// The messages of M4, the four-cornered pocket: its corners, radius, taper and
// allowances: the sentences of input processing (check/messages.h quotes
// lengths and tools for them) that only this module says, kept in its folder.
#pragma once

#include "check/messages.h"

#include <string>
#include <vector>

namespace taiwa::msg {

std::string alpha3NotBelowAlpha2(Len a3, Len a2);
std::string duplicateCorner(int first, int second, Len x, Len y);
std::string selfIntersecting();
std::string notConvex();
std::string radiusOverHalfSide(Len r1, Len shortestSide);
std::string radiusOverInscribed(Len r1, Len inscribed);
std::string taperOutOfRange(double taper);
std::string taperClosesPocket(double taper, Len meetDepth);

}  // namespace taiwa::msg
