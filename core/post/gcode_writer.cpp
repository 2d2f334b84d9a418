// The G-code writer: framing, modal suppression, sequence numbers, line
// limits, the moves and arcs, and the line-to-source map (see
// gcode_writer.h). Its drilling cycles are in gcode_writer_cycles.cpp.
#include "post/gcode_writer.h"

#include "post/gcode_writer_axes.h"
#include "post/number_format.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <utility>

namespace taiwa::post {

using namespace detail;

namespace {

constexpr char kAxisLetter[] = {'X', 'Y', 'Z'};

// What a few symbols of tool names and notes become on a tape: the words a
// machinist writes for them, in ASCII (0 when there is none: one '?').
const char* asciiFor(char32_t c)
{
    switch (c) {
    case U'\u00b0': return "DEG";                                    // 95° holder
    case U'\u00d8': case U'\u00f8': case U'\u2300': return "DIA";  // Ø50, ⌀12
    case U'\u00b1': return "+/-";
    case U'\u00d7': return "x";
    case U'\u00b5': case U'\u03bc': return "u";                     // µm
    case U'\u2010': case U'\u2011': case U'\u2012': case U'\u2013': case U'\u2014': case U'\u2212': return "-";
    case U'\u2018': case U'\u2019': case U'\u2032': return "'";
    case U'\u201c': case U'\u201d': case U'\u2033': return "\"";
    default: return nullptr;
    }
}

}  // namespace

std::string commentText(const std::string& text, bool upper)
{
    std::string t;
    t.reserve(text.size());
    const auto put = [&](char c) { t += upper ? static_cast<char>(std::toupper(static_cast<unsigned char>(c))) : c; };
    for (std::size_t i = 0; i < text.size(); ++i) {
        const auto u = static_cast<unsigned char>(text[i]);
        if (u >= 0x80) {
            // One UTF-8 character: its lead byte says how many continuation bytes follow.
            const int more = u >= 0xf0 ? 3 : u >= 0xe0 ? 2 : u >= 0xc0 ? 1 : 0;
            char32_t c = more == 3 ? u & 0x07u : more == 2 ? u & 0x0fu : u & 0x1fu;
            int k = 0;
            for (; k < more && i + 1 < text.size() && (static_cast<unsigned char>(text[i + 1]) & 0xc0) == 0x80; ++k, ++i)
                c = (c << 6) | (static_cast<unsigned char>(text[i + 1]) & 0x3fu);
            const char* ascii = more > 0 && k == more ? asciiFor(c) : nullptr;
            if (!ascii) ascii = "?";
            for (const char* a = ascii; *a; ++a) put(*a);
            continue;
        }
        const char c = text[i];
        put(c == '(' || c == ')' || c == '%' || u < 0x20 || u == 0x7f ? ' ' : c);
    }
    return t;
}

GCodeWriter::GCodeWriter(const Dialect& dialect, LengthUnit units, std::string workOffset)
    : dialect_(dialect), units_(units), workOffset_(std::move(workOffset)),
      decimals_(units == LengthUnit::Inch ? dialect.lengthDecimals.inch : dialect.lengthDecimals.mm),
      feedDecimals_(units == LengthUnit::Inch ? dialect.feedDecimals.inch : dialect.feedDecimals.mm),
      resolution_(std::pow(10.0, -decimals_)), tape_(dialect)
{
}

std::string GCodeWriter::length(double v) const { return formatNumber(v, decimals_, dialect_.decimalPointAlways); }

GCodeWriter::Written GCodeWriter::written(double v) const
{
    Written w;
    w.exact = v;
    w.size = static_cast<std::uint8_t>(formatNumberInto(w.chars.data(), v, decimals_, dialect_.decimalPointAlways, &w.value));
    return w;
}

void GCodeWriter::motionWord(const char* code)
{
    if (motion_ == code) return;
    motion_ = code;
    tape_.word(code);
}

bool GCodeWriter::axisWords(const Point3& to, bool forceXY)
{
    const double v[] = {to.x, to.y, to.z};
    bool any = false;
    for (int a = X; a <= Z; ++a) {
        Written now = written(v[a]);
        if ((forceXY && a != Z) || !axis_[a] || axis_[a]->text() != now.text()) {
            tape_.word(kAxisLetter[a], now.text());
            any = true;
        }
        axis_[a] = now;
    }
    return any;
}

void GCodeWriter::feedWord(double feedRate)
{
    char f[kNumberChars];
    const std::string_view text(f, formatNumberInto(f, feedRate, feedDecimals_, dialect_.decimalPointAlways));
    if (text == feed_) return;
    feed_ = text;
    tape_.word('F', text);
}

void GCodeWriter::requirePosition(const char* what) const
{
    if (!axis_[X] || !axis_[Y] || !axis_[Z] || !pendingLengthOffset_.empty())
        throw std::logic_error(fmt::format("post-processor: {} from an unknown position (the first move after a tool change must be a rapid)", what));
}

void GCodeWriter::forgetModalState()
{
    axis_ = {};
    motion_.clear();
    feed_.clear();
    cycleWords_.clear();
}

void GCodeWriter::cancelCycle()
{
    if (cycleWords_.empty()) return;
    tape_.block(dialect_.cycleCancel);
    cycleWords_.clear();
    motion_.clear();
}

void GCodeWriter::programStart(const ProgramInfo& info)
{
    if (dialect_.percentFraming) tape_.line("%");
    const std::string name = commentText(info.name.empty() ? std::string("TAIWA") : info.name, dialect_.upperCaseComments);
    if (!dialect_.programNumberLine.empty())
        tape_.line(fmt::format(fmt::runtime(dialect_.programNumberLine), fmt::arg("number", info.number), fmt::arg("name", name.substr(0, 40))));
    else
        comment("Program " + info.name);
    comment(fmt::format("Generated by Taiwa {}; machine {}; dialect {}; material {}; units {}", TAIWA_VERSION,
                        info.machine.empty() ? "-" : info.machine, dialect_.name, info.material,
                        units_ == LengthUnit::Inch ? "inch" : "mm"));
    for (const auto& t : info.tools) comment(fmt::format("T{} D{} {}", t.number, length(t.diameter), t.name));
    for (const auto& b : dialect_.preamble)
        tape_.block(fmt::format(fmt::runtime(b), fmt::arg("units", units_ == LengthUnit::Inch ? dialect_.inchWord : dialect_.metricWord),
                          fmt::arg("workOffset", workOffset_)));
}

void GCodeWriter::comment(const std::string& text)
{
    cancelCycle();
    tape_.comment(text);
}

void GCodeWriter::toolChange(int tool)
{
    cancelCycle();
    for (const auto& b : dialect_.retract) tape_.block(b);
    tape_.block(fmt::format(fmt::runtime(dialect_.toolChange), fmt::arg("tool", tool)));
    forgetModalState();
    const std::string offset = fmt::format(fmt::runtime(dialect_.lengthOffset), fmt::arg("tool", tool));
    if (dialect_.lengthOffsetWithZ) pendingLengthOffset_ = offset;
    else tape_.block(offset);
    workOffsetDue_ = true;
}

void GCodeWriter::spindle(SpindleDirection direction, double rpm)
{
    cancelCycle();
    if (direction == SpindleDirection::Off) {
        tape_.block(dialect_.spindleStop);
        return;
    }
    rpm_ = rpm;
    tape_.block(fmt::format("S{} {}", formatInteger(rpm),
                      direction == SpindleDirection::Clockwise ? dialect_.spindleClockwise : dialect_.spindleCounterClockwise));
}

void GCodeWriter::coolant(bool on)
{
    cancelCycle();
    tape_.block(on ? dialect_.coolantOn : dialect_.coolantOff);
}

void GCodeWriter::rapid(const Point3& to)
{
    cancelCycle();
    if (!axis_[X] || !axis_[Y]) {
        // Position unknown (after a tool change): across in XY at the height
        // the retract left, then down in Z with the length offset.
        const Written x = written(to.x), y = written(to.y);
        tape_.beginBlock();
        motionWord("G0");
        if (workOffsetDue_) tape_.word(workOffset_);
        tape_.word('X', x.text());
        tape_.word('Y', y.text());
        tape_.endBlock();
        axis_[X] = x;
        axis_[Y] = y;
        workOffsetDue_ = false;
    }
    // The Z (or XYZ) move: written only when a word changes, or to bring in
    // FANUC's pending length offset ("G43 H1 Z5." with the first move down).
    const BlockTape::Mark mark = tape_.mark();
    const std::string savedMotion = motion_;
    tape_.beginBlock();
    motionWord("G0");
    tape_.word(pendingLengthOffset_);
    if (!axisWords(to, false) && pendingLengthOffset_.empty()) {
        tape_.rollback(mark);  // nothing moves: no block
        motion_ = savedMotion;
        return;
    }
    pendingLengthOffset_.clear();
    tape_.endBlock();
}

void GCodeWriter::feed(const Point3& to, double feedRate)
{
    cancelCycle();
    requirePosition("a feed move");
    const BlockTape::Mark mark = tape_.mark();
    const std::string savedMotion = motion_;
    tape_.beginBlock();
    motionWord("G1");
    if (!axisWords(to, false)) {
        tape_.rollback(mark);  // nothing moves: no block
        motion_ = savedMotion;
        return;
    }
    feedWord(feedRate);
    tape_.endBlock();
}

void GCodeWriter::arc(const Point3& to, Point2 centre, bool clockwise, double feedRate)
{
    cancelCycle();
    requirePosition("an arc");
    // I, J from the start as written, so the controller's centre is ours to half a unit.
    const double i = centre.x - axis_[X]->value, j = centre.y - axis_[Y]->value;
    // An arc whose radius or length is below one unit of the tape is a line:
    // written, its centre would be its start ("I0 J0") or its end its start
    // (a full circle to the controller). Its length is measured from the
    // start the caller meant, so that a full circle stays one.
    // So is an arc whose radius, as the controller reads it from the words
    // written (the start, I and J, the end, each rounded), is under two units
    // at either end: LinuxCNC refuses it as a zero-radius arc below 0.00127
    // mm (seed 4752 of the contour generator: I-0.002 J0.001 to an end
    // 0.0010 mm from the centre); its chord is within that of the arc.
    const Point3 from{axis_[X]->exact, axis_[Y]->exact, axis_[Z]->exact};
    const Move asked{clockwise ? MoveKind::ArcCW : MoveKind::ArcCCW, to, centre};
    const double ri = written(i).value, rj = written(j).value;  // I and J as read
    const double cx = axis_[X]->value + ri, cy = axis_[Y]->value + rj;
    const double readStart = std::hypot(ri, rj), readEnd = std::hypot(written(to.x).value - cx, written(to.y).value - cy);
    if (std::hypot(i, j) < resolution_ || std::min(readStart, readEnd) < 2.0 * resolution_ ||
        std::abs(arcSweep(from, asked)) * std::hypot(from.x - centre.x, from.y - centre.y) < resolution_) {
        feed(to, feedRate);
        return;
    }
    tape_.beginBlock();
    motionWord(clockwise ? "G2" : "G3");
    axisWords(to, true);
    char n[kNumberChars];
    tape_.word('I', {n, formatNumberInto(n, i, decimals_, dialect_.decimalPointAlways)});
    tape_.word('J', {n, formatNumberInto(n, j, decimals_, dialect_.decimalPointAlways)});
    feedWord(feedRate);
    tape_.endBlock();
}

void GCodeWriter::dwell(double seconds)
{
    cancelCycle();
    tape_.block(fmt::format("G4 {}{}", dialect_.dwellWord, formatNumber(seconds, 3, dialect_.decimalPointAlways)));
}

void GCodeWriter::programEnd()
{
    cancelCycle();
    for (const auto& b : dialect_.retract) tape_.block(b);
    tape_.block(dialect_.programEnd);
    if (dialect_.percentFraming) tape_.line("%");
}

}  // namespace taiwa::post
