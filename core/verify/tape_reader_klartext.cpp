// The reader of HEIDENHAIN Klartext tapes (readTape's, tape_reader.h;
// tape_reader_klartext.h's KlartextReader): the lines grouped into numbered
// blocks, every block understood word by word and its moves made (L, CC,
// C, CP, TOOL CALL, bare M blocks), or the reading stopped at its line. The
// drilling cycles are in tape_reader_klartext_cycles.cpp.
#include "verify/tape_reader_klartext.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <string_view>

namespace taiwa::verify {

namespace tape {

TapeReading KlartextReader::read(const std::string& text)
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

void KlartextReader::group(const std::vector<std::string>& lines)
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

void KlartextReader::block(std::size_t k)
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

double KlartextReader::signedNumber(const std::string& t, std::size_t skip)
{
    const std::string_view s = std::string_view(t).substr(skip);
    if (s.empty() || (s.front() != '+' && s.front() != '-')) refuse("'" + t + "': a signed number expected");
    const auto v = decimal(s, true);
    if (!v) refuse("'" + t + "' is not understood");
    return *v;
}

KlartextReader::Words KlartextReader::parseWords(const std::string& kind, const std::vector<std::string>& tokens)
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

void KlartextReader::mFunctions(const Words& w, bool onL)
{
    for (const int mf : w.m) {
        if (mf == 30) ended_ = true;
        else if ((mf == 91 || mf == 99) && onL) continue;
        else if (mf != 3 && mf != 4 && mf != 5 && mf != 8 && mf != 9) refuse("M" + std::to_string(mf) + " is not understood here");
    }
}

void KlartextReader::toolCall(const std::vector<std::string>& t)
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

void KlartextReader::move(const std::string& kind, const Words& w)
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

}  // namespace tape

TapeReading readKlartext(const std::string& text) { return tape::KlartextReader().read(text); }

}  // namespace taiwa::verify
