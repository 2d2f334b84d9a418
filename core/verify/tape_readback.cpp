// The posted tape read back and held against the plan (tape_readback.h):
// each motion the reader makes of a line is judged against what the line was
// written for (PostedProgram::lines: the step and move, or the frame), in
// mm; a motion that is not a planned one is measured against the material
// (how deep the tool's tip goes below the stock's top under the tool).
#include "verify/tape_readback.h"

#include "verify/tape_reader.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace taiwa::verify {

namespace {

constexpr double kInch = 25.4;

bool near(double tape, double planned, double tol) { return std::isnan(tape) || std::abs(tape - planned) <= tol; }
bool nearXY(const Point3& a, const Point3& b, double tol) { return near(a.x, b.x, tol) && near(a.y, b.y, tol); }
bool near3(const Point3& a, const Point3& b, double tol) { return nearXY(a, b, tol) && near(a.z, b.z, tol); }

// What the judge needs of each step: its path, its feeds, its tool's radius.
struct StepView {
    const ToolPath* path = nullptr;
    std::optional<SpeedsFeeds> sf;
    double radius = 0.0;
};

class Judge {
public:
    Judge(const Plan& plan, const post::Dialect& dialect, const PostOptions& post, bool inches) : plan_(plan), post_(post)
    {
        const int decimals = inches ? dialect.lengthDecimals.inch : dialect.lengthDecimals.mm;
        const int feedDecimals = inches ? dialect.feedDecimals.inch : dialect.feedDecimals.mm;
        const double unit = inches ? kInch : 1.0;
        tol_ = 1.5 * std::pow(10.0, -decimals) * unit;
        feedTol_ = (0.5 * std::pow(10.0, -feedDecimals) + 1e-6) * unit;
        for (const Step& s : plan.steps) {
            StepView v;
            if (s.path) v.path = &*s.path;
            // The speeds and feeds planJob bound to the step (none: the
            // tool has no cutting data for the material, and neither has
            // the tape a feed to hold against).
            v.sf = s.speeds;
            if (s.tool)
                if (const Tool* t = plan.tool(s.tool->toolId)) v.radius = t->radius();
            steps_.push_back(v);
        }
    }

    // Empty when `m` (in mm) is what line source `src` was written for.
    bool planned(const TapeMotion& m, BlockSource src)
    {
        if (src.step < 0 || src.step >= static_cast<int>(steps_.size())) {
            hole_ = {};
            // The program's end: up to the safe height where the tool is.
            return m.kind == TapeMotion::Traverse && up(m) && near(m.end.z, post_.safeZ, tol_);
        }
        const StepView& s = steps_[static_cast<std::size_t>(src.step)];
        if (!s.path) return false;
        const ToolPath& p = *s.path;
        if (src.move < 0) {
            hole_ = {};
            // A step's frame: the retract up to the safe height, across to
            // the path's start at the approach height, down to the start.
            if (m.kind != TapeMotion::Traverse) return false;
            if (up(m) && near(m.end.z, post_.safeZ, tol_)) return true;
            // Across at the height the retract left (at or above the safe height).
            const double approachZ = std::max(post_.safeZ, p.start.z);
            const bool level = !std::isnan(m.start.z) && near(m.end.z, m.start.z, tol_) && m.end.z >= post_.safeZ - tol_;
            return nearXY(m.end, p.start, tol_) &&
                   (level || near(m.end.z, approachZ, tol_) || near(m.end.z, p.start.z, tol_));
        }
        if (src.move >= static_cast<int>(p.moves.size())) return false;
        const Move& pm = p.moves[static_cast<std::size_t>(src.move)];
        if (pm.kind != MoveKind::DrillCycle) hole_ = {};
        const auto feedOk = [&](double planned, double relative) {
            return std::abs(m.feed - planned) <= feedTol_ + relative * planned;
        };
        const double f = !s.sf ? std::nan("") : pm.feed == FeedKind::Cut ? s.sf->feed : s.sf->plungeFeed;
        const auto feedMatches = [&] { return std::isnan(f) || feedOk(f, 0.0); };
        switch (pm.kind) {
        case MoveKind::Rapid: return m.kind == TapeMotion::Traverse && near3(m.end, pm.end, tol_);
        case MoveKind::Feed: return m.kind == TapeMotion::Feed && near3(m.end, pm.end, tol_) && feedMatches();
        case MoveKind::ArcCW:
        case MoveKind::ArcCCW: {
            // An arc shorter than a unit of the tape is written as a line.
            if (m.kind == TapeMotion::Feed) return near3(m.end, pm.end, tol_) && feedMatches();
            if (m.kind != TapeMotion::Arc) return false;
            const int turn = pm.kind == MoveKind::ArcCW ? -1 : 1;
            const double r = std::hypot(pm.end.x - pm.centre.x, pm.end.y - pm.centre.y);
            const bool onCircle = std::abs(std::hypot(m.end.x - pm.centre.x, m.end.y - pm.centre.y) - r) <= 2.0 * tol_;
            return (m.rotation > 0) == (turn > 0) && near(m.centre.x, pm.centre.x, 2.0 * tol_) &&
                   near(m.centre.y, pm.centre.y, 2.0 * tol_) && onCircle && feedMatches();
        }
        case MoveKind::DrillCycle: return inHole(m, src, pm, s);
        }
        return false;
    }

private:
    // Straight up from where the motion began (or from an unknown height).
    bool up(const TapeMotion& m) const
    {
        return nearXY(m.end, m.start, tol_) && (std::isnan(m.start.z) || m.end.z >= m.start.z - tol_);
    }

    // A canned cycle's motions: across to the hole above R, then up and
    // down its axis, feeding no deeper than its bottom at the cycle's rate,
    // a rapid going down no deeper than the deepest feed so far (a peck
    // comes back down to just above it).
    bool inHole(const TapeMotion& m, BlockSource src, const Move& pm, const StepView& s)
    {
        if (hole_.step != src.step || hole_.move != src.move) hole_ = {src.step, src.move, pm.retractZ};
        const double r = pm.retractZ;
        const bool overHole = nearXY(m.end, pm.end, tol_);
        if (m.kind == TapeMotion::Arc) return false;
        if (m.kind == TapeMotion::Traverse) {
            if (up(m)) return true;  // up to R first, or out of the hole
            if (!overHole) return false;
            const bool across = !nearXY(m.start, m.end, tol_);
            if (across) return m.end.z >= r - tol_ && (std::isnan(m.start.z) || m.start.z >= r - tol_);
            // Down to R, or back down into the hole no deeper than it is drilled.
            return m.end.z >= std::min(r, hole_.deepest) - tol_;
        }
        if (!overHole || !nearXY(m.start, m.end, tol_) || m.end.z < pm.end.z - tol_) return false;
        hole_.deepest = std::min(hole_.deepest, m.end.z);
        if (!s.sf) return true;
        // Tapping at the pitch a revolution (S and the pitch rounded on the
        // tape: a percent); the other cycles at the step's feed.
        const double rate = pm.cycle == CycleKind::Tap ? pm.pitch * s.sf->rpm : s.sf->feed;
        return std::abs(m.feed - rate) <= feedTol_ + 0.01 * rate;
    }

    struct Hole {
        int step = -1, move = -1;
        double deepest = 0.0;  // the deepest feed into it so far [mm]
    };

    const Plan& plan_;
    const PostOptions& post_;
    std::vector<StepView> steps_;
    double tol_ = 0.0, feedTol_ = 0.0;  // [mm], [mm/min]
    Hole hole_;

public:
    // How deep [mm] the tool of radius `radius`, its tip along `m`, goes
    // below the material's top: in the height field when there is one, else
    // in the stock block before the first cut. An unknown X or Y is anywhere
    // over the stock; an unknown Z is at the retract's height (no depth).
    double intoStock(const TapeMotion& m, double radius, const Report& report) const
    {
        if (std::isnan(m.end.z)) return 0.0;
        const Stock& stock = plan_.mmJob.stock;
        const sim::HeightField& field = report.stock;
        const bool anywhere = std::isnan(m.end.x) || std::isnan(m.end.y) || std::isnan(m.start.x) || std::isnan(m.start.y);
        if (anywhere) return m.end.z < 0.0 ? std::min(-m.end.z, stock.height) : 0.0;
        const double z0 = std::isnan(m.start.z) ? m.end.z : m.start.z;
        const double length = std::hypot(m.end.x - m.start.x, m.end.y - m.start.y);
        const double spacing = std::max(field.columns() > 0 ? field.cellSize() : 0.5, 0.05);
        const int samples = std::clamp(static_cast<int>(std::ceil(length / spacing)), 1, 20000);
        double deepest = 0.0;
        for (int k = 0; k <= samples; ++k) {
            const double t = static_cast<double>(k) / samples;
            const double x = m.start.x + (m.end.x - m.start.x) * t, y = m.start.y + (m.end.y - m.start.y) * t;
            const double z = z0 + (m.end.z - z0) * t;
            if (z >= 0.0) continue;  // above the stock's top
            deepest = std::max(deepest, materialUnder(x, y, radius, field, stock) - std::max(z, -stock.height));
        }
        return deepest;
    }

private:
    // The highest material top under a disc of `radius` at (x, y); the
    // stock's bottom where there is none.
    static double materialUnder(double x, double y, double radius, const sim::HeightField& field, const Stock& stock)
    {
        const double bottom = -stock.height;
        const double cx = std::clamp(x, stock.x, stock.x + stock.width), cy = std::clamp(y, stock.y, stock.y + stock.length);
        if (std::hypot(cx - x, cy - y) > radius) return bottom;  // beside the block
        if (field.columns() == 0) return 0.0;
        const double cell = field.cellSize();
        // At most about 64 cells across the disc, enough to find a wall.
        const int reach = static_cast<int>(std::ceil(radius / cell));
        const int stride = std::max(1, reach / 32);
        const int ci = static_cast<int>(std::floor((x - stock.x) / cell)), cj = static_cast<int>(std::floor((y - stock.y) / cell));
        double top = bottom;
        for (int j = cj - reach; j <= cj + reach; j += stride) {
            if (j < 0 || j >= field.rows()) continue;
            for (int i = ci - reach; i <= ci + reach; i += stride) {
                if (i < 0 || i >= field.columns()) continue;
                const Point2 c = field.centre(i, j);
                if (std::hypot(c.x - x, c.y - y) > radius + cell) continue;
                top = std::max(top, field.at(i, j));
            }
        }
        return top;
    }
};

Point3 inMm(Point3 p, double k) { return {p.x * k, p.y * k, p.z * k}; }

// The milling tape's own read-back (readBack).
void readBackMilling(Report& report, const Plan& plan, const PostedProgram& program, const post::Dialect& dialect,
                     const PostOptions& post)
{
    const TapeReading tape = readTape(program.nc, dialect);
    const double k = tape.inches ? kInch : 1.0;
    Judge judge(plan, dialect, post, tape.inches);
    int added = 0;
    for (TapeMotion m : tape.motions) {
        if (added >= kMaxTapeFindings) break;
        m.start = inMm(m.start, k);
        m.end = inMm(m.end, k);
        m.centre = {m.centre.x * k, m.centre.y * k};
        m.feed *= k;
        const std::size_t i = static_cast<std::size_t>(m.line) - 1;
        const BlockSource src = i < program.lines.size() ? program.lines[i] : BlockSource{};
        // Lines that go nowhere (a straight move to where the tool is) are no motion.
        if (m.kind != TapeMotion::Arc && near3(m.end, m.start, 1e-9) && !std::isnan(m.start.z)) continue;
        if (judge.planned(m, src)) continue;
        Finding f;
        f.kind = FindingKind::UnplannedMove;
        f.step = src.step;
        f.line = m.line;
        f.position = m.end;
        const int step = src.step >= 0 && src.step < static_cast<int>(plan.steps.size()) ? src.step : -1;
        const Tool* tool = plan.tool(m.tool);
        if (!tool && step >= 0 && plan.steps[static_cast<std::size_t>(step)].tool)
            tool = plan.tool(plan.steps[static_cast<std::size_t>(step)].tool->toolId);
        // A hundredth of a mm is a touch, not a cut.
        const double depth = judge.intoStock(m, tool ? tool->diameter / 2.0 : 0.0, report);
        f.size = depth > 0.01 ? depth : 0.0;
        f.part = m.kind == TapeMotion::Traverse ? "rapid" : m.kind == TapeMotion::Feed ? "feed" : "arc";
        report.findings.push_back(f);
        ++added;
    }
    addUnreadTape(report, tape);
}

}  // namespace

void readBack(Report& report, const Plan& plan, const PostedJob& posted, const post::Dialect& dialect,
              const PostOptions& post)
{
    if (plan.mmJob.bar) return readBackLathe(report, plan, posted, dialect, post);
    readBackMilling(report, plan, posted.tape, dialect, post);
    readBackProbing(report, plan, posted.probing, dialect, post);
}

void readBack(Report& report, const Plan& plan, const PostedProgram& program, const post::Dialect& dialect,
              const PostOptions& post)
{
    // The other programs posted here, as the export posts them.
    readBack(report, plan, postJob(plan, post, program, dialect), dialect, post);
}

std::string programFile(const PostOptions& post, const std::string& suffix)
{
    return post.fileStem.empty() ? suffix.substr(suffix.starts_with('.') ? 1 : 0) : post.fileStem + suffix;
}

void addUnreadTape(Report& report, const TapeReading& tape, const std::string& program)
{
    if (tape.error.empty()) return;
    Finding f;
    f.kind = FindingKind::UnreadTape;
    f.line = tape.errorLine;
    f.program = program;
    f.part = tape.error;
    report.findings.push_back(f);
}

}  // namespace taiwa::verify
