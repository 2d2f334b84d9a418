// The lathe reader's words of a two-path lathe's program (tape_reader_lathe.h,
// post/two_path_post.h): its waits (FANUC's wait M codes; LinuxCNC's output
// and input 0 with the wait's time-out check) and dwells, none a motion.
#include "verify/tape_reader_lathe.h"

#include <algorithm>
#include <string_view>

namespace taiwa::verify::tape {

bool LatheReader::sync(const Block& b)
{
    if (!waits_) return false;
    const bool fanuc = family_ == Family::Fanuc;
    if (std::find(b.g.begin(), b.g.end(), 40) != b.g.end()) {
        const char word = fanuc ? 'X' : 'P';
        if (b.g.size() != 1 || !b.m.empty() || b.v.size() != 1 || !b.has(word) || !(b.v.at(word) >= 0))
            refuse(std::string("only 'G4 ") + word + "<seconds>' alone is understood as a dwell");
        ++m_.out.dwells;
        return true;
    }
    if (fanuc) {
        // A wait M code of the control's range; the block's other words as any block's.
        for (const int mf : b.m)
            if (waits_->contains(mf)) m_.out.waits.push_back({m_.line, mf});
        return false;
    }
    const auto io = std::find_if(b.m.begin(), b.m.end(), [](int mf) { return mf == 64 || mf == 65 || mf == 66; });
    if (io == b.m.end()) return false;
    if (b.m.size() != 1 || !b.g.empty() || !b.has('P') || b.v.at('P') != 0)
        refuse("M64, M65 and M66 are understood on P0 alone in their block (output and input 0, wired to the other path)");
    if (*io != 66) {
        if (b.v.size() != 1) refuse("only 'M64 P0' and 'M65 P0' are understood (output 0 on, off)");
        output_ = *io == 64 ? 1 : 0;
        return true;
    }
    if (b.v.size() != 3 || !b.has('L') || !b.has('Q') || (b.v.at('L') != 3 && b.v.at('L') != 4) || !(b.v.at('Q') > 0))
        refuse("only 'M66 P0 L3|L4 Q<seconds>' is understood (a wait for input 0 high or low, with a time-out)");
    // The k-th meeting: output 0 set to k's parity and the other path's
    // awaited at it; else this wait meets nothing of the other path's.
    const int level = b.v.at('L') == 3 ? 1 : 0;
    const int meeting = static_cast<int>(m_.out.waits.size()) + 1;
    m_.out.waits.push_back({m_.line, level == output_ && level == meeting % 2 ? meeting : -1});
    afterWait_ = true;
    return true;
}

bool LatheReader::timeout(const std::string& s, const std::vector<std::string>& tokens)
{
    if (!waits_ || family_ != Family::LinuxCnc) return false;
    if (tokens[0][0] == 'o' && tokens.size() >= 2 && (tokens[1] == "if" || tokens[1] == "endif")) {
        const auto n = whole(std::string_view(tokens[0]).substr(1));
        if (!n) refuse("'" + s + "' is not understood");
        if (tokens[1] == "if") {
            if (s != tokens[0] + " if [#5399 LT 0]") refuse("only 'o<n> if [#5399 LT 0]', a wait's time-out, is understood");
            if (!afterWait_) refuse("a time-out check with no M66 wait before it");
            if (inTimeout_ >= 0) refuse("an if inside an if");
            inTimeout_ = *n;
        } else {
            if (inTimeout_ != *n || tokens.size() != 2) refuse("an endif with no o" + std::to_string(*n) + " if open");
            inTimeout_ = -1;
        }
        afterWait_ = false;
        return true;
    }
    if (inTimeout_ < 0) return false;
    // The time-out's branch, run only when the other path did not come: it stops the program.
    if (s != "M2") refuse("'" + s + "' in a wait's time-out (only M2, the stop, is understood there)");
    return true;
}

}  // namespace taiwa::verify::tape
