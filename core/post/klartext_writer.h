// The HEIDENHAIN Klartext writer at the end of the sink chain: the
// conversational language of the TNC controls, not G-code. Every block is
// numbered from 0 (BEGIN PGM) on, comments included; a cycle definition is
// one block over several lines, joined by '~'. Straight moves are L blocks
// (FMAX for rapids), arcs a CC pole then C (or CP for a helix or a full
// circle) with DR- clockwise, drilling CYCL DEF 200 called by M99 at each
// hole, the tool TOOL CALL n Z S. M functions ride on the next move.
// The dialect's data gives decimals, the machine-datum retract and the M
// codes; docs/post-processors.md cites the manual for each construct.
#pragma once

#include "model/job.h"
#include "post/dialect.h"
#include "post/machine_sink.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace taiwa::post {

// The program name of BEGIN PGM / END PGM, the file's (the control matches
// them): letters, digits, '_' and '-' of `name` (others become '_'), at
// most 32 characters; "TAIWA" when empty.
std::string klartextProgramName(const std::string& name);

class KlartextWriter final : public MachineSink {
public:
    // preset: the datum (preset table row) selected by cycle 247; 0: none.
    KlartextWriter(const Dialect& dialect, LengthUnit units, int preset);

    void source(BlockSource where) override { source_ = where; }
    void programStart(const ProgramInfo& info) override;
    void comment(const std::string& text) override;
    void toolChange(int tool) override;
    void spindle(SpindleDirection direction, double rpm) override;
    // M8 / M9 wait for the next block (Klartext writes M functions after its words).
    void coolant(bool on) override { mFunctions_.push_back(on ? dialect_.coolantOn : dialect_.coolantOff); }
    void rapid(const Point3& to) override;
    void feed(const Point3& to, double feedRate) override;
    void arc(const Point3& to, Point2 centre, bool clockwise, double feedRate) override;
    void drillCycle(const DrillCycle& cycle) override;
    void holeCycle(const DrillCycle& cycle, double rtp);  // tapping, reaming, boring
    void dwell(double seconds) override;
    void programEnd() override;

    std::string takeText() { return std::move(text_); }
    std::vector<BlockSource> takeSources() { return std::move(sources_); }

private:
    std::string number(double v) const;  // "+10.5", "-3", "+0"
    double asRead(double v) const;       // the value the control reads from number(v)
    void block(const std::string& words);
    void continuation(const std::string& text);  // an unnumbered line of the block before
    // An L block to `to` (only the coordinates whose written value
    // changes); false when nothing would move.
    bool line(const Point3& to, bool rapid, double feedRate);
    std::string feedWords(double feedRate);
    std::string takeMFunctions();  // " M3 M8" waiting for the next block, or ""
    void flushMFunctions();        // as a block of their own
    void toolCallDue(const std::string& speed = {});  // the tool call (with " S..." if given), when one waits
    void requirePosition(const char* what) const;

    const Dialect& dialect_;
    LengthUnit units_;
    int preset_;
    int decimals_, feedDecimals_;
    double resolution_;
    int sequence_ = 0;
    std::string programName_;
    BlockSource source_;
    std::string text_;
    std::vector<BlockSource> sources_;

    std::array<std::optional<double>, 3> axis_;  // X, Y, Z as written; empty while unknown
    std::array<double, 3> exact_{};              // ... as asked
    std::string feed_;                           // last F number ("" after a tool call)
    std::optional<Point2> pole_;                 // the CC in force
    std::string cycle_;                          // the CYCL DEF 200 in force (its Q lines)
    std::vector<std::string> mFunctions_;        // waiting for the next block
    int toolDue_ = 0;                            // a tool change whose TOOL CALL is not written yet
};

}  // namespace taiwa::post
