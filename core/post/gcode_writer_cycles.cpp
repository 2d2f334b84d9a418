// The G-code writer's drilling cycles (gcode_writer.h): ISO's canned
// cycles (G81, G83, G84 with FANUC's M29, G85, G86) kept modal from hole
// to hole, LinuxCNC's G33.1 tapping as explicit moves, and Siemens'
// CYCLE81-86 called modally with MCALL.
#include "post/gcode_writer.h"

#include "post/gcode_writer_axes.h"
#include "post/number_format.h"

#include <fmt/format.h>

#include <algorithm>

namespace taiwa::post {

using namespace detail;

void GCodeWriter::drillCycle(const DrillCycle& c)
{
    requirePosition("a drilling cycle");
    if (dialect_.syntax == Syntax::Sinumerik) {
        sinumerikDrillCycle(c);
        return;
    }
    if (c.cycle == CycleKind::Tap && dialect_.tap == "G33.1") {
        synchronisedTap(c);
        return;
    }
    const bool peck = c.cycle == CycleKind::Drill && c.peck > 0;
    const std::string& code = c.cycle == CycleKind::Tap    ? dialect_.tap
                              : c.cycle == CycleKind::Ream ? dialect_.ream
                              : c.cycle == CycleKind::Bore ? dialect_.bore
                              : peck                       ? dialect_.peckDrill
                                                           : dialect_.drill;
    std::string params = " Z" + length(c.bottom.z) + " R" + length(c.retractZ);
    if (peck) params += " Q" + length(c.peck);
    if (c.cycle == CycleKind::Bore && dialect_.boreDwell) params += " P0";
    const std::string f = formatNumber(c.feed, feedDecimals_, dialect_.decimalPointAlways);
    const Point3 hole{c.bottom.x, c.bottom.y, axis_[Z]->value};
    const bool same = motion_ == code && cycleWords_ == params && feed_ == f;
    if (!same && c.cycle == CycleKind::Tap && !dialect_.rigidTapping.empty()) {
        // FANUC's rigid tapping: M29 with the speed, just before the cycle.
        cancelCycle();
        tape_.block(fmt::format(fmt::runtime(dialect_.rigidTapping), fmt::arg("rpm", formatInteger(rpm_))));
    }
    tape_.beginBlock();
    if (same) {
        axisWords(hole, true);  // one more hole of the same modal cycle
    } else {
        if (cycleWords_.empty()) tape_.word(dialect_.cycleRetract);
        motionWord(code.c_str());
        axisWords(hole, true);
        tape_.append(params);
        feedWord(c.feed);
        cycleWords_ = params;
    }
    tape_.endBlock();
    // Back at the initial level, or at R if that is higher (LinuxCNC's G98).
    if (axis_[Z]->value < c.retractZ) axis_[Z] = written(c.retractZ);
}

void GCodeWriter::synchronisedTap(const DrillCycle& c)
{
    // LinuxCNC's rigid tapping is a motion, not a canned cycle: over the
    // hole at the present height, down to R, G33.1 to the bottom and back
    // to R with the spindle reversed, then up to where the tool came from
    // (as G98 would).
    const double initial = axis_[Z]->exact;
    rapid({c.bottom.x, c.bottom.y, initial});
    rapid({c.bottom.x, c.bottom.y, c.retractZ});
    tape_.beginBlock();
    motionWord("G33.1");
    axisWords({c.bottom.x, c.bottom.y, c.bottom.z}, false);
    char n[kNumberChars];
    tape_.word('K', {n, formatNumberInto(n, c.pitch, decimals_ + 2, dialect_.decimalPointAlways)});
    tape_.endBlock();
    axis_[Z] = written(c.retractZ);
    rapid({c.bottom.x, c.bottom.y, std::max(initial, c.retractZ)});
}

void GCodeWriter::sinumerikDrillCycle(const DrillCycle& c)
{
    // The cycle is called modally (MCALL) at each position that follows, as
    // G81 is; its parameters by position: CYCLE81(RTP, RFP, SDIS, DP) and
    // CYCLE83(RTP, RFP, SDIS, DP, DPR, FDEP, FDPR, DAM, DTB, DTS, FRF, VARI).
    // The reference plane is our R plane with no safety distance of its
    // own, so the cycle drills from where G81 would; it returns to RTP, the
    // initial level (or R when that is higher), as G98 does.
    const double rtp = std::max(axis_[Z]->value, c.retractZ);
    std::string params;
    if (c.cycle == CycleKind::Tap) {
        // Rigid tapping: CYCLE84(RTP, RFP, SDIS, DP, DPR, DTB, SDAC, MPIT,
        // PIT, POSS, SST, SST1), the pitch in PIT, M3 after it, in and out
        // at the spindle speed.
        params = fmt::format("{}({},{},0,{},,0,3,,{},0,{},{})", dialect_.tap, length(rtp), length(c.retractZ),
                             length(c.bottom.z), formatNumber(c.pitch, decimals_ + 2, false), formatInteger(rpm_),
                             formatInteger(rpm_));
    } else if (c.cycle == CycleKind::Ream) {
        // CYCLE85(RTP, RFP, SDIS, DP, DPR, DTB, FFR, RFF): in and out at the feed.
        const std::string f = formatNumber(c.feed, feedDecimals_, false);
        params = fmt::format("{}({},{},0,{},,0,{},{})", dialect_.ream, length(rtp), length(c.retractZ), length(c.bottom.z),
                             f, f);
    } else if (c.cycle == CycleKind::Bore) {
        // CYCLE86(RTP, RFP, SDIS, DP, DPR, DTB, SDIR, RPA, RPO, RPAP, POSS):
        // the spindle stopped at 0° at the bottom, no lift off the wall, M3 after.
        params = fmt::format("{}({},{},0,{},,0,3,0,0,0,0)", dialect_.bore, length(rtp), length(c.retractZ),
                             length(c.bottom.z));
    } else if (c.peck > 0) {
        // Chip removal (VARI=1): out to the reference plane after each peck
        // of DAM, the first one to FDEP; no dwells, full feed at first.
        params = fmt::format("{}({},{},0,{},,{},,{},0,0,1,1)", dialect_.peckDrill, length(rtp), length(c.retractZ),
                             length(c.bottom.z), length(std::max(c.bottom.z, c.retractZ - c.peck)), length(c.peck));
    } else {
        params = fmt::format("{}({},{},0,{})", dialect_.drill, length(rtp), length(c.retractZ), length(c.bottom.z));
    }
    const std::string f = formatNumber(c.feed, feedDecimals_, dialect_.decimalPointAlways);
    if (cycleWords_ != params || feed_ != f) {
        cancelCycle();
        if (feed_ != f) {
            tape_.beginBlock();
            feedWord(c.feed);
            tape_.endBlock();
        }
        tape_.block("MCALL " + params);
        cycleWords_ = params;
    }
    tape_.beginBlock();
    motionWord("G0");
    axisWords({c.bottom.x, c.bottom.y, axis_[Z]->exact}, true);
    tape_.endBlock();
    axis_[Z] = written(rtp);
}

}  // namespace taiwa::post
