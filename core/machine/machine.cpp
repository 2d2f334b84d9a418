// The machine library (machine.h): the shipped definitions, read and checked.
#include "machine/machine.h"

#include "builtin_data.h"
#include "io/data_files.h"
#include "io/data_reader.h"
#include "model/local_names_json.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <regex>
#include <stdexcept>

namespace taiwa {

const char* toKey(MachineKind k) { return k == MachineKind::Lathe ? "lathe" : "mill"; }

namespace {

using json = nlohmann::json;

// The ranges a machine's values are read in: wide enough for any machine
// tool, narrow enough that no time, length or count derived from them
// overflows or prints as a 300-digit number.
constexpr double kMaxTravel = 100000.0;     // mm from the machine's zero
constexpr double kMinRate = 1.0, kMaxRate = 1.0e6;  // feeds and rapids, mm/min
constexpr double kMaxSpindle = 200000.0;    // rpm
constexpr double kMinAcceleration = 1.0, kMaxAcceleration = 1.0e6;  // mm/s²
constexpr double kMaxChuck = 10000.0;       // mm

// Every key of a machine definition (docs/machines.md).
constexpr const char* kKeys[] = {"format", "version", "id", "name", "names", "kind", "travel", "maxSpindleSpeed",
                                 "maxFeed", "rapid", "toolChanger", "turret", "chuck", "xDiameter", "paths", "waitCodes",
                                 "gangSlide", "acceleration", "lookAhead", "cornerTolerance", "coolant"};

class Reader {
public:
    Reader(const std::string& text, const std::string& source) : r_(text, source) {}

    // A number above zero, within [low, high].
    double positive(const json& v, const std::string& path, double low, double high, const char* unit) const
    {
        if (!v.is_number() || !(v.get<double>() > 0.0)) r_.fail(path, "must be a number above zero");
        const double d = v.get<double>();
        if (!(d >= low && d <= high))
            r_.fail(path, "must be from " + io::shortNumber(low) + " to " + io::shortNumber(high) + " " + unit + ", not " + io::shortNumber(d));
        return d;
    }

    Machine read() const
    {
        const json& j = r_.root();
        if (r_.text("format", "") != "taiwa-machine") r_.fail("format", "must be \"taiwa-machine\"");
        // A key this program does not read is a typo whose value would be
        // silently ignored (a "maxSpindelSpeed" of 3000 and the tape at 9549 rpm).
        for (const auto& [key, value] : j.items())
            if (std::find(std::begin(kKeys), std::end(kKeys), key) == std::end(kKeys))
                r_.fail(key, "not a key of a machine definition (a typo?)");
        const json& version = r_.at(j, "version", "version");
        if (!version.is_number_integer() || version.get<long long>() != 1)
            r_.fail("version", "this program reads machine definitions of version 1");
        Machine m;
        m.source = r_.source();
        m.id = r_.identifier("id");
        m.name = r_.text(r_.at(j, "name", "name"), "name", 80, false);
        if (const json* names = r_.find(j, "names")) {
            auto local = localNamesFrom(*names);
            if (!local) r_.fail("names", local.error());
            for (const auto& [language, text] : *local)
                if (text.size() > 200 || !io::printable(text)) r_.fail("names." + language, "must be printable text of at most 200 bytes");
            m.names = std::move(*local);
        }
        const std::string kind = r_.text(r_.at(j, "kind", "kind"), "kind", 20, false);
        if (kind == "mill") m.kind = MachineKind::Mill;
        else if (kind == "lathe") m.kind = MachineKind::Lathe;
        else r_.fail("kind", "must be \"mill\" or \"lathe\", not \"" + kind + "\"");
        const json& travel = r_.at(j, "travel", "travel");
        if (!travel.is_object()) r_.fail("travel", "must be an object of axes");
        const std::vector<std::string> axes =
            m.kind == MachineKind::Lathe ? std::vector<std::string>{"x", "z"} : std::vector<std::string>{"x", "y", "z"};
        for (const auto& [axis, range] : travel.items()) {
            const std::string path = "travel." + axis;
            if (!range.is_array() || range.size() != 2) r_.fail(path, "must be [min, max] in mm with min below max");
            const double lo = r_.number(range[0], path + "[0]", -kMaxTravel, kMaxTravel, false);
            const double hi = r_.number(range[1], path + "[1]", -kMaxTravel, kMaxTravel, false);
            if (!(lo < hi)) r_.fail(path, "must be [min, max] in mm with min below max");
            m.travel[axis] = {lo, hi};
        }
        for (const auto& a : axes)
            if (!m.travel.contains(a)) r_.fail("travel." + a, "missing");
        m.maxSpindleSpeed = positive(r_.at(j, "maxSpindleSpeed", "maxSpindleSpeed"), "maxSpindleSpeed", 1.0, kMaxSpindle, "rpm");
        m.maxFeed = positive(r_.at(j, "maxFeed", "maxFeed"), "maxFeed", kMinRate, kMaxRate, "mm/min");
        const json& rapid = r_.at(j, "rapid", "rapid");
        if (!rapid.is_object()) r_.fail("rapid", "must be an object of axes");
        for (const auto& a : axes) m.rapid[a] = positive(r_.at(rapid, a, "rapid." + a), "rapid." + a, kMinRate, kMaxRate, "mm/min");
        const auto count = [&](const json& o, const char* key, const std::string& path) {
            if (!o.is_object()) r_.fail(path.substr(0, path.find('.')), "must be an object");
            return static_cast<int>(r_.whole(r_.at(o, key, path), path, 1, 10000));
        };
        const auto length = [&](const json& o, const char* key, const std::string& path) {
            return positive(r_.at(o, key, path), path, 0.001, kMaxChuck, "mm");
        };
        if (m.kind == MachineKind::Lathe) {
            if (const json* x = r_.find(j, "xDiameter")) {
                if (!x->is_boolean()) r_.fail("xDiameter", "must be true or false");
                m.xDiameter = x->get<bool>();
            } else {
                m.xDiameter = true;
            }
            m.turretStations = count(r_.at(j, "turret", "turret"), "stations", "turret.stations");
            const json& chuck = r_.at(j, "chuck", "chuck");
            if (!chuck.is_object()) r_.fail("chuck", "must be an object");
            m.chuckDiameter = length(chuck, "diameter", "chuck.diameter");
            m.maxBarDiameter = length(chuck, "maxBarDiameter", "chuck.maxBarDiameter");
            m.jawLength = length(chuck, "jawLength", "chuck.jawLength");
            auto layout = readLatheLayout(j);  // two paths, a gang slide (lathe_kinds.h)
            if (!layout) {
                const std::string& e = layout.error();
                r_.fail(e.substr(0, e.find(": ")), e.substr(e.find(": ") + 2));
            }
            m.layout = std::move(*layout);
        } else {
            m.toolPockets = count(r_.at(j, "toolChanger", "toolChanger"), "pockets", "toolChanger.pockets");
        }
        if (const json* acc = r_.find(j, "acceleration")) {
            if (!acc->is_object()) r_.fail("acceleration", "must be an object of axes");
            for (const auto& a : axes)
                m.acceleration[a] = positive(r_.at(*acc, a, "acceleration." + a), "acceleration." + a, kMinAcceleration,
                                             kMaxAcceleration, "mm/s²");
        }
        if (const json* v = r_.find(j, "lookAhead")) {
            if (!v->is_number_integer() && !v->is_number_unsigned())
                r_.fail("lookAhead", "must be a whole number of blocks from 1 to 10000");
            m.lookAhead = static_cast<int>(r_.whole(*v, "lookAhead", 1, 10000));
        }
        if (const json* v = r_.find(j, "cornerTolerance")) m.cornerTolerance = positive(*v, "cornerTolerance", 1e-6, 10.0, "mm");
        if (const json* coolant = r_.find(j, "coolant")) {
            if (!coolant->is_object()) r_.fail("coolant", "must be an object");
            static const std::regex mWords(R"(\s*([Mm][0-9]{1,3}\s*)+)");
            for (auto [key, field] : {std::pair{"flood", &m.coolantOn}, std::pair{"off", &m.coolantOff}}) {
                const std::string path = std::string("coolant.") + key;
                *field = r_.text(r_.at(*coolant, key, path), path, 40, false);
                if (!std::regex_match(*field, mWords)) r_.fail(path, "must be M words only (as \"M8\"), not '" + *field + "'");
            }
        }
        return m;
    }

private:
    io::DataReader r_;
};

}  // namespace

Result<Machine> readMachine(const std::string& text, const std::string& source)
{
    return io::readData<Reader>(text, source);
}

std::string userMachineFolder() { return io::userDataFolder("machines"); }

namespace {

// The shipped definitions, then the user's: a user file of a known id
// replaces the shipped one, a new id adds a machine; a broken file is left
// out with its problem, the shipped ones stay.
const io::DataLibrary<Machine>& library()
{
    static const auto lib = io::loadDataLibrary<Machine>(builtin::kMachines, userMachineFolder(), readMachine,
                                                         [](const Machine& m) { return m.id; }, "machines");
    return lib;
}

}  // namespace

const std::vector<Machine>& machineLibrary() { return library().items; }
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
