// The reader of HEIDENHAIN Klartext tapes (readTape's, tape_reader.h): every
// block understood word by word, the drilling cycles expanded as the manuals
// describe, or the reading stopped at its line.
#include "verify/tape_reader_machine.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <set>
#include <string_view>

namespace taiwa::verify {

namespace {

using namespace tape;

class KlartextReader {
public:
    TapeReading read(const std::string& text)
    {
        const auto lines = splitLines(text);
        try {
            group(lines);
            for (std::size_t k = 0; k < blocks_.size(); ++k) {
                m_.line = blocks_[k].line;
                block(k);
            }
        } catch (const Unread& r) {
            m_.out.error = lineError(m_.line, r, lines);
            m_.out.errorLine = m_.line;
        }
        return std::move(m_.out);
    }

private:
    struct Block {
        int line = 0;                                     // of its first line
        std::string head;                                 // after the block number
        std::vector<std::pair<int, std::string>> more;    // continuation lines (line, text)
    };

    struct Words {
        std::optional<double> x, y, z, ipa, iz, f;
        bool fmax = false, r0 = false;
        int dr = 0;
        std::vector<int> m;
    };

    // Lines into numbered blocks with their '~' continuation lines.
    void group(const std::vector<std::string>& lines)
    {
        bool open = false;
        int expected = 0;
        for (std::size_t i = 0; i < lines.size(); ++i) {
            m_.line = static_cast<int>(i) + 1;
            const std::string& l = lines[i];
            if (l.find_first_of("\r\t") != std::string::npos) refuse("a carriage return or tab");
            if (l.starts_with("  ")) {
                if (!open) refuse("a continuation line with no '~' before it");
                const std::string t = trim(l);
                blocks_.back().more.emplace_back(m_.line, t);
                open = t.ends_with("~");
                continue;
            }
            if (open) refuse("the block before ends with '~' but this line does not continue it");
            const auto space = l.find(' ');
            const auto n = whole(std::string_view(l).substr(0, space));
            if (space == std::string::npos || !n) refuse("a block that does not begin with its number");
            if (*n != expected) refuse("block number " + std::to_string(*n) + ", expected " + std::to_string(expected));
            ++expected;
            blocks_.push_back({m_.line, l.substr(space + 1), {}});
            open = blocks_.back().head.ends_with("~");
        }
        if (open) refuse("the last block ends with '~'");
        if (blocks_.size() < 2) refuse("a program has at least BEGIN PGM and END PGM");
    }

    void block(std::size_t k)
    {
        const Block& b = blocks_[k];
        const std::string& h = b.head;
        std::smatch match;
        static const std::regex begin(R"(BEGIN PGM (\S+) (MM|INCH))");
        static const std::regex end(R"(END PGM (\S+) (MM|INCH))");
        static const std::regex blk1(R"(BLK FORM 0\.1 Z X[-+][0-9.]+ Y[-+][0-9.]+ Z[-+][0-9.]+)");
        static const std::regex blk2(R"(BLK FORM 0\.2 X[-+][0-9.]+ Y[-+][0-9.]+ Z[-+][0-9.]+)");
        static const std::regex dwell(R"(CYCL DEF 9\.1 DWELL ([0-9.]+))");
        static const std::regex datum(R"(Q339=\+[0-9]+ ;DATUM NUMBER)");
        if (k == 0) {
            if (!std::regex_match(h, match, begin)) refuse("a program begins with BEGIN PGM name MM|INCH");
            name_ = match[1].str();
            unit_ = match[2].str();
            m_.units(unit_ == "INCH");
            return;
        }
        if (k + 1 == blocks_.size()) {
            if (dwellDue_) refuse("CYCL DEF 9.0 with no 9.1 after it");
            if (!std::regex_match(h, match, end) || match[1].str() != name_ || match[2].str() != unit_)
                refuse("a program ends with END PGM " + name_ + " " + unit_);
            if (!ended_) refuse("END PGM with no M30 before it");
            return;
        }
        if (!b.more.empty() && !h.starts_with("CYCL DEF 247 ") && !h.starts_with("CYCL DEF 200 ") &&
            !h.starts_with("CYCL DEF 201 ") && !h.starts_with("CYCL DEF 202 ") && !h.starts_with("CYCL DEF 207 "))
            refuse("continuation lines after a block that has none");
        if (dwellDue_ != h.starts_with("CYCL DEF 9.1 ")) refuse("CYCL DEF 9.0 and 9.1 go together");
        if (ended_) refuse("a block after M30 other than END PGM");
        if (h.starts_with(";")) {
            m_.comment(h.substr(1));
        } else if (h.starts_with("BLK FORM 0.1 ")) {
            if (!std::regex_match(h, blk1)) refuse("BLK FORM 0.1 not understood");
            blankDue_ = true;
        } else if (h.starts_with("BLK FORM 0.2 ")) {
            if (!blankDue_ || !std::regex_match(h, blk2)) refuse("BLK FORM 0.2 not understood (or without 0.1 before it)");
            blankDue_ = false;
        } else if (h == "CYCL DEF 247 DATUM SETTING ~") {
            if (b.more.size() != 1 || !std::regex_match(b.more[0].second, datum)) refuse("cycle 247 needs Q339 alone");
        } else if (h == "CYCL DEF 200 DRILLING ~") {
            holeCycle(b, 200);
        } else if (h == "CYCL DEF 201 REAMING ~") {
            holeCycle(b, 201);
        } else if (h == "CYCL DEF 202 BORING ~") {
            holeCycle(b, 202);
        } else if (h == "CYCL DEF 207 RIGID TAPPING NEW ~") {
            holeCycle(b, 207);
        } else if (h == "CYCL DEF 9.0 DWELL TIME") {
            dwellDue_ = true;
        } else if (h.starts_with("CYCL DEF 9.1 ")) {
            if (!std::regex_match(h, dwell)) refuse("CYCL DEF 9.1 DWELL needs the time in seconds");
            dwellDue_ = false;
            ++m_.out.dwells;
        } else if (h.starts_with("TOOL CALL ")) {
            toolCall(splitWords(h.substr(10)));
        } else {
            const auto tokens = splitWords(h);
            if (tokens.empty()) refuse("an empty block");
            const std::string& kind = tokens[0];
            if (kind == "L" || kind == "CC" || kind == "C" || kind == "CP") {
                move(kind, parseWords(kind, tokens));
            } else if (std::all_of(tokens.begin(), tokens.end(), [](const std::string& t) { return t.starts_with("M"); })) {
                const Words w = parseWords("", tokens);
                mFunctions(w, false);
            } else {
                refuse("block not understood");
            }
        }
    }

    static double signedNumber(const std::string& t, std::size_t skip)
    {
        const std::string_view s = std::string_view(t).substr(skip);
        if (s.empty() || (s.front() != '+' && s.front() != '-')) refuse("'" + t + "': a signed number expected");
        const auto v = decimal(s, true);
        if (!v) refuse("'" + t + "' is not understood");
        return *v;
    }

    // The words of an L, CC, C or CP block, or of a bare M block (`kind` "").
    static Words parseWords(const std::string& kind, const std::vector<std::string>& tokens)
    {
        Words w;
        std::set<std::string> seen;
        const auto once = [&](const std::string& key) {
            if (!seen.insert(key).second) refuse("two " + key + " words in one block");
        };
        const auto allowed = [&](const std::string& word, const char* kinds) {
            const std::string k = " " + kind + " ";
            if (std::string(kinds).find(k) == std::string::npos)
                refuse("'" + word + "' in a " + (kind.empty() ? "bare M" : kind) + " block");
        };
        for (std::size_t i = kind.empty() ? 0 : 1; i < tokens.size(); ++i) {
            const std::string& t = tokens[i];
            if (t == "FMAX") {
                allowed(t, " L ");
                once("F");
                w.fmax = true;
            } else if (t == "R0") {
                allowed(t, " L ");
                once(t);
                w.r0 = true;
            } else if (t == "DR+" || t == "DR-") {
                allowed(t, " C CP ");
                once("DR");
                w.dr = t == "DR+" ? 1 : -1;
            } else if (t.starts_with("IPA")) {
                allowed(t, " CP ");
                once("IPA");
                w.ipa = signedNumber(t, 3);
            } else if (t.starts_with("IZ")) {
                allowed(t, " CP ");
                once("IZ");
                w.iz = signedNumber(t, 2);
            } else if (t.size() > 1 && (t[0] == 'X' || t[0] == 'Y' || t[0] == 'Z')) {
                allowed(t, t[0] == 'Z' ? " L " : " L CC C ");
                once(t.substr(0, 1));
                (t[0] == 'X' ? w.x : t[0] == 'Y' ? w.y : w.z) = signedNumber(t, 1);
            } else if (t.size() > 1 && t[0] == 'F') {
                allowed(t, " L C CP ");
                once("F");
                w.f = decimal(std::string_view(t).substr(1), false);
                if (!w.f || !(*w.f > 0)) refuse("'" + t + "' is not a feed rate");
            } else if (t.size() > 1 && t[0] == 'M') {
                const auto n = whole(std::string_view(t).substr(1));
                if (!n) refuse("'" + t + "' is not understood");
                w.m.push_back(*n);
            } else {
                refuse("'" + t + "' is not understood");
            }
        }
        return w;
    }

    // M3 M4 M5 M8 M9 and M30 anywhere; M91 and M99 on L blocks only.
    void mFunctions(const Words& w, bool onL)
    {
        for (const int mf : w.m) {
            if (mf == 30) ended_ = true;
            else if ((mf == 91 || mf == 99) && onL) continue;
            else if (mf != 3 && mf != 4 && mf != 5 && mf != 8 && mf != 9) refuse("M" + std::to_string(mf) + " is not understood here");
        }
    }

    void toolCall(const std::vector<std::string>& t)
    {
        std::size_t i = 0;
        if (i < t.size() && whole(t[i])) {
            m_.tool = *whole(t[i]);
            if (m_.tool == 0) refuse("TOOL CALL 0");
            ++i;
        } else if (m_.tool == 0) {
            refuse("a TOOL CALL with no tool number and no tool in the spindle");
        }
        if (i >= t.size() || t[i] != "Z") refuse("TOOL CALL needs the tool axis Z");
        ++i;
        if (i < t.size() && t[i].starts_with("S") && decimal(std::string_view(t[i]).substr(1), false)) {
            rpm_ = *decimal(std::string_view(t[i]).substr(1), false);
            ++i;
        }
        if (i != t.size()) refuse("'" + t[i] + "' is not understood in TOOL CALL");
    }

    // Cycles 200 (drilling), 201 (reaming), 202 (boring) and 207 (rigid
    // tapping), their Q parameters in the order the TNC writes them. Dwells,
    // a lift off the wall (Q214) and left-hand tapping are refused.
    void holeCycle(const Block& b, int number)
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

    void move(const std::string& kind, const Words& w)
    {
        if (kind == "CC") {
            if (!w.x || !w.y) refuse("CC needs X and Y");
            pole_ = Point2{*w.x, *w.y};
            return;
        }
        const bool machine = std::find(w.m.begin(), w.m.end(), 91) != w.m.end();
        const bool call = std::find(w.m.begin(), w.m.end(), 99) != w.m.end();
        mFunctions(w, kind == "L");
        if (ended_) refuse("M30 on a move");
        if (w.f) m_.feed = *w.f;
        if (kind == "L") {
            if (!w.x && !w.y && !w.z) refuse("L with no coordinate");
            if (w.fmax && !w.r0) refuse("FMAX without R0");
            if (machine) {
                // The machine datum (M91): a retract, no move in the program.
                if (call || !w.fmax) refuse("M91 is understood only on a rapid with no cycle call");
                return;
            }
            Point3 to = m_.at;
            if (w.x) to.x = *w.x;
            if (w.y) to.y = *w.y;
            if (w.z) to.z = *w.z;
            if (w.fmax) m_.traverse(to);
            else m_.feedTo(to, m_.feed);
            if (call) cycleCall();
            return;
        }
        if (!pole_) refuse(kind + " with no CC before it");
        if (w.dr == 0) refuse(kind + " needs DR+ or DR-");
        if (!known(m_.at)) refuse("an arc from an unknown position");
        const Point2 c = *pole_;
        if (kind == "C") {
            const Point3 to{w.x ? *w.x : m_.at.x, w.y ? *w.y : m_.at.y, m_.at.z};
            m_.arc(to, c, w.dr, m_.feed);
            return;
        }
        // CP: the start turned by IPA about the pole, Z by IZ.
        if (!w.ipa || *w.ipa == 0.0) refuse("CP needs IPA");
        if ((*w.ipa > 0) != (w.dr > 0)) refuse("IPA and DR turn opposite ways");
        const double ipa = *w.ipa;
        const double a = ipa * std::numbers::pi / 180.0;
        const double turns = std::abs(ipa) / 360.0;
        const bool wholeTurns = std::abs(turns - std::round(turns)) < 1e-12;
        const double dx = m_.at.x - c.x, dy = m_.at.y - c.y;
        const Point3 to{wholeTurns ? m_.at.x : c.x + dx * std::cos(a) - dy * std::sin(a),
                        wholeTurns ? m_.at.y : c.y + dx * std::sin(a) + dy * std::cos(a), m_.at.z + (w.iz ? *w.iz : 0.0)};
        // rs274's turn count: ±1 up to one whole turn, one more per turn beyond.
        const int rotation = w.dr * std::max(1, static_cast<int>(std::ceil(turns - 1e-9)));
        m_.arc(to, c, rotation, m_.feed);
    }

    // The cycle in force at the position just reached: to the set-up
    // clearance (Q203 + Q200) in rapid, then
    // - 200: plunges of Q202 from the surface at Q206, each but the last
    //   back up to the set-up clearance and down again in rapid to
    //   peckReturn() above its bottom, the last one to the depth (Q202 at
    //   least |Q201|: one plunge);
    // - 201: to the depth at Q206, out to the set-up clearance at Q208 (0:
    //   at Q206);
    // - 202: to the depth at Q206, the spindle stopped at Q336, out to the
    //   set-up clearance at Q208 (0: at Q206);
    // - 207: to the depth and out to the set-up clearance at Q239 x S (the
    //   TOOL CALL's speed);
    // then out to the 2nd set-up clearance (Q203 + Q204) in rapid.
    void cycleCall()
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

    Machine m_;
    std::vector<Block> blocks_;
    std::string name_, unit_;
    bool ended_ = false;
    bool dwellDue_ = false;
    bool blankDue_ = false;
    std::optional<Point2> pole_;
    int cycleNumber_ = 0;          // the CYCL DEF 200, 201, 202 or 207 in force
    std::map<int, double> cycle_;  // its Q parameters: Q number -> value
    double rpm_ = 0.0;             // the spindle speed of the last TOOL CALL with S
};

}  // namespace

TapeReading readKlartext(const std::string& text) { return KlartextReader().read(text); }

}  // namespace taiwa::verify
