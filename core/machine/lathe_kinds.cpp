// The two-path and gang-tool lathes' parts of a machine definition
// (lathe_kinds.h): read from the machine file and checked, and the
// conversion of a point between the paths' programs.
#include "machine/lathe_kinds.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <set>
#include <stdexcept>

namespace taiwa {

using json = nlohmann::json;

turning::ZR MultiPath::fromPath1(turning::ZR p, std::size_t to) const
{
    const LathePath& a = paths.at(0);
    const LathePath& b = paths.at(to);
    const turning::ZR machine{a.origin.z + a.zDirection * p.z, a.origin.r + a.xDirection * p.r};
    return {b.zDirection * (machine.z - b.origin.z), b.xDirection * (machine.r - b.origin.r)};
}

turning::ZR MultiPath::toPath1(turning::ZR p, std::size_t from) const
{
    const LathePath& a = paths.at(0);
    const LathePath& b = paths.at(from);
    const turning::ZR machine{b.origin.z + b.zDirection * p.z, b.origin.r + b.xDirection * p.r};
    return {a.zDirection * (machine.z - a.origin.z), a.xDirection * (machine.r - a.origin.r)};
}

const GangPlace* GangSlide::place(int tool) const
{
    for (const auto& p : places)
        if (p.tool == tool) return &p;
    return nullptr;
}

namespace {

// The machine file's key and what is wrong with it; readLatheLayout returns it
// as its Failure ("paths[1].turret: missing").
[[noreturn]] void refuse(const std::string& key, const std::string& what) { throw Refusal(what, Place::atKey(key)); }

double number(const json& o, const char* key, const std::string& path)
{
    const auto it = o.find(key);
    if (it == o.end()) refuse(path, "missing");
    if (!it->is_number() || !std::isfinite(it->get<double>())) refuse(path, "must be a number");
    return it->get<double>();
}

int direction(const json& o, const char* key, const std::string& path)
{
    const auto it = o.find(key);
    if (it == o.end()) return 1;
    if (!it->is_number_integer() || (it->get<int>() != 1 && it->get<int>() != -1)) refuse(path, "must be 1 or -1");
    return it->get<int>();
}

void onlyKeys(const json& o, const std::string& path, const std::set<std::string>& known)
{
    for (const auto& [k, v] : o.items())
        if (!known.contains(k)) refuse(path + k, "unknown key");
}

// A point {"z": …, "x": …}; x as the machine programs it (a diameter when
// `xDiameter`), kept as a radius.
turning::ZR point(const json& o, const char* key, const std::string& path, bool xDiameter)
{
    const auto it = o.find(key);
    if (it == o.end()) refuse(path, "missing");
    if (!it->is_object()) refuse(path, "must be {\"z\": mm, \"x\": mm}");
    onlyKeys(*it, path + ".", {"z", "x"});
    return {number(*it, "z", path + ".z"), number(*it, "x", path + ".x") / (xDiameter ? 2.0 : 1.0)};
}

MultiPath readPaths(const json& m, bool xDiameter)
{
    const json& paths = m["paths"];
    if (!paths.is_array() || paths.size() < 2 || paths.size() > 3)
        refuse("paths", "must be a list of 2 or 3 paths (one turret: leave \"paths\" out)");
    MultiPath mp;
    for (std::size_t i = 0; i < paths.size(); ++i) {
        const json& p = paths[i];
        const std::string at = "paths[" + std::to_string(i) + "]";
        if (!p.is_object()) refuse(at, "must be an object");
        onlyKeys(p, at + ".", {"name", "origin", "direction", "turretStations"});
        LathePath lp;
        if (!p.contains("name") || !p["name"].is_string() || p["name"].get<std::string>().empty())
            refuse(at + ".name", "must be a text");
        lp.name = p["name"].get<std::string>();
        lp.origin = point(p, "origin", at + ".origin", xDiameter);
        if (p.contains("direction")) {
            const json& d = p["direction"];
            if (!d.is_object()) refuse(at + ".direction", "must be {\"z\": 1 or -1, \"x\": 1 or -1}");
            onlyKeys(d, at + ".direction.", {"z", "x"});
            lp.zDirection = direction(d, "z", at + ".direction.z");
            lp.xDirection = direction(d, "x", at + ".direction.x");
        }
        const double stations = number(p, "turretStations", at + ".turretStations");
        if (stations < 1 || stations != std::floor(stations)) refuse(at + ".turretStations", "must be a whole number above zero");
        lp.turretStations = static_cast<int>(stations);
        mp.paths.push_back(lp);
    }
    if (mp.paths[0].xDirection == mp.paths[1].xDirection && mp.paths[0].origin.r == mp.paths[1].origin.r)
        refuse("paths[1].direction.x", "path 2 must face path 1 across the work (X mirrored or its origin across the axis)");
    const auto it = m.find("waitCodes");
    if (it == m.end()) refuse("waitCodes", "missing (the wait M-codes the control offers, {\"first\": 101, \"last\": 199})");
    if (!it->is_object()) refuse("waitCodes", "must be {\"first\": n, \"last\": n}");
    onlyKeys(*it, "waitCodes.", {"first", "last"});
    const double first = number(*it, "first", "waitCodes.first"), last = number(*it, "last", "waitCodes.last");
    if (first < 1 || first != std::floor(first) || first > 9999) refuse("waitCodes.first", "must be a whole M number from 1 to 9999");
    if (last < first || last != std::floor(last) || last > 9999)
        refuse("waitCodes.last", "must be a whole M number from waitCodes.first to 9999");
    mp.waitCodes = {static_cast<int>(first), static_cast<int>(last)};
    return mp;
}

GangSlide readGang(const json& m, bool xDiameter)
{
    const json& g = m["gangSlide"];
    if (!g.is_object()) refuse("gangSlide", "must be an object");
    onlyKeys(g, "gangSlide.", {"clearance", "tools"});
    GangSlide slide;
    slide.clearance = number(g, "clearance", "gangSlide.clearance");
    if (!(slide.clearance > 0)) refuse("gangSlide.clearance", "must be a number above zero");
    const auto it = g.find("tools");
    if (it == g.end() || !it->is_array() || it->empty()) refuse("gangSlide.tools", "must be a list of the tools on the slide");
    for (std::size_t i = 0; i < it->size(); ++i) {
        const json& t = (*it)[i];
        const std::string at = "gangSlide.tools[" + std::to_string(i) + "]";
        if (!t.is_object()) refuse(at, "must be {\"tool\": n, \"offset\": {\"z\": mm, \"x\": mm}}");
        onlyKeys(t, at + ".", {"tool", "offset"});
        const double tool = number(t, "tool", at + ".tool");
        if (tool < 1 || tool != std::floor(tool)) refuse(at + ".tool", "must be a whole tool number above zero");
        GangPlace p;
        p.tool = static_cast<int>(tool);
        if (slide.place(p.tool)) refuse(at + ".tool", "tool " + std::to_string(p.tool) + " is on the slide twice");
        p.offset = point(t, "offset", at + ".offset", xDiameter);
        slide.places.push_back(p);
    }
    return slide;
}

}  // namespace

Result<LatheLayout> readLatheLayout(const json& machine)
{
    try {
        LatheLayout l;
        const bool xDiameter = machine.value("xDiameter", true);
        if (machine.contains("paths")) l.multiPath = readPaths(machine, xDiameter);
        else if (machine.contains("waitCodes")) refuse("waitCodes", "only a lathe with \"paths\" waits");
        if (machine.contains("gangSlide")) {
            if (l.multiPath) refuse("gangSlide", "a two-path lathe with a gang slide is not modelled");
            l.gang = readGang(machine, xDiameter);
        }
        return l;
    } catch (const Refusal& e) {
        return e.failure();
    }
}

}  // namespace taiwa
