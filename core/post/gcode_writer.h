// The G-code writer at the end of the post-processor chain: it owns every
// number's formatting (fixed decimals per unit, trailing zeros trimmed, no
// "-0", NaN refused), emits modal words only when they change, numbers the
// blocks, converts mm to inch at the edge, and records where each line came
// from.
#pragma once

#include "model/job.h"
#include "model/toolpath.h"
#include "post/dialect.h"
#include "post/post.h"

#include <optional>
#include <string>
#include <vector>

namespace taiwa::post {

// "12.5", "-0.001", "10" (or "10." with a decimal point always); throws
// std::invalid_argument for NaN or infinity.
std::string formatNumber(double value, int decimals, bool decimalPointAlways);

class GCodeWriter {
public:
    GCodeWriter(const Dialect& dialect, LengthUnit units);

    void setSource(BlockSource source) { source_ = source; }
    // A raw block (sequence number added); words already formatted.
    void block(const std::string& words);
    void comment(const std::string& text);
    void line(const std::string& text);  // unnumbered line ('%', O-number)

    // Motion in mm (core units); feeds in mm/min.
    void rapid(const Point3& to);
    void feed(const Point3& to, double feedRate);
    void arc(bool clockwise, const Point3& to, Point2 centre, double feedRate);
    void drill(const Move& cycle, double feedRate);
    void cancelCycle();

    // Forget modal position, motion and feed (after a tool change).
    void forgetPosition();
    void setPosition(const Point3& p) { pos_ = p; }

    std::string length(double mm) const;   // one length word's number, in output units
    std::string feedValue(double mmPerMin) const;
    const std::string& text() const { return text_; }
    const std::vector<BlockSource>& sources() const { return sources_; }

private:
    std::string axes(const Point3& to, bool forceXY);
    std::string feedWord(double feedRate);

    const Dialect& dialect_;
    LengthUnit units_;
    int decimals_;
    int sequence_ = 0;
    BlockSource source_;
    std::string text_;
    std::vector<BlockSource> sources_;
    std::optional<Point3> pos_;
    std::string motion_;  // current modal motion code
    std::optional<double> feed_;
    bool inCycle_ = false;
};

}  // namespace taiwa::post
