// The drilling cycles of the Klartext tape reader (tape_reader_klartext.h):
// CYCL DEF 200 DRILLING, 201 REAMING, 202 BORING and 207 RIGID TAPPING NEW
// read into their Q parameters (what this reader does not support
// refused), and the cycle in force run by M99 as the TNC runs it.
#include "verify/tape_reader_klartext.h"

#include <algorithm>
#include <cctype>

namespace taiwa::verify::tape {

void KlartextReader::holeCycle(const Block& b, int number)
{
    static const std::regex q(R"(Q([0-9]+)=([-+][0-9.]+|[A-Z]+) ;[A-Z0-9 -]+?( ~)?)");
    static const std::map<int, std::vector<int>> orders{
        {200, {200, 201, 206, 202, 210, 203, 204, 211}},
        {201, {200, 201, 206, 211, 208, 203, 204}},
        {202, {200, 201, 206, 211, 208, 203, 204, 214, 336}},
        {207, {200, 201, 239, 203, 204}},
    };
    const std::vector<int>& order = orders.at(number);
    if (b.more.size() != order.size()) {
        std::string all;
        for (const int n : order) all += " Q" + std::to_string(n);
        refuse("cycle " + std::to_string(number) + " needs" + all);
    }
    std::map<int, double> v;
    for (std::size_t i = 0; i < b.more.size(); ++i) {
        m_.line = b.more[i].first;
        std::smatch match;
        const int n = order[i];
        if (!std::regex_match(b.more[i].second, match, q) || std::stoi(match[1].str()) != n)
            refuse("Q" + std::to_string(n) + " expected");
        // Q208=MAX: out at rapid (kept as -1, a feed no cycle writes).
        // A cycle parameter's rapid is MAX as the TNC displays it (and
        // FAUTO, AUTO); FMAX is the word of an L block, not a value.
        const std::string word = match[2].str();
        const bool max = word == "MAX";
        if (std::isalpha(static_cast<unsigned char>(word[0])) && !max)
            refuse("Q" + std::to_string(n) + "=" + word + " is not a TNC's cycle parameter value (a rapid is MAX)");
        if (max && n != 208) refuse("MAX is only a retraction feed (Q208) here");
        const auto value = max ? std::optional<double>(-1.0) : decimal(word, true);
        if (!value) refuse("Q" + std::to_string(n) + " is not a number");
        v[n] = *value;
        if ((n == 200 || n == 204) && *value < 0) refuse("a negative set-up clearance");
        if (n == 201 && *value >= 0) refuse("Q201 (depth) must be negative");
        if (n == 206 && !(*value > 0)) refuse("Q206 (plunge feed) must be positive");
        if (n == 202 && !(*value > 0)) refuse("Q202 (plunging depth) must be positive");
        if (n == 208 && *value < 0 && !max) refuse("Q208 (retraction feed) must not be negative");
        if (n == 239 && !(*value > 0)) refuse("Q239 (pitch) must be positive: left-hand tapping is not supported by this reader");
        if (n == 214 && *value != 0) refuse("Q214 (a lift off the wall) is not supported by this reader");
        if ((n == 210 || n == 211) && *value != 0)
            refuse("dwells in cycle " + std::to_string(number) + " are not supported by this reader");
    }
    m_.line = b.line;
    cycleNumber_ = number;
    cycle_ = v;
}

void KlartextReader::cycleCall()
{
    if (cycle_.empty()) refuse("M99 with no cycle defined");
    const double surface = cycle_.at(203);
    const double clearance = surface + cycle_.at(200);
    const double bottom = surface + cycle_.at(201);
    const Point3 at = m_.at;
    m_.traverse({at.x, at.y, clearance});
    switch (cycleNumber_) {
    case 200: {
        const double plunge = cycle_.at(202);
        for (double depth = surface - plunge; depth > bottom; depth -= plunge) {
            m_.feedTo({at.x, at.y, depth}, cycle_.at(206));
            m_.traverse({at.x, at.y, clearance});
            m_.traverse({at.x, at.y, depth + peckReturn(m_.out.inches)});
        }
        m_.feedTo({at.x, at.y, bottom}, cycle_.at(206));
        break;
    }
    case 201:
    case 202: {
        m_.feedTo({at.x, at.y, bottom}, cycle_.at(206));
        if (cycle_.at(208) < 0) break;  // MAX: straight out at rapid to the 2nd set-up clearance, below
        m_.feedTo({at.x, at.y, clearance}, cycle_.at(208) > 0 ? cycle_.at(208) : cycle_.at(206));
        break;
    }
    case 207:
        if (!(rpm_ > 0)) refuse("cycle 207 with no spindle speed (TOOL CALL ... S)");
        m_.feedTo({at.x, at.y, bottom}, cycle_.at(239) * rpm_);
        m_.feedTo({at.x, at.y, clearance}, cycle_.at(239) * rpm_);
        break;
    }
    m_.traverse({at.x, at.y, surface + std::max(cycle_.at(200), cycle_.at(204))});
}

}  // namespace taiwa::verify::tape
