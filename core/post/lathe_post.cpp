// The lathe post-processor (lathe_post.h). The dialect's data gives the
// framing, block numbers, number style, comments, coolant and program end;
// what a lathe says differently in each family (FANUC or LinuxCNC: the
// dialect's macroSyntax; Siemens: its syntax) is in one small table, as for
// the probing cycle.
#include "post/lathe_post.h"

#include "post/dialect.h"
#include "post/gcode_writer.h"
#include "post/number_format.h"
#include "post/tape_image.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace taiwa {

namespace {

using turning::ZR;

// FANUC's G76 Q: the smallest cut a pass of the cycle takes (radius) [mm].
constexpr double kThreadMinCut = 0.05;

// What the two families of controls write differently on a lathe.
struct LatheWords {
    bool fanuc = false;
    bool siemens = false;    // SINUMERIK: T n D1, G96 S LIMS=, arcs by CR=, no G71 (explicit passes)
    const char* plane;       // preamble: plane, diameter mode, feed per revolution
    const char* feedPerRev;
};

LatheWords latheWords(const post::Dialect& d)
{
    if (d.syntax == post::Syntax::Sinumerik) return {false, true, "G18 DIAMON", "G95"};
    if (d.macroSyntax == "fanuc") return {true, false, "G18", "G99"};
    return {false, false, "G18 G7", "G95"};
}

std::string upper(std::string s)
{
    for (auto& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

class LatheWriter {
public:
    LatheWriter(const post::Dialect& d, const PostOptions& o)
        : d_(d), w_(latheWords(d)), inch_(o.units == LengthUnit::Inch)
    {
        decimals_ = inch_ ? d.lengthDecimals.inch : d.lengthDecimals.mm;
    }

    void source(BlockSource s) { source_ = s; }

    // ---- words -------------------------------------------------------------

    double units(double mm) const { return inch_ ? mm / 25.4 : mm; }
    std::string num(double mm) const { return post::formatNumber(units(mm), decimals_, d_.decimalPointAlways); }
    std::string x(double r) const { return "X" + num(2.0 * r); }  // a diameter
    std::string z(double zz) const { return "Z" + num(zz); }
    std::string feedWord(double mmPerRev) const { return "F" + post::formatNumber(units(mmPerRev), decimals_, d_.decimalPointAlways); }

    // ---- lines and blocks -------------------------------------------------

    void line(const std::string& text)
    {
        nc_ += text;
        nc_ += '\n';
        lines_.push_back(source_);
    }

    // The sequence number the k-th block from now gets (k = 1: the next).
    int sequenceAhead(int k) const
    {
        int s = sequence_;
        for (int i = 0; i < k; ++i)
            s = s == 0 || s + d_.sequenceIncrement > d_.sequenceMax ? d_.sequenceStart : s + d_.sequenceIncrement;
        return s;
    }

    void block(const std::string& words)
    {
        std::string b;
        if (d_.sequenceNumbers) {
            sequence_ = sequenceAhead(1);
            b = fmt::format("N{} ", sequence_);
        }
        b += words;
        if (b.size() > d_.maxLineLength)
            throw std::length_error(fmt::format("post-processor: block longer than {} characters: {}", d_.maxLineLength, b));
        line(b);
    }

    void comment(const std::string& text)
    {
        if (d_.semicolonComments) {
            std::string c = "; " + post::commentText(text, d_.upperCaseComments);
            if (c.size() > d_.maxLineLength) c.resize(d_.maxLineLength);
            line(c);
            return;
        }
        std::string c = "(" + post::commentText(text, d_.upperCaseComments);
        if (c.size() + 1 > d_.maxLineLength) c.resize(d_.maxLineLength - 1);
        line(c + ")");
    }

    // ---- motion with modal words -------------------------------------------

    void forget()
    {
        motion_.clear();
        xw_.clear();
        zw_.clear();
        fw_.clear();
    }

    // A move block: only the words that change (prefix: G41/G42/G40 words).
    void move(const char* g, ZR to, std::optional<double> feed = std::nullopt, const std::string& prefix = {},
              const std::string& arcWords = {})
    {
        std::string words = prefix;
        auto add = [&](const std::string& w) {
            if (!words.empty()) words += ' ';
            words += w;
        };
        const bool arc = !arcWords.empty();
        if (motion_ != g || arc || !prefix.empty()) add(g);
        motion_ = g;
        const std::string xs = x(to.r), zs = z(to.z);
        if (xs != xw_ || arc || !prefix.empty()) add(xs);
        if (zs != zw_ || arc || !prefix.empty()) add(zs);
        xw_ = xs;
        zw_ = zs;
        if (arc) add(arcWords);
        if (feed) {
            const std::string f = feedWord(*feed);
            if (f != fw_) add(f);
            fw_ = f;
        }
        if (words.empty()) return;  // already there
        block(words);
        at_ = to;
    }

    void rapid(ZR to) { move("G0", to); }
    void linear(ZR to, double feed, const std::string& prefix = {}) { move("G1", to, feed, prefix); }
    void arc(bool cw, ZR to, ZR centre, double feed)
    {
        if (w_.siemens) {
            // The radius, negative for more than a half turn: CR= is a radius
            // on every control, where I under DIAMON is not said the same way.
            const double az = at_.z - centre.z, ar = at_.r - centre.r, bz = to.z - centre.z, br = to.r - centre.r;
            double sweep = std::atan2(az * br - ar * bz, az * bz + ar * br);  // counter-clockwise, Z right and X up
            if (cw) sweep = -sweep;
            if (sweep <= 0) sweep += 2 * std::numbers::pi;
            const double radius = std::hypot(az, ar);
            move(cw ? "G2" : "G3", to, feed, {}, "CR=" + num(sweep > std::numbers::pi ? -radius : radius));
            return;
        }
        move(cw ? "G2" : "G3", to, feed, {}, "I" + num(centre.r - at_.r) + " K" + num(centre.z - at_.z));
    }

    ZR at() const { return at_; }
    void setAt(ZR p) { at_ = p; }
    const LatheWords& words() const { return w_; }
    const post::Dialect& dialect() const { return d_; }
    bool inch() const { return inch_; }

    std::string takeText() { return std::move(nc_); }
    std::vector<BlockSource> takeLines() { return std::move(lines_); }

private:
    const post::Dialect& d_;
    LatheWords w_;
    bool inch_;
    int decimals_ = 3;
    int sequence_ = 0;
    BlockSource source_;
    std::string nc_;
    std::vector<BlockSource> lines_;
    std::string motion_, xw_, zw_, fw_;
    ZR at_{};
};

// The roughing cycle's contour as blocks (no numbers), written through the
// writer's number format: from the cycle's start level onto the contour's
// first point (with Z too for a LinuxCNC subroutine, X alone for FANUC's
// type I P block), then each element.
std::vector<std::string> cycleContour(const LatheWriter& w, const TurnCycle& c, bool withZ)
{
    std::vector<std::string> out;
    const ZR first = c.contour.front().a;
    out.push_back(withZ ? "G0 " + w.x(first.r) + " " + w.z(c.start.z) : "G0 " + w.x(first.r));
    if (std::abs(c.start.z - first.z) > 1e-9) out.push_back("G1 " + w.z(first.z));
    ZR at = first;
    for (const auto& s : c.contour) {
        if (s.arc) {
            out.push_back(std::string(s.ccw ? "G3 " : "G2 ") + w.x(s.b.r) + " " + w.z(s.b.z) + " I" + w.num(s.centre.r - at.r) + " K" +
                          w.num(s.centre.z - at.z));
        } else {
            std::string b = "G1";
            if (std::abs(s.b.r - at.r) > 1e-9) b += " " + w.x(s.b.r);
            if (std::abs(s.b.z - at.z) > 1e-9) b += " " + w.z(s.b.z);
            if (b != "G1") out.push_back(b);
        }
        at = s.b;
    }
    return out;
}

class LathePoster {
public:
    LathePoster(LatheWriter& w, const PostOptions& o, const std::vector<Tool>& library, const std::vector<Step>& steps)
        : w_(w), o_(o), lib_(library), steps_(steps), stations_(latheStations(steps))
    {
    }

    void start()
    {
        const post::Dialect& d = w_.dialect();
        w_.source({});
        if (d.percentFraming) w_.line("%");
        const std::string name = post::commentText(o_.programName.empty() ? std::string("TAIWA") : o_.programName, d.upperCaseComments);
        if (!d.programNumberLine.empty())
            w_.line(fmt::format(fmt::runtime(d.programNumberLine), fmt::arg("number", o_.programNumber), fmt::arg("name", name.substr(0, 40))));
        else
            w_.comment("Program " + o_.programName);
        w_.comment(fmt::format("Generated by Taiwa {}; machine {}; dialect {}; material {}; units {}", TAIWA_VERSION,
                               o_.machine.empty() ? "-" : o_.machine, d.name, o_.material, w_.inch() ? "inch" : "mm"));
        for (const auto& [station, id] : stations_) {
            const Tool* t = findTool(lib_, id);
            w_.comment(fmt::format("T{:02d} = library T{} {} R{} orientation {}", station, id, t ? t->name : "?",
                                   t ? w_.num(t->cornerRadius) : "?", orientationOf(id)));
        }
        // LinuxCNC takes the nose radii and orientations from its tool
        // table: the export writes it beside the tape (tool_table.h).
        if (!w_.words().fanuc && !w_.words().siemens && !o_.fileStem.empty())
            w_.comment(fmt::format("Tool table {}.tbl: the stations above with their nose diameters and orientations, in inch", o_.fileStem));
        if (w_.words().siemens)
            w_.block(fmt::format("{} {} G40 G90 {} {}", w_.words().plane, w_.inch() ? d.inchWord : d.metricWord,
                                 post::workOffsetWords(d, o_.workOffset), w_.words().feedPerRev));
        else
            w_.block(fmt::format("{} {} G40 G80 G90 {} {}", w_.words().plane, w_.inch() ? "G20" : "G21",
                                 post::workOffsetWords(d, o_.workOffset), w_.words().feedPerRev));
        // LinuxCNC takes the roughing contours as subroutines, defined before they are called.
        if (!w_.words().fanuc && !w_.words().siemens)
            for (std::size_t i = 0; i < steps_.size(); ++i)
                if (usesCycle(steps_[i])) {
                    w_.source({static_cast<int>(i), -1});
                    const auto& c = *steps_[i].turn->path.cycle;
                    w_.line(fmt::format("o{} sub", subNumber(i)));
                    for (const auto& b : cycleContour(w_, c, true)) w_.line("  " + b);
                    w_.line(fmt::format("o{} endsub", subNumber(i)));
                }
    }

    void step(std::size_t index, const Step& s)
    {
        const TurnStep& ts = *s.turn;
        const int station = stationOf(s.tool->toolId);
        w_.source({static_cast<int>(index), -1});
        const auto u = static_cast<std::size_t>(s.unit);
        const std::string name = u < o_.unitNames.size() && !o_.unitNames[u].empty() ? " \"" + o_.unitNames[u] + "\"" : "";
        w_.comment(fmt::format("STEP {}: UNIT {}{} {} {} T{}", index + 1, s.unit + 1, name, s.module, upper(s.label()), s.tool->toolId));
        if (station != station_) {
            stop();
            w_.rapid({o_.latheChangeZ, o_.latheChangeX / 2.0});
            if (w_.words().fanuc) w_.block(fmt::format("T{:02d}{:02d}", station, station));
            else if (w_.words().siemens) w_.block(fmt::format("T{} D1", station));
            else w_.block(fmt::format("T{} M6 G43", station));
            w_.forget();
            station_ = station;
            spindle_ = {};
        }
        const TurnCutting& c = ts.cutting;
        const std::string sp = spindleWords(c);
        if (sp != spindle_) {
            if (c.constantSurfaceSpeed && w_.words().fanuc) w_.block("G50 S" + post::formatInteger(c.maxRpm));
            w_.block(sp + " " + w_.dialect().spindleClockwise);
            spindle_ = sp;
            if (o_.coolant && !coolant_) {
                w_.block(w_.dialect().coolantOn);
                coolant_ = true;
            }
        }
        const TurnPath& p = ts.path;
        w_.rapid(p.start);
        if (usesCycle(s)) {
            cycle(index, *p.cycle, c);
            return;
        }
        if (ts.thread && !w_.words().siemens) {
            threadCycle(*ts.thread);
            return;
        }
        for (std::size_t m = 0; m < p.moves.size(); ++m) {
            w_.source({static_cast<int>(index), static_cast<int>(m)});
            const TurnMove& mv = p.moves[m];
            const double f = mv.feed == FeedKind::Plunge ? c.plungeFeedPerRev : c.feedPerRev;
            std::string prefix;
            if (p.comp != NoseCompensation::Off && static_cast<int>(m) == p.compFrom) prefix = p.comp == NoseCompensation::Left ? "G41" : "G42";
            if (p.comp != NoseCompensation::Off && static_cast<int>(m) == p.compTo) prefix = "G40";
            switch (mv.kind) {
            case TurnMove::Rapid:
                if (!prefix.empty()) w_.move("G0", mv.end, std::nullopt, prefix);
                else w_.rapid(mv.end);
                break;
            case TurnMove::Feed:
                // A threading pass: synchronised with the spindle, K the lead along Z.
                if (ts.thread) w_.move("G33", mv.end, std::nullopt, {}, "K" + w_.num(ts.thread->pitch));
                else w_.linear(mv.end, f, prefix);
                break;
            case TurnMove::ArcCW:
            case TurnMove::ArcCCW: w_.arc(mv.kind == TurnMove::ArcCW, mv.end, mv.centre, f); break;
            }
        }
    }

    void end()
    {
        w_.source({});
        stop();
        w_.rapid({o_.latheChangeZ, o_.latheChangeX / 2.0});
        w_.block(w_.dialect().programEnd);
        if (w_.dialect().percentFraming) w_.line("%");
    }

private:
    // The control's G71 where the step has one (Siemens' CYCLE95 is not
    // written: its tapes carry the passes).
    bool usesCycle(const Step& s) const
    {
        return o_.turningCycles && !w_.words().siemens && s.turn && s.turn->path.cycle.has_value();
    }
    static int subNumber(std::size_t stepIndex) { return 100 + static_cast<int>(stepIndex) + 1; }

    int stationOf(int id) const
    {
        for (const auto& [station, tool] : stations_)
            if (tool == id) return station;
        return 0;
    }
    int orientationOf(int id) const
    {
        for (const auto& s : steps_)
            if (s.tool && s.tool->toolId == id && s.turn) return s.turn->orientation;
        return 0;
    }

    std::string spindleWords(const TurnCutting& c) const
    {
        if (!c.constantSurfaceSpeed) return "G97 S" + post::formatInteger(c.rpm);
        // G96 S is in feet per minute under G20.
        const double vc = w_.inch() ? c.surfaceSpeed * 1000.0 / 304.8 : c.surfaceSpeed;
        if (w_.words().fanuc) return "G96 S" + post::formatInteger(vc);
        if (w_.words().siemens) return "G96 S" + post::formatInteger(vc) + " LIMS=" + post::formatInteger(c.maxRpm);
        return "G96 D" + post::formatInteger(c.maxRpm) + " S" + post::formatInteger(vc);
    }

    void stop()
    {
        if (station_ == 0) return;
        if (coolant_) w_.block(w_.dialect().coolantOff);
        coolant_ = false;
        w_.block(w_.dialect().spindleStop);
    }

    void cycle(std::size_t index, const TurnCycle& c, const TurnCutting& cut)
    {
        w_.rapid(c.start);
        if (w_.words().fanuc && w_.dialect().oneBlockRoughingCycle) {
            // One block, the depth of cut in D (Haas; the retract is the
            // control's setting).
            const auto blocks = cycleContour(w_, c, false);
            const int p = w_.sequenceAhead(2), q = w_.sequenceAhead(1 + static_cast<int>(blocks.size()));
            w_.block(fmt::format("G71 P{} Q{} U{} W{} D{} {}", p, q, w_.num(2.0 * c.allowanceX * (c.inner ? -1.0 : 1.0)),
                                 w_.num(c.allowanceZ), w_.num(c.depthOfCut), w_.feedWord(cut.feedPerRev)));
            for (const auto& b : blocks) w_.block(b);
        } else if (w_.words().fanuc) {
            // Type I (X alone in the P block) when the contour only grows
            // outward; every contour here does (turn_plan: monotone).
            const auto blocks = cycleContour(w_, c, false);
            const int p = w_.sequenceAhead(3), q = w_.sequenceAhead(2 + static_cast<int>(blocks.size()));
            w_.block(fmt::format("G71 U{} R{}", w_.num(c.depthOfCut), w_.num(c.retract)));
            w_.block(fmt::format("G71 P{} Q{} U{} W{} {}", p, q, w_.num(2.0 * c.allowanceX * (c.inner ? -1.0 : 1.0)),
                                 w_.num(c.allowanceZ), w_.feedWord(cut.feedPerRev)));
            for (const auto& b : blocks) w_.block(b);
        } else {
            w_.block(fmt::format("G71 Q{} {} {} D{} I{} R{} {}", subNumber(index), w_.x(c.start.r), w_.z(c.start.z),
                                 w_.num(c.allowanceX), w_.num(c.depthOfCut), w_.num(c.retract), w_.feedWord(cut.feedPerRev)));
        }
        w_.forget();
        w_.rapid(c.start);
    }

    // The control's threading cycle from the drive point (the path's start),
    // docs/turning.md "Threading". LinuxCNC 2.9: G76 P Z I J R K Q H with
    // I, J, K as diameters under G7 (interp_convert.cc halves them); FANUC
    // 0i: G76 P(m)(r)(a) Q(dmin) R(d) then G76 X Z P(k) Q(Δd) F, P and Q in
    // the least input increment; the one-block form (Haas, FANUC 10/11):
    // G76 X Z K D F A P1.
    void threadCycle(const TurnThread& th)
    {
        const double root = th.crestR - th.depth;
        const auto increments = [&](double mm) { return post::formatInteger(w_.units(mm) * (w_.inch() ? 10000.0 : 1000.0)); };
        if (w_.words().fanuc && w_.dialect().oneBlockRoughingCycle) {
            w_.block(fmt::format("G76 {} {} K{} D{} {} A60 P1", w_.x(root), w_.z(th.zEnd), w_.num(th.depth), w_.num(th.firstDepth),
                                 w_.feedWord(th.pitch)));
        } else if (w_.words().fanuc) {
            // m: the passes at full depth; r: no chamfer out (the relief);
            // a: the insert's 60°; no finishing allowance.
            w_.block(fmt::format("G76 P{:02d}0060 Q{} R{}", th.springPasses + 1, increments(kThreadMinCut), w_.num(0.0)));
            w_.block(fmt::format("G76 {} {} P{} Q{} {}", w_.x(root), w_.z(th.zEnd), increments(th.depth), increments(th.firstDepth),
                                 w_.feedWord(th.pitch)));
        } else {
            w_.block(fmt::format("G76 P{} {} I{} J{} R2 K{} Q{:g} H{}", w_.num(th.pitch), w_.z(th.zEnd), w_.num(-2.0 * th.clearance),
                                 w_.num(2.0 * th.firstDepth), w_.num(2.0 * th.depth), th.compoundAngle, th.springPasses));
        }
        w_.forget();
        w_.setAt({th.zEnd, th.crestR + th.clearance});
    }

    LatheWriter& w_;
    const PostOptions& o_;
    const std::vector<Tool>& lib_;
    const std::vector<Step>& steps_;
    std::vector<std::pair<int, int>> stations_;
    int station_ = 0;
    std::string spindle_;
    bool coolant_ = false;
};

}  // namespace

std::vector<std::pair<int, int>> latheStations(const std::vector<Step>& orderedSteps)
{
    std::vector<std::pair<int, int>> out;
    for (const auto& s : orderedSteps) {
        if (!s.tool) continue;
        if (std::none_of(out.begin(), out.end(), [&](const auto& p) { return p.second == s.tool->toolId; }))
            out.emplace_back(static_cast<int>(out.size()) + 1, s.tool->toolId);
    }
    return out;
}

PostedProgram postLathe(const std::vector<Step>& orderedSteps, const std::vector<Tool>& library, const PostOptions& options)
{
    const post::Dialect* dialect = post::findDialect(options.dialect);
    if (!dialect) throw std::invalid_argument("unknown dialect '" + options.dialect + "'");
    if (const auto why = post::cannotPost(*dialect, post::Task::LatheTape)) throw std::invalid_argument(*why);
    for (const auto& s : orderedSteps) {
        if (!s.turn || !s.tool) throw std::invalid_argument("post-processor: step " + s.label() + " is not a turning step with a tool");
        if (!findTool(library, s.tool->toolId))
            throw std::invalid_argument("post-processor: tool " + std::to_string(s.tool->toolId) + " is not in the library");
    }
    LatheWriter writer(*dialect, options);
    LathePoster poster(writer, options, library, orderedSteps);
    poster.start();
    for (std::size_t i = 0; i < orderedSteps.size(); ++i) poster.step(i, orderedSteps[i]);
    poster.end();
    PostedProgram p;
    p.nc = writer.takeText();
    p.lines = writer.takeLines();
    p.tapeImage = post::tapeImage(p.nc, options.programName, dialect->name, options.machine);
    return p;
}

}  // namespace taiwa
