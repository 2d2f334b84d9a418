// Module TURN's keys in the job file (docs/job-format.md): its profile
// table, grinding-allowance table, pinned tools and skipped steps read with
// unknown keys refused, and written in canonical order (turn_file.h).
#include "modules/turn/turn_file.h"

#include "check/messages.h"
#include "io/job_messages.h"
#include "io/json_objects.h"
#include "io/json_write.h"
#include "model/translate_noop.h"

#include <fmt/format.h>

namespace taiwa {

using namespace turning;
using ordered = nlohmann::ordered_json;

namespace {

const std::vector<std::string> kUnitKeys{"module", "name", "side", "start", "rows", "allowances", "tools", "skip", "cutting"};
const std::vector<std::string> kRowKeys{"id",     "kind",   "x",          "z",         "radius",
                                        "centreX", "centreZ", "corner", "cornerSize", "roughness", "tolerance", "thread"};
const std::vector<std::string> kAllowanceKeys{"edge", "allowance", "adjustment", "groove", "grooveWidth", "grooveDepth"};
const std::vector<std::string> kSides{"outer", "inner"};
const std::vector<std::string> kKinds{"line", "cw", "ccw"};
const std::vector<std::string> kCorners{"none", "chamfer", "rounding"};
const std::vector<std::string> kGrooves{"auto", "none", "lateral", "longitudinal", "ring"};

std::size_t optionalChoice(const io::ObjectFields& f, const char* key, const std::vector<std::string>& allowed)
{
    return f.find(key) ? f.choice(key, allowed).value_or(0) : 0;
}

using io::number;

}  // namespace

TurnUnit readTurnUnit(const io::ObjectFields& f)
{
    TurnUnit t;
    TurnedProfile& p = t.profile;
    f.rejectUnknown(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a TURN unit"), kUnitKeys);
    p.side = optionalChoice(f, "side", kSides) == 1 ? ProfileSide::Inner : ProfileSide::Outer;
    if (const auto s = io::objectAt(f, "start", "an object {\"x\": diameter, \"z\": Z}")) {
        s->rejectUnknown(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the start point"), {"x", "z"});
        p.startX = s->number("x", 0.0);
        p.startZ = s->number("z", 0.0);
    }
    io::eachObject(f, "rows", TAIWA_TRANSLATE_NOOP("taiwa::msg", "an array of profile rows"), true,
               [&](const io::ObjectFields& r, std::size_t i) {
        r.rejectUnknown(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a profile row"), kRowKeys);
        ProfileRow row;
        row.id = r.whole("id", static_cast<int>(i) + 1);
        row.kind = static_cast<ElementKind>(optionalChoice(r, "kind", kKinds));
        row.x = r.number("x").value_or(0.0);
        row.z = r.number("z").value_or(0.0);
        row.radius = r.optionalNumber("radius");
        row.centreX = r.optionalNumber("centreX");
        row.centreZ = r.optionalNumber("centreZ");
        row.corner = static_cast<CornerKind>(optionalChoice(r, "corner", kCorners));
        row.cornerSize = r.number("cornerSize", 0.0);
        row.attributes.roughness = r.optionalNumber("roughness");
        row.attributes.tolerance = r.string("tolerance", "");
        if (const auto th = io::objectAt(r, "thread", "an object {\"pitch\": mm, \"depth\": mm}")) {
            th->rejectUnknown(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a thread"), {"pitch", "depth"});
            row.attributes.thread = ThreadSpec{th->number("pitch").value_or(0.0), th->optionalNumber("depth")};
        }
        p.rows.push_back(row);
    });
    io::eachObject(f, "allowances", TAIWA_TRANSLATE_NOOP("taiwa::msg", "an array of grinding-allowance rows"), false,
               [&](const io::ObjectFields& a, std::size_t) {
        a.rejectUnknown(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a grinding-allowance row"), kAllowanceKeys);
        AllowanceRow row;
        row.edge = a.string("edge").value_or("");
        row.allowance = a.number("allowance").value_or(0.0);
        row.adjustment = a.optionalNumber("adjustment");
        row.groove = static_cast<GrooveKind>(optionalChoice(a, "groove", kGrooves));
        row.grooveWidth = a.optionalNumber("grooveWidth");
        row.grooveDepth = a.optionalNumber("grooveDepth");
        p.allowances.push_back(row);
    });
    t.tools = f.wholeMap("tools");
    if (const auto* skip = f.find("skip")) {
        if (!skip->is_array()) {
            f.error("skip",
                    msg::io::wrongType(TAIWA_TRANSLATE_NOOP("taiwa::msg", "an array of step names"), *skip));
        } else {
            for (std::size_t i = 0; i < skip->size(); ++i) {
                if ((*skip)[i].is_string()) t.skip.push_back((*skip)[i].get<std::string>());
                else
                    f.error(fmt::format("skip[{}]", i + 1),
                            msg::io::wrongType(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a step name"), (*skip)[i]));
            }
        }
    }
    return t;
}

void writeTurnUnit(const TurnUnit& t, nlohmann::ordered_json& u)
{
    const TurnedProfile& p = t.profile;
    u["side"] = toKey(p.side);
    u["start"] = {{"x", number(p.startX)}, {"z", number(p.startZ)}};
    u["rows"] = ordered::array();
    for (const auto& r : p.rows) {
        ordered j;
        j["id"] = r.id;
        j["kind"] = toKey(r.kind);
        j["x"] = number(r.x);
        j["z"] = number(r.z);
        if (r.radius) j["radius"] = number(*r.radius);
        if (r.centreX) j["centreX"] = number(*r.centreX);
        if (r.centreZ) j["centreZ"] = number(*r.centreZ);
        if (r.corner != CornerKind::None) j["corner"] = toKey(r.corner);
        if (r.corner != CornerKind::None || r.cornerSize != 0.0) j["cornerSize"] = number(r.cornerSize);
        if (r.attributes.roughness) j["roughness"] = number(*r.attributes.roughness);
        if (!r.attributes.tolerance.empty()) j["tolerance"] = r.attributes.tolerance;
        if (const auto& th = r.attributes.thread) {
            ordered spec;
            spec["pitch"] = number(th->pitch);
            if (th->depth) spec["depth"] = number(*th->depth);
            j["thread"] = std::move(spec);
        }
        u["rows"].push_back(std::move(j));
    }
    if (!t.tools.empty()) u["tools"] = io::pins(t.tools);
    if (!t.skip.empty()) u["skip"] = t.skip;
    if (p.allowances.empty()) return;
    u["allowances"] = ordered::array();
    for (const auto& a : p.allowances) {
        ordered j;
        j["edge"] = a.edge;
        j["allowance"] = number(a.allowance);
        if (a.adjustment) j["adjustment"] = number(*a.adjustment);
        if (a.groove != GrooveKind::Auto) j["groove"] = toKey(a.groove);
        if (a.grooveWidth) j["grooveWidth"] = number(*a.grooveWidth);
        if (a.grooveDepth) j["grooveDepth"] = number(*a.grooveDepth);
        u["allowances"].push_back(std::move(j));
    }
}

}  // namespace taiwa
