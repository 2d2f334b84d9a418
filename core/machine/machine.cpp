// The machine library (machine.h): the shipped definitions, read and checked.
#include "machine/machine.h"

#include "builtin_data.h"
#include "io/data_files.h"
#include "model/local_names_json.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <stdexcept>

namespace taiwa {

const char* toKey(MachineKind k) { return k == MachineKind::Lathe ? "lathe" : "mill"; }

namespace {

using json = nlohmann::json;

using io::lineOfKey;

class Reader {
public:
    Reader(const json& j, std::string source, const std::string& text) : j_(j), source_(std::move(source)), text_(text) {}

    // "FILE:LINE: key: what" (no line for a key that is missing).
    [[noreturn]] void fail(const std::string& key, const std::string& what) const
    {
        const int line = lineOfKey(text_, key);
        throw std::runtime_error(source_ + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " + key + ": " + what);
    }
    const json& at(const json& o, const std::string& key, const std::string& path) const
    {
        const auto it = o.find(key);
        if (it == o.end()) fail(path, "missing");
        return *it;
    }
    std::string string(const json& o, const std::string& key, const std::string& path) const
    {
        const json& v = at(o, key, path);
        if (!v.is_string() || v.get<std::string>().empty()) fail(path, "must be a text");
        return v.get<std::string>();
    }
    double positive(const json& o, const std::string& key, const std::string& path) const
    {
        const json& v = at(o, key, path);
        if (!v.is_number() || !(v.get<double>() > 0.0)) fail(path, "must be a number above zero");
        return v.get<double>();
    }

    Machine read() const
    {
        if (!j_.is_object()) fail("(file)", "not a JSON object");
        if (j_.value("format", "") != "taiwa-machine") fail("format", "must be \"taiwa-machine\"");
        if (!j_.contains("version") || !j_["version"].is_number_integer() || j_["version"].get<int>() != 1)
            fail("version", "this program reads machine definitions of version 1");
        Machine m;
        m.source = source_;
        m.id = string(j_, "id", "id");
        m.name = string(j_, "name", "name");
        if (j_.contains("names")) {
            auto names = localNamesFrom(j_["names"]);
            if (!names) fail("names", names.error());
            m.names = std::move(*names);
        }
        const std::string kind = string(j_, "kind", "kind");
        if (kind == "mill") m.kind = MachineKind::Mill;
        else if (kind == "lathe") m.kind = MachineKind::Lathe;
        else fail("kind", "must be \"mill\" or \"lathe\", not \"" + kind + "\"");
        const json& travel = at(j_, "travel", "travel");
        if (!travel.is_object()) fail("travel", "must be an object of axes");
        for (const auto& [axis, range] : travel.items()) {
            if (!range.is_array() || range.size() != 2 || !range[0].is_number() || !range[1].is_number() ||
                !(range[0].get<double>() < range[1].get<double>()))
                fail("travel." + axis, "must be [min, max] in mm with min below max");
            m.travel[axis] = {range[0].get<double>(), range[1].get<double>()};
        }
        const std::vector<std::string> axes =
            m.kind == MachineKind::Lathe ? std::vector<std::string>{"x", "z"} : std::vector<std::string>{"x", "y", "z"};
        for (const auto& a : axes)
            if (!m.travel.contains(a)) fail("travel." + a, "missing");
        m.maxSpindleSpeed = positive(j_, "maxSpindleSpeed", "maxSpindleSpeed");
        m.maxFeed = positive(j_, "maxFeed", "maxFeed");
        const json& rapid = at(j_, "rapid", "rapid");
        for (const auto& a : axes) m.rapid[a] = positive(rapid, a, "rapid." + a);
        if (m.kind == MachineKind::Lathe) {
            m.xDiameter = j_.value("xDiameter", true);
            m.turretStations = static_cast<int>(positive(at(j_, "turret", "turret"), "stations", "turret.stations"));
            const json& chuck = at(j_, "chuck", "chuck");
            m.chuckDiameter = positive(chuck, "diameter", "chuck.diameter");
            m.maxBarDiameter = positive(chuck, "maxBarDiameter", "chuck.maxBarDiameter");
            m.jawLength = positive(chuck, "jawLength", "chuck.jawLength");
            auto layout = readLatheLayout(j_);  // two paths, a gang slide (lathe_kinds.h)
            if (!layout) {
                const std::string& e = layout.error();
                fail(e.substr(0, e.find(": ")), e.substr(e.find(": ") + 2));
            }
            m.layout = std::move(*layout);
        } else {
            m.toolPockets = static_cast<int>(positive(at(j_, "toolChanger", "toolChanger"), "pockets", "toolChanger.pockets"));
        }
        if (j_.contains("acceleration")) {
            const json& acc = j_["acceleration"];
            if (!acc.is_object()) fail("acceleration", "must be an object of axes");
            for (const auto& a : axes) m.acceleration[a] = positive(acc, a, "acceleration." + a);
        }
        if (j_.contains("lookAhead")) {
            const json& v = j_["lookAhead"];
            if (!v.is_number_integer() || v.get<int>() < 1 || v.get<int>() > 10000)
                fail("lookAhead", "must be a whole number of blocks from 1 to 10000");
            m.lookAhead = v.get<int>();
        }
        if (j_.contains("cornerTolerance")) m.cornerTolerance = positive(j_, "cornerTolerance", "cornerTolerance");
        if (j_.contains("coolant")) {
            m.coolantOn = string(j_["coolant"], "flood", "coolant.flood");
            m.coolantOff = string(j_["coolant"], "off", "coolant.off");
        }
        return m;
    }

private:
    const json& j_;
    std::string source_;
    const std::string& text_;
};

}  // namespace

Result<Machine> readMachine(const std::string& text, const std::string& source)
{
    json j;
    try {
        j = json::parse(text);
    } catch (const json::parse_error& e) {
        return Failure{source + ":" + std::to_string(io::lineOfByte(text, e.byte)) + ": not valid JSON"};
    }
    try {
        return Reader(j, source, text).read();
    } catch (const std::runtime_error& e) {
        return Failure{e.what()};
    }
}

std::string userMachineFolder() { return io::userDataFolder("machines"); }

namespace {

struct Library {
    std::vector<Machine> machines;
    std::vector<std::string> problems;
};

// The shipped definitions, then the user's: a user file of a known id
// replaces the shipped one, a new id adds a machine; a broken file is left
// out with its problem, the shipped ones stay.
const Library& library()
{
    static const Library lib = [] {
        Library l;
        for (const auto& [text, source] : builtin::kMachines) {
            auto m = readMachine(text, source);
            if (!m) throw std::logic_error("a shipped machine definition is broken: " + m.error());
            l.machines.push_back(std::move(*m));
        }
        io::addShopFiles(l.machines, l.problems, userMachineFolder(), readMachine, [](const Machine& m) { return m.id; },
                         "machines");
        return l;
    }();
    return lib;
}

}  // namespace

const std::vector<Machine>& machineLibrary() { return library().machines; }
const std::vector<std::string>& machineLibraryProblems() { return library().problems; }

const Machine* findMachine(const std::string& id)
{
    for (const auto& m : machineLibrary())
        if (m.id == id) return &m;
    return nullptr;
}

std::vector<std::string> machineIds()
{
    std::vector<std::string> ids;
    for (const auto& m : machineLibrary()) ids.push_back(m.id);
    return ids;
}

}  // namespace taiwa
