// The G-code writer: number formatting, modal suppression, sequence numbers,
// unit conversion at the output edge, and the line-to-source map.
#include "post/gcode_writer.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>

namespace taiwa::post {

std::string formatNumber(double value, int decimals, bool decimalPointAlways)
{
    if (!std::isfinite(value)) throw std::invalid_argument("post-processor: a coordinate or feed is not a finite number");
    std::string s = fmt::format("{:.{}f}", value, decimals);
    if (s.find('.') != std::string::npos) {
        while (s.back() == '0') s.pop_back();
        if (s.back() == '.' && !decimalPointAlways) s.pop_back();
    }
    if (s == "-0" || s == "-0.") s.erase(0, 1);
    if (s == "-." || s == ".") s = decimalPointAlways ? "0." : "0";
    return s;
}

GCodeWriter::GCodeWriter(const Dialect& dialect, LengthUnit units)
    : dialect_(dialect), units_(units), decimals_(units == LengthUnit::Inch ? 4 : 3)
{
}

std::string GCodeWriter::length(double mm) const
{
    return formatNumber(fromMm(mm, units_), decimals_, dialect_.decimalPointAlways);
}

std::string GCodeWriter::feedValue(double mmPerMin) const
{
    // Feeds: one decimal in mm/min, two in in/min; a whole feed has no point needed.
    return formatNumber(fromMm(mmPerMin, units_), units_ == LengthUnit::Inch ? 2 : 1, dialect_.decimalPointAlways);
}

void GCodeWriter::line(const std::string& text)
{
    text_ += text;
    text_ += '\n';
    sources_.push_back(source_);
}

void GCodeWriter::block(const std::string& words)
{
    if (dialect_.sequenceNumbers) {
        sequence_ += dialect_.sequenceIncrement;
        line(fmt::format("N{} {}", sequence_, words));
    } else {
        line(words);
    }
}

void GCodeWriter::comment(const std::string& text)
{
    std::string t;
    for (char c : text) {
        if (c == '(' || c == ')') c = ' ';
        if (c == '\n' || c == '\r') c = ' ';
        t += dialect_.upperCaseComments ? static_cast<char>(std::toupper(static_cast<unsigned char>(c))) : c;
    }
    line("(" + t + ")");
}

void GCodeWriter::forgetPosition()
{
    pos_.reset();
    motion_.clear();
    feed_.reset();  // a new tool states its feed again
}

std::string GCodeWriter::axes(const Point3& to, bool forceXY)
{
    std::string w;
    const auto word = [&](char axis, double v, std::optional<double> was, bool force) {
        const std::string now = length(v);
        if (force || !was || length(*was) != now) w += fmt::format(" {}{}", axis, now);
    };
    word('X', to.x, pos_ ? std::optional(pos_->x) : std::nullopt, forceXY);
    word('Y', to.y, pos_ ? std::optional(pos_->y) : std::nullopt, forceXY);
    word('Z', to.z, pos_ ? std::optional(pos_->z) : std::nullopt, false);
    return w;
}

std::string GCodeWriter::feedWord(double feedRate)
{
    const std::string f = feedValue(feedRate);
    if (feed_ && feedValue(*feed_) == f) return "";
    feed_ = feedRate;
    return " F" + f;
}

void GCodeWriter::rapid(const Point3& to)
{
    cancelCycle();
    const std::string w = axes(to, false);
    if (!w.empty()) {
        block(motion_ == "G0" ? w.substr(1) : "G0" + w);
        motion_ = "G0";
    }
    pos_ = to;
}

void GCodeWriter::feed(const Point3& to, double feedRate)
{
    cancelCycle();
    const std::string w = axes(to, false);
    if (!w.empty()) {
        const std::string f = feedWord(feedRate);
        block(motion_ == "G1" ? (w + f).substr(1) : "G1" + w + f);
        motion_ = "G1";
    }
    pos_ = to;
}

void GCodeWriter::arc(bool clockwise, const Point3& to, Point2 centre, double feedRate)
{
    cancelCycle();
    if (!pos_) throw std::invalid_argument("post-processor: an arc without a known start point");
    const std::string code = clockwise ? "G2" : "G3";
    std::string w = code + axes(to, true);
    w += fmt::format(" I{} J{}", length(centre.x - pos_->x), length(centre.y - pos_->y));
    w += feedWord(feedRate);
    block(w);
    motion_ = code;
    pos_ = to;
}

void GCodeWriter::drill(const Move& cycle, double feedRate)
{
    if (!pos_) throw std::invalid_argument("post-processor: a drilling cycle without a known start height");
    std::string w = dialect_.cycleRetractMode.empty() ? std::string() : dialect_.cycleRetractMode + " ";
    w += cycle.peck > 0 ? "G83" : "G81";
    w += fmt::format(" X{} Y{} Z{} R{}", length(cycle.end.x), length(cycle.end.y), length(cycle.end.z), length(cycle.retractZ));
    if (cycle.peck > 0) w += " Q" + length(cycle.peck);
    feed_.reset();
    w += feedWord(feedRate);
    block(w);
    inCycle_ = true;
    motion_ = "cycle";
    // G98: the tool returns to the initial level above the hole.
    pos_ = Point3{cycle.end.x, cycle.end.y, pos_->z};
}

void GCodeWriter::cancelCycle()
{
    if (!inCycle_) return;
    block("G80");
    inCycle_ = false;
    motion_.clear();
}

}  // namespace taiwa::post
