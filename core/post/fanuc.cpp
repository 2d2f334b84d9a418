// The `fanuc` dialect: ISO / FANUC 0i style. '%' leader and trailer, an
// O-number line, N sequence numbers (N10, N20, ... up to N99999), every
// length with a decimal point, comments in upper case, reference-point
// return G91 G28 Z0. before tool changes and at the end, G43 H with the
// first Z move, dwell G4 X<seconds>, extended work offsets G54.1 P1..P48.
#include "post/dialect.h"

namespace taiwa::post {

const Dialect& fanucDialect()
{
    static const Dialect d = [] {
        Dialect t;
        t.name = "fanuc";
        t.percentFraming = true;
        t.programNumberLine = "O{number:04d} ({name})";
        t.sequenceNumbers = true;
        t.maxLineLength = 128;
        t.decimalPointAlways = true;
        t.upperCaseComments = true;
        t.preamble = {"G17 {units} G40 G49 G80 G90"};
        t.extendedWorkOffsets = 48;  // G54.1 P1..P48, the standard option
        t.retract = {"G91 G28 Z0.", "G90"};
        t.lengthOffsetWithZ = true;
        t.dwellWord = 'X';
        return t;
    }();
    return d;
}

}  // namespace taiwa::post
