// The default tool library: what a typical job shop's machining centre
// carries, with cutting data for every material of the shipped technology
// table. Ids are stable: they are the T numbers on the tape.
#include "tools/tool_library.h"
#include "model/translate_noop.h"

#include "tools/default_names.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <tuple>

namespace taiwa {

namespace {

// Surface speed [m/min] and feed per tooth (drills: per revolution) [mm] per
// material, as a carbide-tool maker's starting values, scaled by tool kind.
struct MaterialData {
    const char* id;
    double vcMill, fzMill;    // milling, per mm of diameter (2-25 mm) for fz
    double vcDrill, fDrill;   // drills, per mm of diameter for f
};
constexpr MaterialData kMaterials[] = {
    {"aluminium-6061", 300, 0.008, 120, 0.020},
    {"steel-s45c", 120, 0.005, 80, 0.015},
    {"stainless-304", 80, 0.004, 50, 0.012},
    {"cast-iron-fc250", 110, 0.006, 70, 0.018},
    {"brass-c3604", 200, 0.007, 100, 0.020},
    {"pom", 250, 0.010, 100, 0.025},
};

std::vector<CuttingData> cuttingFor(ToolType type, double diameter)
{
    std::vector<CuttingData> data;
    for (const auto& m : kMaterials) {
        const bool drill = type == ToolType::Drill || type == ToolType::CentreDrill;
        const double scale = type == ToolType::FaceMill ? 1.2 : type == ToolType::TaperEndMill ? 0.6 : 1.0;
        const double fz = drill ? m.fDrill * diameter : m.fzMill * std::clamp(diameter, 2.0, 25.0);
        data.push_back({m.id, (drill ? m.vcDrill : m.vcMill) * scale, fz, drill ? 1.0 : 0.4});
    }
    return data;
}

// What every tool of the library is given: its id, type, size, names,
// holder, flutes and life [min].
Tool identified(int id, ToolType type, double d, tools::Named name, std::string holder, int flutes, double life)
{
    Tool t;
    t.id = id;
    t.type = type;
    t.diameter = d;
    t.name = std::move(name.text);
    t.names = std::move(name.names);
    t.holder = std::move(holder);
    t.flutes = flutes;
    t.lifeMinutes = life;
    return t;
}

Tool make(int id, ToolType type, double d, tools::Named name, double flute, double stickout, std::string holder,
          int flutes, double life)
{
    Tool t = identified(id, type, d, std::move(name), std::move(holder), flutes, life);
    t.fluteLength = flute;
    t.stickout = stickout;
    t.cutting = cuttingFor(type, d);
    return t;
}

// Turning: surface speed [m/min] and feed per revolution [mm/rev] per
// material for roughing and finishing inserts, a carbide maker's starting
// values; grooving and threading take a share of them.
struct TurningData {
    const char* id;
    double vcRough, fRough, vcFinish, fFinish;
};
constexpr TurningData kTurningMaterials[] = {
    {"aluminium-6061", 500, 0.30, 600, 0.12}, {"steel-s45c", 200, 0.30, 250, 0.12},
    {"stainless-304", 160, 0.25, 190, 0.10},  {"cast-iron-fc250", 180, 0.30, 220, 0.15},
    {"brass-c3604", 300, 0.25, 350, 0.10},    {"pom", 250, 0.25, 300, 0.12},
};

// A lathe tool: the insert from its ISO code (inscribed circle as the
// diameter, nose radius as the corner radius), the holder and cutting data.
Tool lathe(int id, ToolType type, tools::Named name, std::string code, double noseRadius, double ic, TurningSpec spec,
           std::string holder, bool finishing, double feedShare = 1.0)
{
    Tool t = identified(id, type, ic, std::move(name), std::move(holder), 1, 30);
    t.cornerRadius = noseRadius;
    t.centreCutting = false;
    spec.insertCode = std::move(code);
    t.turning = std::move(spec);
    for (const auto& m : kTurningMaterials)
        t.cutting.push_back({m.id, finishing ? m.vcFinish : m.vcRough, (finishing ? m.fFinish : m.fRough) * feedShare, 1.0});
    return t;
}

}  // namespace

// Taps cut at a tenth of a drill's surface speed; their feed is the pitch
// per revolution. Reamers at half a drill's speed and twice its feed per
// revolution; boring tools at 0.8 of an end mill's surface speed, 0.05 mm a
// revolution (speedsFeeds takes all three per revolution, as drills).
std::vector<Tool> defaultHoleTools()
{
    std::vector<Tool> tools;
    const std::pair<int, double> tapDrills[] = {{17, 2.5}, {18, 3.3}, {19, 4.2}};
    for (const auto& [id, d] : tapDrills)
        tools.push_back(make(id, ToolType::Drill, d, tools::named(tools::kCarbideDrill, d), 5 * d + 5, 5 * d + 20,
                             TAIWA_TRANSLATE_NOOP("taiwa::msg", "ER32 collet chuck"), 2, 120));
    const std::tuple<int, int, double> taps[] = {{61, 3, 0.5}, {62, 4, 0.7}, {63, 5, 0.8}, {64, 6, 1.0},
                                                 {65, 8, 1.25}, {66, 10, 1.5}, {67, 12, 1.75}};
    for (const auto& [id, size, pitch] : taps) {
        Tool t = make(id, ToolType::Tap, size, tools::named(tools::kTap, size, pitch), 3 * size + 6,
                      5 * size + 25, TAIWA_TRANSLATE_NOOP("taiwa::msg", "Tapping chuck ER32"), 3, 60);
        t.turning.pitchMin = t.turning.pitchMax = pitch;
        t.turning.threadAngle = 60;
        t.pointAngle = 0;
        t.cutting = cuttingFor(ToolType::Drill, size);
        for (auto& c : t.cutting) {
            c.surfaceSpeed /= 10.0;
            c.feedPerTooth = pitch;
            c.plungeFactor = 1.0;
        }
        tools.push_back(t);
    }
    const std::pair<int, double> reamers[] = {{74, 6}, {75, 8}, {76, 10}, {77, 12}};
    for (const auto& [id, d] : reamers) {
        tools.push_back(make(id - 4, ToolType::Drill, d - 0.2, tools::named(tools::kCarbideDrill, d - 0.2),
                             5 * d + 5, 5 * d + 20, TAIWA_TRANSLATE_NOOP("taiwa::msg", "ER32 collet chuck"), 2, 120));
        Tool t = make(id, ToolType::Reamer, d, tools::named(tools::kReamer, d), 3 * d + 10, 5 * d + 30,
                      TAIWA_TRANSLATE_NOOP("taiwa::msg", "HSK63 shrink-fit"), 6, 120);
        t.pointAngle = 0;
        t.cutting = cuttingFor(ToolType::Drill, d);
        for (auto& c : t.cutting) {
            c.surfaceSpeed /= 2.0;
            c.feedPerTooth *= 2.0;
        }
        tools.push_back(t);
    }
    const std::pair<int, double> bores[] = {{80, 16}, {81, 20}, {82, 25}};
    for (const auto& [id, d] : bores) {
        Tool t = make(id, ToolType::BoringBar, d, tools::named(tools::kBoringHead, d), 3 * d, 4 * d + 20,
                      TAIWA_TRANSLATE_NOOP("taiwa::msg", "HSK63 boring head"), 1, 120);
        t.cornerRadius = 0.2;
        t.pointAngle = 0;
        for (auto& c : t.cutting) {
            c.surfaceSpeed *= 0.8;
            c.feedPerTooth = 0.05;
            c.plungeFactor = 1.0;
        }
        tools.push_back(t);
    }
    return tools;
}

// The lathe's tools, T101 on: OD roughing and finishing, ID boring, a
// grooving and a parting blade, a threading insert.
std::vector<Tool> defaultLatheTools()
{
    std::vector<Tool> tools;
    TurningSpec od;
    od.approachAngle = 95;
    od.hand = "right";
    tools.push_back(lathe(101, ToolType::TurningInsert, tools::named(tools::kOdRoughing, "CNMG 120408", 95), "CNMG 120408", 0.8, 12.7, od,
                          "PCLNR 2525M12", false));
    od.approachAngle = 93;
    tools.push_back(lathe(102, ToolType::TurningInsert, tools::named(tools::kOdFinishing, "DNMG 150604", 93), "DNMG 150604", 0.4, 12.7,
                          od, "PDJNR 2525M15", true));
    tools.push_back(lathe(103, ToolType::TurningInsert, tools::named(tools::kOdFinishing, "VCMT 160404", 93), "VCMT 160404", 0.4, 9.525,
                          od, "SVJCR 2525M16", true));
    TurningSpec id = od;
    id.inside = true;
    id.minBore = 16;
    tools.push_back(lathe(104, ToolType::TurningInsert, tools::named(tools::kIdBoring, "DCMT 11T304", 12), "DCMT 11T304", 0.4, 9.525, id,
                          "S12M-SDUCR 11", true));
    TurningSpec groove;
    groove.width = 3;
    groove.maxDepth = 15;
    groove.hand = "neutral";
    tools.push_back(lathe(105, ToolType::Grooving, tools::named(tools::kGrooving, 3, 15), "", 0.2, 3, groove, "GHDR 26-3", true, 0.5));
    TurningSpec part = groove;
    part.maxDepth = 25;
    part.maxDiameter = 50;
    tools.push_back(lathe(106, ToolType::Grooving, tools::named(tools::kParting, 3, 50), "", 0.2, 3, part, TAIWA_TRANSLATE_NOOP("taiwa::msg", "GHDR 26-3 parting"), true, 0.4));
    TurningSpec thread;
    thread.hand = "right";
    thread.pitchMin = 0.5;
    thread.pitchMax = 3.0;
    thread.threadAngle = 60;
    tools.push_back(lathe(107, ToolType::Threading, tools::named(tools::kThreading, 60, 0.5, 3), "", 0.05, 6.35, thread,
                          "SER 2525M16", true));
    return tools;
}

std::vector<Tool> defaultToolLibrary()
{
    std::vector<Tool> tools;
    // T1-T2: centre drills.
    tools.push_back(make(1, ToolType::CentreDrill, 3.15, tools::named(tools::kCentreDrill, 3.15), 4, 30, TAIWA_TRANSLATE_NOOP("taiwa::msg", "ER16 collet chuck"), 2, 240));
    tools.back().pointAngle = 90;
    tools.push_back(make(2, ToolType::CentreDrill, 6.3, tools::named(tools::kCentreDrill, 6.3), 7, 40, TAIWA_TRANSLATE_NOOP("taiwa::msg", "ER16 collet chuck"), 2, 240));
    tools.back().pointAngle = 90;
    // T3-T16: twist drills, solid carbide up to 12 mm, HSS-Co above.
    const double drills[] = {3, 4, 5, 6, 6.8, 8, 8.5, 10, 10.2, 12, 14, 16, 18, 20};
    int id = 3;
    for (const double d : drills) {
        const bool carbide = d <= 12;
        tools.push_back(make(id++, ToolType::Drill, d,
                             tools::named(carbide ? tools::kCarbideDrill : tools::kCobaltDrill, d),
                             carbide ? 5 * d + 5 : 6 * d, carbide ? 5 * d + 20 : 6 * d + 30,
                             carbide ? TAIWA_TRANSLATE_NOOP("taiwa::msg", "ER32 collet chuck") : TAIWA_TRANSLATE_NOOP("taiwa::msg", "Weldon side lock"), 2, carbide ? 120 : 90));
    }
    // T21-T31: flat end mills (centre cutting).
    const double flats[] = {2, 3, 4, 5, 6, 8, 10, 12, 16, 20, 25};
    id = 21;
    for (const double d : flats) {
        tools.push_back(make(id++, ToolType::FlatEndMill, d, tools::named(tools::kFlatEndMill, d),
                             d <= 4 ? 3 * d : 2.5 * d, 3 * d + 15,
                             d <= 12 ? TAIWA_TRANSLATE_NOOP("taiwa::msg", "HSK63 shrink-fit") : "HSK63 Weldon",
                             d <= 5 ? 2 : d <= 16 ? 3 : 4, 120));
    }
    // T41-T47: ball end mills.
    const double balls[] = {2, 3, 4, 6, 8, 10, 12};
    id = 41;
    for (const double d : balls) {
        Tool t = make(id++, ToolType::BallEndMill, d, tools::named(tools::kBallEndMill, d / 2), 2 * d, 3 * d + 15,
                      TAIWA_TRANSLATE_NOOP("taiwa::msg", "HSK63 shrink-fit"), 2, 150);
        t.cornerRadius = d / 2;
        tools.push_back(t);
    }
    // T51-T56: taper end mills, the diameter is the tip's.
    const std::pair<double, double> tapers[] = {{1, 3}, {2, 3}, {3, 4}, {5, 4}, {7, 4}, {10, 6}};
    id = 51;
    for (const auto& [angle, tip] : tapers) {
        Tool t = make(id++, ToolType::TaperEndMill, tip, tools::named(tools::kTaperEndMill, angle, tip), 30,
                      45, TAIWA_TRANSLATE_NOOP("taiwa::msg", "HSK63 shrink-fit"), 3, 90);
        t.taperAngle = angle;
        tools.push_back(t);
    }
    // T60: face mill.
    tools.push_back(make(60, ToolType::FaceMill, 50, tools::named(tools::kFaceMill, 50, 5), 6, 50, TAIWA_TRANSLATE_NOOP("taiwa::msg", "HSK63 shell mill arbor"), 5, 240));
    tools.back().centreCutting = false;  // inserts on the rim only: it cannot plunge
    // T17-T19: the tap drills of M3-M5; T70-T73: the pre-drills of the
    // reamers (0.2 mm under); T61-T67 taps, T74-T77 reamers, T80-T82
    // boring tools set to their bore (module HOLES).
    for (Tool& t : defaultHoleTools()) tools.push_back(std::move(t));
    // T90: touch probe for work-centre probing, 4 mm ruby ball; its length
    // is set to the ball's lowest point. It cuts nothing: no cutting data.
    Tool probe = make(90, ToolType::Probe, 4, tools::named(tools::kProbe, 4), 0, 50, TAIWA_TRANSLATE_NOOP("taiwa::msg", "HSK63 probe body"), 0, 0);
    probe.cutting.clear();
    probe.centreCutting = false;
    tools.push_back(probe);
    for (Tool& t : defaultLatheTools()) tools.push_back(std::move(t));
    // In the order of their ids, as the library reads them back.
    std::stable_sort(tools.begin(), tools.end(), [](const Tool& a, const Tool& b) { return a.id < b.id; });
    return tools;
}

std::string defaultToolLibraryPath()
{
    if (const char* env = std::getenv("TAIWA_TOOL_DB"); env && *env) return env;
    if (const char* xdg = std::getenv("XDG_DATA_HOME"); xdg && *xdg) return std::string(xdg) + "/taiwa/tools.sqlite";
    const char* home = std::getenv("HOME");
    return std::string(home && *home ? home : ".") + "/.local/share/taiwa/tools.sqlite";
}

}  // namespace taiwa
