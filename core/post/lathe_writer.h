// The lathe writer at the end of the lathe's sink chain (lathe_sink.h): the
// words a lathe program says in each family of controls (FANUC and Haas by
// the dialect's macroSyntax, LinuxCNC, SINUMERIK by its syntax), from values
// already in the tape's units. It writes X as a diameter, modal words only
// when they change, the controls' roughing and threading cycles, and leaves
// block numbers, line limits and comments to the block tape.
#pragma once

#include "model/job.h"
#include "post/block_tape.h"
#include "post/dialect.h"
#include "post/lathe_sink.h"

#include <optional>
#include <string>
#include <vector>

namespace taiwa::post {

class LatheWriter final : public LatheSink {
public:
    LatheWriter(const Dialect& dialect, LengthUnit units);

    void source(BlockSource where) override { tape_.source(where); }
    void programStart(const LatheProgramInfo& info) override;
    void contourSubroutine(int number, const TurnCycle& cycle) override;
    void comment(const std::string& text) override { tape_.comment(text); }
    void toolChange(int station) override;
    void spindle(const LatheSpindle& speeds) override;
    void spindleStop() override { tape_.block(dialect_.spindleStop); }
    void coolant(bool on) override { tape_.block(on ? dialect_.coolantOn : dialect_.coolantOff); }
    void rapid(turning::ZR to, CompensationWord comp) override;
    void feed(turning::ZR to, double feedPerRev, CompensationWord comp) override;
    void rapidAlong(LatheAxis axis, double value) override;
    void arc(bool clockwise, turning::ZR to, turning::ZR centre, double feedPerRev) override;
    void threadPass(turning::ZR to, double lead) override;
    void roughingCycle(int number, const TurnCycle& cycle, double feedPerRev) override;
    void threadingCycle(const TurnThread& thread) override;
    void programEnd() override;

    std::string takeText() { return tape_.takeText(); }
    std::vector<BlockSource> takeSources() { return tape_.takeSources(); }

private:
    enum class Family { Fanuc, LinuxCnc, Siemens };

    std::string num(double v) const;
    std::string x(double r) const { return "X" + num(2.0 * r); }  // a diameter
    std::string z(double zz) const { return "Z" + num(zz); }
    std::string feedWord(double perRev) const { return "F" + num(perRev); }
    // A move block: only the words that change (all of them with a
    // compensation word or an arc's).
    void move(const char* g, turning::ZR to, std::optional<double> feed, CompensationWord comp = CompensationWord::None,
              const std::string& arcWords = {});
    void forget();
    // The roughing contour as blocks (no numbers): onto its first point
    // (with Z too for a LinuxCNC subroutine, X alone for FANUC's type I P
    // block), then each element.
    std::vector<std::string> contourBlocks(const TurnCycle& c, bool withZ) const;

    const Dialect& dialect_;
    Family family_;
    bool inch_;
    int decimals_;
    BlockTape tape_;
    std::string motion_, xw_, zw_, fw_, spindle_;
    turning::ZR at_{};
};

}  // namespace taiwa::post
