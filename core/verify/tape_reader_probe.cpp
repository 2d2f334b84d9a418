// The probing programs run as their control runs them (tape_reader_probe.h):
// line by line on the readers' machine (tape_reader_machine.h), the flow
// (labels, o-word ifs) kept here, the values by tape_params.h, the motions
// in machine coordinates with the work offsets the program reads and sets.
#include "verify/tape_reader_probe.h"

#include "verify/tape_params.h"
#include "verify/tape_reader_machine.h"

#include <algorithm>
#include <cctype>
#include <map>

namespace taiwa::verify {

namespace {

using namespace tape;

constexpr double kInch = 25.4;

std::string lower(std::string s)
{
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

class ProbeControl {
public:
    ProbeControl(const post::Dialect& d, const Point3& start, const Point3& offsets, const ProbeTouch& touch)
        : fanuc_(d.macroSyntax == "fanuc"), numbered_(!d.programNumberLine.empty()), params_(fanuc_), touch_(touch)
    {
        m_.framed = d.percentFraming;
        m_.at = start;
        for (int p = 1; p <= 9; ++p) setOffset(p, false, offsets);
        if (fanuc_)
            for (int p = 1; p <= 48; ++p) setOffset(p, true, offsets);
        current();
    }

    ProbeReading read(const std::string& text)
    {
        ProbeReading r;
        r.tape = m_.readLines(
            text, [&](const std::string& raw) { line(raw); },
            [&](const std::vector<std::string>& lines) {
                if (!stop_.empty()) return;
                if (label_) refuse("GOTO " + std::to_string(*label_) + ": no such label after it");
                if (!ifs_.empty()) refuse("o" + std::to_string(ifs_.back().number) + " if is not closed");
                m_.endOfTape(lines);
            });
        r.probes = std::move(probes_);
        r.targets = std::move(targets_);
        r.stop = stop_;
        r.stopLine = stopLine_;
        return r;
    }

private:
    struct If {
        int number = 0;
        bool active = false;  // its lines run
        bool taken = false;   // a branch of it ran (or none may: it lies in a branch skipped)
    };

    bool skipping() const { return label_.has_value() || std::any_of(ifs_.begin(), ifs_.end(), [](const If& i) { return !i.active; }); }

    void line(const std::string& raw)
    {
        if (!stop_.empty()) return;  // the program stopped at an abort or alarm
        const std::string low = lower(raw);
        const std::string s = trim(m_.withoutComments(raw, false));
        if (s.empty()) {
            if (!fanuc_ && low.find("(abort,") != std::string::npos && !skipping()) halt(raw);
            return;
        }
        if (m_.framingLine(s)) return;
        if (!begun_ && numbered_ && s.size() > 1 && (s[0] == 'O') && whole(s.substr(1))) return;  // the O-number
        begun_ = true;
        std::string rest = s;
        int label = -1;
        if (rest[0] == 'N' || rest[0] == 'n') {
            const auto end = rest.find(' ');
            const auto n = whole(std::string_view(rest).substr(1, end == std::string::npos ? std::string::npos : end - 1));
            if (!n) refuse("'" + rest.substr(0, end) + "' is not a block number");
            label = *n;
            rest = end == std::string::npos ? std::string() : trim(rest.substr(end));
        }
        if (label_ && label == *label_) label_.reset();
        if (!fanuc_ && (rest[0] == 'o' || rest[0] == 'O')) return oWord(rest);
        if (skipping()) return;
        if (!fanuc_ && low.find("(abort,") != std::string::npos) return halt(raw);
        if (fanuc_ && (rest.starts_with("IF") || rest.starts_with("GOTO"))) return jump(rest);
        const auto [name, value] = params_.assignment(rest);
        if (name == "3000" && fanuc_) return halt(raw);
        if (!name.empty()) return params_.set(name, value);
        block(rest);
    }

    void halt(const std::string& raw)
    {
        stop_ = trim(raw);
        stopLine_ = m_.line;
    }

    // "o101 if [...]", "o101 elseif [...]", "o101 else", "o101 endif".
    void oWord(const std::string& s)
    {
        const auto space = s.find(' ');
        const auto n = whole(std::string_view(s).substr(1, space == std::string::npos ? std::string::npos : space - 1));
        const std::string rest = space == std::string::npos ? std::string() : trim(s.substr(space));
        const std::string word = lower(rest.substr(0, rest.find(' ')));
        const std::string expr = rest.size() > word.size() ? rest.substr(word.size()) : std::string();
        if (!n) refuse("'" + s + "' is not understood");
        const bool outerSkipped = std::any_of(ifs_.begin(), ifs_.end() - (word == "if" ? 0 : std::min<long>(1, static_cast<long>(ifs_.size()))),
                                              [](const If& i) { return !i.active; }) || label_.has_value();
        if (word == "if") {
            const bool go = !outerSkipped && params_.evaluate(expr) != 0.0;
            ifs_.push_back({*n, go, go || outerSkipped});
            return;
        }
        if (ifs_.empty() || ifs_.back().number != *n) refuse("o" + std::to_string(*n) + " " + word + " with no o" + std::to_string(*n) + " if");
        If& i = ifs_.back();
        if (word == "endif" && expr.empty()) ifs_.pop_back();
        else if (word == "else" && expr.empty()) i.active = !i.taken, i.taken = true;
        else if (word == "elseif") {
            i.active = !i.taken && !outerSkipped && params_.evaluate(expr) != 0.0;
            i.taken = i.taken || i.active;
        } else
            refuse("o-word '" + word + "' is not understood");
    }

    // FANUC: "IF [cond] GOTO n", "GOTO n" (forward only: the post jumps to its alarms and its end).
    void jump(const std::string& s)
    {
        const auto at = s.rfind("GOTO");
        const auto target = whole(trim(s.substr(at + 4)));
        if (!target) refuse("GOTO to no label number");
        if (s.starts_with("IF")) {
            if (at < 3) refuse("IF with no condition");
            if (params_.evaluate(s.substr(2, at - 2)) == 0.0) return;
        } else if (at != 0) {
            refuse("'" + s + "' is not understood");
        }
        label_ = *target;
    }

    void block(const std::string& b);
    void motion(const std::map<char, double>& axes, bool probe);

    int base(int p, bool extended) const { return extended ? 7001 + 20 * (p - 1) : 5201 + 20 * p; }
    Point3 offset(int p, bool extended) const
    {
        const int b = base(p, extended);
        return {params_.get(std::to_string(b)), params_.get(std::to_string(b + 1)), params_.get(std::to_string(b + 2))};
    }
    void setOffset(int p, bool extended, const Point3& v)
    {
        const int b = base(p, extended);
        params_.set(std::to_string(b), v.x), params_.set(std::to_string(b + 1), v.y), params_.set(std::to_string(b + 2), v.z);
    }
    // The current position in the active work coordinates, where the program reads it.
    void current()
    {
        const Point3 o = offset(active_, extended_);
        const int b = fanuc_ ? 5041 : 5420;
        params_.set(std::to_string(b), m_.at.x - o.x), params_.set(std::to_string(b + 1), m_.at.y - o.y),
            params_.set(std::to_string(b + 2), m_.at.z - o.z);
    }

    Machine m_;
    bool fanuc_, numbered_;
    Params params_;
    const ProbeTouch& touch_;
    bool begun_ = false, incremental_ = false;
    bool probeMode_ = false, probeTouchRequired_ = false;  // LinuxCNC's G38.2/G38.3 in force, and which
    int mode_ = 0;  // G0 (0) or G1 (10)
    double feed_ = kUnknown;
    int active_ = 1;  // the work offset: 1-9 (G54-G59.3), or extended
    bool extended_ = false;
    std::vector<If> ifs_;
    std::optional<int> label_;  // a GOTO's target, skipping to it
    std::vector<int> probes_;
    std::vector<Point3> targets_;
    std::string stop_;
    int stopLine_ = 0;
};

void ProbeControl::block(const std::string& text)
{
    const auto words = params_.words(text);
    std::vector<int> g, m;
    std::map<char, double> v;
    for (std::size_t k = 0; k < words.size(); ++k) {
        const ParamWord& w = words[k];
        if (w.letter == 'G' || w.letter == 'M' || w.letter == 'N') {
            if (w.computed || !codeWord(std::string(1, w.letter) + w.text, k + 1, g, m)) refuse("'" + text + "' is not understood");
            continue;
        }
        if (std::string_view("XYZFTHPLR").find(w.letter) == std::string_view::npos) refuse(std::string("'") + w.letter + w.text + "' is not understood");
        if (v.contains(w.letter)) refuse(std::string("two ") + w.letter + " words in one block");
        v[w.letter] = w.value;
    }
    bool g10 = false, g28 = false, g53 = false, probe = false;
    for (const int code : g) {
        const int n = code / 10, tenth = code % 10;
        if (code == 0 || code == 10) probeMode_ = false, mode_ = code;
        else if (!fanuc_ && n == 38 && (tenth == 2 || tenth == 3)) probeMode_ = true, probeTouchRequired_ = tenth == 2;
        else if (fanuc_ && code == 310) probe = true;
        else if (code == 100) g10 = true;
        else if (code == 170 || code == 400 || code == 940 || code == 490 || code == 430 || code == 800) continue;
        else if (code == 200 || code == 210) {
            if (code == 200 && !m_.unitsStated) m_.at = {m_.at.x / kInch, m_.at.y / kInch, m_.at.z / kInch};
            m_.units(code == 200);
        }
        else if (code == 900 || code == 910) incremental_ = code == 910;
        else if (code == 280) g28 = true;
        else if (code == 530 && !fanuc_) g53 = true;
        else if (code >= 540 && code <= 590 && tenth == 0) active_ = n - 53, extended_ = false;
        else if (!fanuc_ && code >= 591 && code <= 593) active_ = 6 + tenth, extended_ = false;
        else if (fanuc_ && (code == 541 || code == 1540)) {
            if (!v.contains('P')) refuse("G54.1 with no P");
            active_ = static_cast<int>(v.at('P')), extended_ = true;
        } else
            refuse("G" + std::to_string(n) + (tenth ? "." + std::to_string(tenth) : "") + " is not understood");
    }
    for (const int code : m) {
        if (code == 6 && v.contains('T')) m_.tool = static_cast<int>(v.at('T'));
        else if (code == 2 || code == 30) m_.ended = true;
        else refuse("M" + std::to_string(code) + " is not understood");
    }
    if (v.contains('F')) feed_ = v.at('F');
    if (v.contains('R') && !g10) refuse("R outside G10");  // G10's R: the rotation about the origin set
    std::map<char, double> axes;
    for (const char a : {'X', 'Y', 'Z'})
        if (v.contains(a)) axes[a] = v.at(a);
    if (g10) {
        const int l = v.contains('L') ? static_cast<int>(v.at('L')) : 0;
        if ((l != 2 && l != 20) || !v.contains('P')) refuse("G10 other than L2 P or L20 P");
        const int p = static_cast<int>(v.at('P'));
        const bool extended = fanuc_ && l == 20;
        Point3 o = offset(p, extended);
        double* const axis[3] = {&o.x, &o.y, &o.z};
        const double at[3] = {m_.at.x, m_.at.y, m_.at.z};
        for (int k = 0; k < 3; ++k)
            if (axes.contains(static_cast<char>('X' + k))) *axis[k] = l == 2 ? axes.at(static_cast<char>('X' + k)) : at[k] - axes.at(static_cast<char>('X' + k));
        setOffset(p, extended, o);
        return current();
    }
    if (g28 || g53) {
        // The machine's retract: "G91 G28 Z0" (FANUC), "G53 G0 Z0" (LinuxCNC), to the top of Z.
        if (axes.size() != 1 || !axes.contains('Z') || axes.at('Z') != 0.0 || (g28 && !incremental_) || (g53 && mode_ != 0))
            refuse("a machine retract other than G91 G28 Z0 or G53 G0 Z0");
        m_.traverse({m_.at.x, m_.at.y, kUnknown});
        return current();
    }
    if (axes.empty()) return;
    motion(axes, probe || probeMode_);
}

void ProbeControl::motion(const std::map<char, double>& axes, bool probe)
{
    const Point3 o = offset(active_, extended_);
    Point3 to = m_.at;
    double* const axis[3] = {&to.x, &to.y, &to.z};
    const double origin[3] = {o.x, o.y, o.z};
    for (int k = 0; k < 3; ++k) {
        const char a = static_cast<char>('X' + k);
        if (axes.contains(a)) *axis[k] = incremental_ ? *axis[k] + axes.at(a) : origin[k] + axes.at(a);
    }
    if (!probe) {
        if (mode_ == 0) m_.traverse(to);
        else m_.feedTo(to, feed_);
        return current();
    }
    if (!known(m_.at)) refuse("a probing move from an unknown position");
    const double k = m_.out.inches ? kInch : 1.0;
    const std::optional<Point3> hit = touch_({m_.at.x * k, m_.at.y * k, m_.at.z * k}, {to.x * k, to.y * k, to.z * k});
    const Point3 end = hit ? Point3{hit->x / k, hit->y / k, hit->z / k} : to;
    probes_.push_back(static_cast<int>(m_.out.motions.size()));
    targets_.push_back(to);
    m_.feedTo(end, feed_);
    const int b = 5061;
    params_.set(std::to_string(b), end.x - o.x), params_.set(std::to_string(b + 1), end.y - o.y),
        params_.set(std::to_string(b + 2), end.z - o.z);
    if (!fanuc_) params_.set("5070", hit ? 1.0 : 0.0);
    current();
    if (!hit && probeTouchRequired_ && probeMode_) refuse("G38.2 touches nothing: the control stops with an error");
}

}  // namespace

ProbeReading readProbingProgram(const std::string& text, const post::Dialect& dialect, const Point3& start, const ProbeTouch& touch,
                                const Point3& offsets)
{
    return ProbeControl(dialect, start, offsets, touch).read(text);
}

}  // namespace taiwa::verify
