// The HEIDENHAIN Klartext tape reader behind readTape (tape_reader.h): its
// state and its parts. Its blocks grouped, read word by word and their
// moves made in tape_reader_klartext.cpp; its drilling cycles (CYCL DEF
// 200, 201, 202, 207 and their calls by M99) in
// tape_reader_klartext_cycles.cpp. Internal to core/verify.
#pragma once

#include "verify/tape_reader_machine.h"

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace taiwa::verify::tape {

class KlartextReader {
public:
    TapeReading read(const std::string& text);

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
    void group(const std::vector<std::string>& lines);
    void block(std::size_t k);
    static double signedNumber(const std::string& t, std::size_t skip);
    // The words of an L, CC, C or CP block, or of a bare M block (`kind` "").
    static Words parseWords(const std::string& kind, const std::vector<std::string>& tokens);
    // M3 M4 M5 M8 M9 and M30 anywhere; M91 and M99 on L blocks only.
    void mFunctions(const Words& w, bool onL);
    void toolCall(const std::vector<std::string>& t);
    void move(const std::string& kind, const Words& w);

    // Cycles 200 (drilling), 201 (reaming), 202 (boring) and 207 (rigid
    // tapping), their Q parameters in the order the TNC writes them. Dwells,
    // a lift off the wall (Q214) and left-hand tapping are refused.
    void holeCycle(const Block& b, int number);
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
    void cycleCall();

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

}  // namespace taiwa::verify::tape
