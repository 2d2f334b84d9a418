// The `linuxcnc` dialect: RS274/NGC as LinuxCNC's interpreter reads it. No
// '%' and no N numbers (both optional there), the full modal preamble with
// path blending G64 P0.01, retract G53 G0 Z0 (machine Z0), "G43 H1" in its
// own block after "T1 M6", dwell G4 P<seconds>, work offsets G54..G59 and
// G59.1..G59.3 (no G54.1 P: its interpreter stops at it, so it is refused).
#include "post/dialect.h"

namespace taiwa::post {

const Dialect& linuxcncDialect()
{
    static const Dialect d = [] {
        Dialect t;
        t.name = "linuxcnc";
        t.preamble = {"G17 {units} G40 G49 {workOffset} G80 G90 G94 G64 P0.01"};
        t.moreWorkOffsets = {"G59.1", "G59.2", "G59.3"};
        t.retract = {"G53 G0 Z0"};
        return t;
    }();
    return d;
}

}  // namespace taiwa::post
