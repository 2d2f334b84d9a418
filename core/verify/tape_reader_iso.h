// The ISO and SINUMERIK tape reader behind readTape (tape_reader.h): its
// state and its parts. Its lines split into words and checked in
// tape_reader.cpp; each block's words acted on (the modal state, the
// moves, the drilling cycles) in tape_reader_iso_block.cpp. Internal to
// core/verify.
#pragma once

#include "verify/tape_reader_cycles.h"
#include "verify/tape_reader_machine.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace taiwa::verify::tape {

class IsoReader {
public:
    explicit IsoReader(const post::Dialect& d);

    TapeReading read(const std::string& text);

private:
    // Drill..Bore: the canned cycles G81, G83, G84, G85, G86 (ISO);
    // Synchronised: LinuxCNC's G33.1.
    enum class Mode { None, Rapid, Feed, Clockwise, CounterClockwise, Synchronised, Drill, Peck, Tap, Ream, Bore };

    struct Block {
        std::vector<int> g, m;        // G in tenths (G59.1: 591), M whole
        std::map<char, double> v;     // X Y Z I J K R F P Q S T H D
        std::map<char, bool> point;   // whether the number had a decimal point
        bool supa = false;
        bool mcall = false;
        std::string cycle;            // "CYCLE81(...)"
        std::optional<double> adis;
        bool has(char c) const { return v.count(c) != 0; }
    };

    Block words(const std::vector<std::string>& tokens);
    void line(const std::string& raw);

    // One block's words acted on: the modal state, the machine retracts, the
    // move or the cycle.
    // What a block's words do (tape_reader_iso_block.cpp): its G codes,
    // its other words, then its move.
    struct GCodes {
        std::optional<Mode> motion;
        bool g4 = false, g28 = false, g43 = false, g53 = false, g80 = false, indexed = false, g64 = false, g641 = false;
    };
    GCodes gCodes(const Block& b);
    void words(const Block& b, const GCodes& c);
    void block(const Block& b);
    // LinuxCNC's G33.1 Z K at the hole the tool is over: down to Z at K x S
    // and back up to where it began at the same rate (the spindle reversed
    // at the bottom).
    void synchronisedTap(const Block& b, const Point3& to);
    // G98 G81/G83/G84/G85/G86 at `hole`: the block's Z, R and Q kept for
    // the next holes, the moves made by runCannedCycle (tape_reader_cycles.cpp).
    void drill(const Block& b, const Point3& hole);

    bool sinumerik_;
    bool numbered_;        // an "O1000" program number line
    bool points_;          // lengths and feeds must carry a decimal point
    bool offsetNeeded_;    // a Z move after M6 waits for the length offset
    char dwellWord_;       // G4's time: P, X (FANUC) or F (SINUMERIK)
    bool tapSynchronised_; // tapping is G33.1 (LinuxCNC), not G84
    double rpm_ = 0.0;     // the last S
    Machine m_;
    Mode mode_ = Mode::None;
    bool incremental_ = false;
    bool g98_ = false;
    bool lengthOffset_ = true;  // false from a tool change to its G43 H / D
    bool dInForce_ = false;     // SINUMERIK: a D (1 or more) in force, no D0 since
    bool programNumber_ = false;
    int selected_ = 0;
    std::optional<double> cycleZ_, cycleR_, cycleQ_;
    std::optional<SinumerikCycle> mcall_;
};

}  // namespace taiwa::verify::tape
