// The drilling cycles of the tape reader (tape_reader_cycles.h).
#include "verify/tape_reader_cycles.h"

#include <optional>
#include <string_view>
#include <vector>

namespace taiwa::verify::tape {

namespace {

// The parameters of "NAME(p1,p2,...)", an empty one as nothing.
std::vector<std::optional<double>> cycleParameters(const std::string& call, const std::string& name)
{
    if (!call.ends_with(")")) refuse("'" + call + "' is not understood");
    const std::string inside = call.substr(name.size() + 1, call.size() - name.size() - 2);
    std::vector<std::optional<double>> p;
    std::size_t from = 0;
    for (int k = 1;; ++k) {
        const auto comma = inside.find(',', from);
        const std::size_t size = comma == std::string::npos ? std::string::npos : comma - from;
        const std::string_view part = std::string_view(inside).substr(from, size);
        if (part.empty()) {
            p.emplace_back();
        } else {
            const auto value = decimal(part, false);
            if (!value) refuse(name + "'s parameter " + std::to_string(k) + " is not a number");
            p.emplace_back(*value);
        }
        if (comma == std::string::npos) break;
        from = comma + 1;
    }
    return p;
}

}  // namespace

// CYCLE81(RTP,RFP,SDIS,DP); CYCLE83(RTP,RFP,SDIS,DP,,FDEP,,DAM,0,0,1,1);
// CYCLE84(RTP,RFP,SDIS,DP,,0,3,,PIT,POSS,SST,SST1);
// CYCLE85(RTP,RFP,SDIS,DP,,0,FFR,RFF); CYCLE86(RTP,RFP,SDIS,DP,,0,3,0,0,0,POSS).
// Any other value of the fixed parameters (dwells, relative depths,
// degression, chip breaking, left-hand tapping, lift off the wall) is
// refused.
SinumerikCycle sinumerikCycle(const std::string& call)
{
    const auto paren = call.find('(');
    const std::string name = call.substr(0, paren == std::string::npos ? call.size() : paren);
    if (paren == std::string::npos || !(name == "CYCLE81" || name == "CYCLE83" || name == "CYCLE84" ||
                                        name == "CYCLE85" || name == "CYCLE86"))
        refuse("'" + call + "' is not understood");
    SinumerikCycle c;
    c.number = std::stoi(name.substr(5));
    const auto p = cycleParameters(call, name);
    const auto need = [&](std::size_t k, const char* what) {
        if (k > p.size() || !p[k - 1]) refuse(name + " needs " + what + " (parameter " + std::to_string(k) + ")");
        return *p[k - 1];
    };
    const auto empty = [&](std::size_t k, const char* what) {
        if (k <= p.size() && p[k - 1])
            refuse(name + "'s " + what + " (parameter " + std::to_string(k) + ") is not supported by this reader");
    };
    const auto only = [&](std::size_t k, double value, const char* what) {
        if (need(k, what) != value) refuse(name + " with " + what + " other than " + show(value) + " is not supported by this reader");
    };
    const std::size_t counts[] = {4, 0, 12, 12, 8, 11};  // CYCLE81, -, 83, 84, 85, 86
    if (c.number == 81 && p.size() != 4) refuse("CYCLE81 needs exactly RTP, RFP, SDIS and DP");
    if (p.size() != counts[c.number - 81]) refuse(name + " needs " + std::to_string(counts[c.number - 81]) + " parameters");
    c.rtp = need(1, "RTP");
    c.rfp = need(2, "RFP");
    c.sdis = need(3, "SDIS");
    c.dp = need(4, "DP (the depth, absolute)");
    if (c.number != 81) empty(5, "DPR (a relative depth)");
    if (c.number == 83) {
        c.fdep = need(6, "FDEP (the first depth, absolute)");
        empty(7, "FDPR (a relative first depth)");
        c.dam = need(8, "DAM (the peck)");
        if (!(c.dam > 0)) refuse("CYCLE83's DAM must be positive (a degression is not supported by this reader)");
        only(9, 0, "DTB (a dwell at depth)");
        only(10, 0, "DTS (a dwell at the start)");
        only(11, 1, "FRF (the first feed's factor)");
        only(12, 1, "VARI (1: chip removal)");
    } else if (c.number == 84) {
        only(6, 0, "DTB (a dwell at depth)");
        only(7, 3, "SDAC (the spindle after the cycle)");
        empty(8, "MPIT (a thread size)");
        c.pit = need(9, "PIT (the pitch)");
        if (!(c.pit > 0)) refuse("CYCLE84's PIT must be positive (left-hand tapping is not supported by this reader)");
        need(10, "POSS (the spindle's stop angle)");
        c.sst = need(11, "SST (the tapping speed)");
        c.sst1 = need(12, "SST1 (the speed out)");
        if (!(c.sst > 0 && c.sst1 > 0)) refuse("CYCLE84's SST and SST1 must be positive");
    } else if (c.number == 85) {
        only(6, 0, "DTB (a dwell at depth)");
        c.ffr = need(7, "FFR (the feed in)");
        c.rff = need(8, "RFF (the feed out)");
        if (!(c.ffr > 0 && c.rff > 0)) refuse("CYCLE85's FFR and RFF must be positive");
    } else if (c.number == 86) {
        only(6, 0, "DTB (a dwell at depth)");
        only(7, 3, "SDIR (the spindle's direction)");
        only(8, 0, "RPA (a lift off the wall)");
        only(9, 0, "RPO (a lift off the wall)");
        only(10, 0, "RPAP (a lift off the wall)");
        need(11, "POSS (the spindle's stop angle)");
    }
    return c;
}

// SINUMERIK: the modally called cycle at the position just reached (the
// tool at its height there): down to RFP + SDIS in rapid, then
// - CYCLE81: feed to DP at F;
// - CYCLE83 (VARI=1, chip removal): pecks to FDEP, then DAM deeper each
//   time, each back up to RFP + SDIS and down again in rapid to
//   peckReturn() above its bottom, the last one to DP, at F (as G83);
// - CYCLE84 (rigid tapping): to DP at PIT x SST, out to RFP + SDIS at
//   PIT x SST1;
// - CYCLE85: to DP at FFR, out to RFP + SDIS at RFF;
// - CYCLE86: to DP at F, the spindle stopped, out in rapid;
// then up to RTP in rapid (CYCLE86: its two rapids up the hole's axis as
// the one straight move they make).
void runCalledCycle(Machine& m, const SinumerikCycle& c, const Point3& to)
{
    const double top = c.rfp + c.sdis;
    if (c.dp > c.rfp) refuse("CYCLE" + std::to_string(c.number) + "'s depth above its reference plane");
    m.traverse({to.x, to.y, top});
    switch (c.number) {
    case 81:
    case 86:
        m.feedTo({to.x, to.y, c.dp}, m.feed);
        break;
    case 83:
        for (double depth = c.fdep; depth > c.dp; depth -= c.dam) {
            m.feedTo({to.x, to.y, depth}, m.feed);
            m.traverse({to.x, to.y, top});
            m.traverse({to.x, to.y, depth + peckReturn(m.out.inches)});
        }
        m.feedTo({to.x, to.y, c.dp}, m.feed);
        break;
    case 84:
        m.feedTo({to.x, to.y, c.dp}, c.pit * c.sst);
        m.feedTo({to.x, to.y, top}, c.pit * c.sst1);
        break;
    case 85:
        m.feedTo({to.x, to.y, c.dp}, c.ffr);
        m.feedTo({to.x, to.y, top}, c.rff);
        break;
    }
    m.traverse({to.x, to.y, c.rtp});
}

// G98 G81/G83/G84/G85/G86 as rs274 expands G81, G83, G85 and G86: up to
// R first when below it, across at the initial level, down to R, then
// - G81: feed to Z;
// - G83: pecks of Q from R, each back up to R and down again in rapid to
//   peckReturn() above its bottom, the last one to Z;
// - G84 (rigid tapping, as the linuxcnc tape's G33.1): feed to Z and
//   back out to R at F (F = pitch x S);
// - G85: feed to Z and back out to R;
// - G86: feed to Z (the spindle stops there);
// then back to the initial level in rapid.
void runCannedCycle(Machine& m, int code, const Point3& hole, double r, double bottom, std::optional<double> q)
{
    const std::string name = "G" + std::to_string(code);
    if (code == 83 && !q) refuse("G83 needs Q (the peck)");
    if (code == 83 && !(*q > 0)) refuse("G83's Q must be positive");
    if (bottom > r) refuse(name + "'s Z above its R");
    if (!known(m.at)) refuse("a canned cycle from an unknown position");
    double initial = m.at.z;
    if (initial < r) {
        m.traverse({m.at.x, m.at.y, r});
        initial = r;
    }
    m.traverse({hole.x, hole.y, initial});
    m.traverse({hole.x, hole.y, r});
    if (code == 83) {
        // rs274's loop, to the same arithmetic.
        for (double depth = r - *q; depth > bottom; depth -= *q) {
            m.feedTo({hole.x, hole.y, depth}, m.feed);
            m.traverse({hole.x, hole.y, r});
            m.traverse({hole.x, hole.y, depth + peckReturn(m.out.inches)});
        }
    }
    m.feedTo({hole.x, hole.y, bottom}, m.feed);
    if (code == 84 || code == 85) m.feedTo({hole.x, hole.y, r}, m.feed);
    m.traverse({hole.x, hole.y, initial});
}

}  // namespace taiwa::verify::tape
