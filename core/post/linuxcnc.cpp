// The `linuxcnc` dialect: RS274/NGC as LinuxCNC's interpreter reads it. No
// '%' and no N numbers (both optional there), the full modal preamble with
// path blending G64 P0.01, retract G53 G0 Z0 (machine Z0), "G43 H1" in its
// own block after "T1 M6", dwell G4 P<seconds>.
#include "post/dialect.h"

namespace taiwa::post {

const Dialect& linuxcncDialect()
{
    static const Dialect d = [] {
        Dialect t;
        t.name = "linuxcnc";
        t.preamble = {"G17 {units} G40 G49 {workOffset} G80 G90 G94 G64 P0.01"};
        t.retract = {"G53 G0 Z0"};
        return t;
    }();
    return d;
}

}  // namespace taiwa::post
