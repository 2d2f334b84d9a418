// The G-code writer at the end of the sink chain (ISO G-code, and Siemens'
// where its comments and drilling cycles differ). It receives lengths and
// feeds already in the tape's units, owns every number's formatting (through
// number_format), writes modal words only when they change (motion code,
// each axis, feed, a canned cycle's Z R Q), numbers the blocks, keeps lines
// within the dialect's limit, and records where each line came from.
#pragma once

#include "model/job.h"
#include "post/block_tape.h"
#include "post/dialect.h"
#include "post/number_format.h"
#include "post/machine_sink.h"

#include <array>
#include <optional>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace taiwa::post {

// The text of a comment as both controllers take it: printable ASCII only;
// parentheses (neither controller allows nested comments), '%' (it ends a
// FANUC tape, even inside a comment) and control characters become spaces;
// of the non-ASCII (UTF-8) characters, '°' becomes DEG, 'Ø' (and '⌀') DIA,
// '±' +/-, '×' x, 'µ' u, dashes '-', curly quotes straight ones, and any
// other one '?'.
std::string commentText(const std::string& text, bool upper);

class GCodeWriter final : public MachineSink {
public:
    // workOffset: the words selecting the work offset, as workOffsetWords gives them.
    GCodeWriter(const Dialect& dialect, LengthUnit units, std::string workOffset = "G54");

    void source(BlockSource where) override { tape_.source(where); }
    void programStart(const ProgramInfo& info) override;
    void comment(const std::string& text) override;
    void toolChange(int tool) override;
    void spindle(SpindleDirection direction, double rpm) override;
    void coolant(bool on) override;
    void rapid(const Point3& to) override;
    void feed(const Point3& to, double feedRate) override;
    void arc(const Point3& to, Point2 centre, bool clockwise, double feedRate) override;
    void drillCycle(const DrillCycle& cycle) override;
    void dwell(double seconds) override;
    void programEnd() override;

    const std::string& text() const { return tape_.text(); }
    const std::vector<BlockSource>& sources() const { return tape_.sources(); }
    // Room for a program of about this many blocks (one growing tape copied
    // over and over cost a tenth of the time).
    void reserve(std::size_t blocks) { tape_.reserve(blocks); }
    // The tape and its sources, moved out (the writer is done).
    std::string takeText() { return tape_.takeText(); }
    std::vector<BlockSource> takeSources() { return tape_.takeSources(); }

private:
    // The number of an axis word as written (in place: no allocation on the
    // writer's hot path), the value the controller reads from it, and the
    // value the caller asked for.
    struct Written {
        std::array<char, kNumberChars> chars{};
        std::uint8_t size = 0;
        double value = 0.0;
        double exact = 0.0;
        std::string_view text() const { return {chars.data(), size}; }
    };

    std::string length(double v) const;
    Written written(double v) const;
    void motionWord(const char* code);             // the motion code when the modal motion changes
    // The X, Y, Z words whose written number changes (X, Y always when
    // forced), with the axes' state updated; whether any was written.
    bool axisWords(const Point3& to, bool forceXY);
    void feedWord(double feedRate);
    void requirePosition(const char* what) const;
    void cancelCycle();
    void sinumerikDrillCycle(const DrillCycle& cycle);
    void synchronisedTap(const DrillCycle& cycle);  // LinuxCNC's G33.1: explicit moves
    void forgetModalState();

    const Dialect& dialect_;
    LengthUnit units_;
    std::string workOffset_;
    int decimals_;
    int feedDecimals_;
    double resolution_;  // one unit of the last decimal of a length: 0.001 mm, 0.0001 in
    BlockTape tape_;  // block numbers, line limit, comments, line sources

    // Modal state as the controller sees it.
    std::array<std::optional<Written>, 3> axis_;  // X, Y, Z; empty while unknown
    std::string motion_;                           // G0, G1, G2, G3, G81, G83 or empty
    std::string feed_;                             // last F number
    std::string cycleWords_;                       // " Z.. R.. Q.." of the active cycle
    std::string pendingLengthOffset_;              // "G43 H1" waiting for the first Z move (FANUC)
    bool workOffsetDue_ = false;                   // restate the work offset with the next XY move
    double rpm_ = 0.0;                             // the spindle speed last set (tapping cycles state it)
};

}  // namespace taiwa::post
