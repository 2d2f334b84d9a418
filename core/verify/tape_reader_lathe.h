// The reader of the lathe tapes Taiwa writes (readLatheTape, tape_reader.h),
// as strict as the milling reader: a word, block or construct it does not
// understand stops the reading at its line. Its lines split into words in
// tape_reader_lathe.cpp, each block acted on there, the controls' cycles
// (G71 roughing, G76 threading) read into TapeCycle in
// tape_reader_lathe_cycles.cpp. Internal to core/verify. What it accepts:
// - ISO (FANUC and Haas by the dialect's macroSyntax "fanuc", else
//   LinuxCNC): '%' framing, the "O1000 (NAME)" line and N numbers as the
//   dialect writes them, comments in parentheses, G18, G7 (LinuxCNC's
//   diameter mode, required before an X word there; FANUC and Haas take X
//   as a diameter by their setting), G20/G21, G40/G41/G42 (the programmed
//   point is judged), G80, G90, G95 (LinuxCNC) or G99 (FANUC, Haas) feed
//   per revolution (required before a feed), the work offsets as the
//   milling reader takes them, G0 G1 X Z F, G2 G3 X Z I K (I on the radius,
//   from the start), G33 X Z K, G96 S with the limit in G50 S (FANUC, Haas)
//   or in D (LinuxCNC), G97 S, T M6 [G43] (LinuxCNC), T0101 (FANUC, Haas:
//   the station and its offset, the change made by the T word), M3 M4 M5
//   M8 M9 M30 (any other M but a subprogram's a switch), LinuxCNC's
//   "o<n> sub" .. "o<n> endsub" contour definitions, and the cycles: G71
//   roughing (LinuxCNC: "G71 Q<n> X Z D I R F" calling the o<n> contour;
//   FANUC: "G71 U R" then "G71 P Q U W F"; Haas: "G71 P Q U W D F"; the
//   contour blocks P..Q after it read as the contour, not run), G76
//   threading (LinuxCNC: "G76 P Z I J [R] K [Q] [H]"; FANUC: "G76 P(m)(r)(a)
//   Q R" then "G76 X Z P Q F"; Haas: "G76 X Z K D F A P1").
// - SINUMERIK: ';' comments, N numbers, G18 DIAMON (required before an X
//   word), G700/G710, G40 G41 G42, G90, G95, the work offsets, G0 G1 X Z
//   F, G2 G3 X Z CR= (negative: more than a half turn), G33 X Z K, G96 S
//   LIMS=, G97 S, T D1, M3 M4 M5 M8 M9 M30.
// A two-path lathe's program (post/two_path_post.h, read with the control's
// wait codes; tape_reader_lathe_sync.cpp) may also have its waits and
// dwells: FANUC and Haas a wait M code of the range, "G04 X<seconds>";
// LinuxCNC "M64 P0" or "M65 P0", "M66 P0 L3|L4 Q<seconds>", then the
// time-out's "o<n> if [#5399 LT 0]" whose branch holds M2 alone (not run:
// it stops the program) and "o<n> endif", and "G4 P<seconds>".
// A cycle is not expanded into its passes: it is one Cycle motion whose
// words are read (TapeCycle) with the box its motions stay within: G71
// between its start and its contour, grown by the allowance and the lift
// after a pass; G76 between the drive point and the thread's root and end,
// grown along Z by the thread's depth (the compound infeed's shift).
#pragma once

#include "verify/tape_reader_machine.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace taiwa::verify::tape {

class LatheReader {
public:
    // `twoPath`: a two-path lathe's program, its control's wait codes.
    explicit LatheReader(const post::Dialect& d, const WaitCodeRange* twoPath = nullptr);

    TapeReading read(const std::string& text);

    struct Block {
        int n = -1;                   // the N number, -1 without
        std::vector<int> g, m;        // G in tenths (G54.1: 541), M whole
        std::map<char, double> v;     // the address words
        std::map<char, bool> point;   // whether the number had a decimal point
        std::optional<double> cr, lims;  // SINUMERIK's CR= and LIMS=
        bool diamon = false;          // SINUMERIK's DIAMON
        bool has(char c) const { return v.count(c) != 0; }
    };

private:
    enum class Family { Fanuc, LinuxCnc, Siemens };
    enum class Mode { None, Rapid, Feed, Clockwise, CounterClockwise, Thread };

    Block words(const std::string& s);
    void line(const std::string& raw);
    void block(const Block& b);
    // The block's G codes: the modal ones taken, the motion's returned; 71
    // or 76 for a cycle, 50 for FANUC's spindle limit.
    std::optional<Mode> gCodes(const Block& b, int& cycle, bool& limit);
    void otherWords(const Block& b);
    void move(const Block& b);

    // A two-path program's (tape_reader_lathe_sync.cpp): a wait or a dwell
    // acted on (true when the block was no more), the time-out's lines.
    bool sync(const Block& b);
    bool timeout(const std::string& s, const std::vector<std::string>& tokens);

    // The cycles (tape_reader_lathe_cycles.cpp).
    TapeCycle cycleHere(TapeCycle::Kind kind, const char* word) const;
    void roughing(const Block& b);
    void threading(const Block& b);
    // The contour of a G71 from its start through `blocks`, into `c`.
    void contour(TapeCycle& c, const std::vector<Block>& blocks) const;
    // The cycle read: its box, recorded as a motion.
    void runCycle(TapeCycle c);
    double increments(double v) const { return v / (m_.out.inches ? 10000.0 : 1000.0); }

    Family family_;
    bool oneBlock_;        // Haas: G71 and G76 in one block
    bool numbered_, points_;
    Machine m_;
    Mode mode_ = Mode::None;
    bool programNumber_ = false;
    bool plane_ = false;       // G18 stated
    bool diameter_ = false;    // G7 / DIAMON (FANUC, Haas: always)
    bool perRevolution_ = false;
    int selected_ = 0;
    // LinuxCNC's o<n> sub bodies, by number: their blocks (not run).
    std::map<int, std::vector<Block>> subs_;
    int inSub_ = -1;
    // FANUC's first G71 / G76 block, waiting for its second.
    std::optional<Block> firstRoughing_, firstThreading_;
    // A FANUC or Haas G71 whose contour blocks P..Q follow: the cycle and
    // the blocks so far.
    std::optional<TapeCycle> pending_;
    int pendingFrom_ = 0, pendingTo_ = 0, pendingLine_ = 0;
    std::vector<Block> pendingBlocks_;
    // A two-path program's: the wait codes, LinuxCNC's output 0 (-1: not
    // set yet), the time-out's if open (-1: none), an M66 just read.
    std::optional<WaitCodeRange> waits_;
    int output_ = -1, inTimeout_ = -1;
    bool afterWait_ = false;
};

}  // namespace taiwa::verify::tape
