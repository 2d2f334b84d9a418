// The tool change log of an SQLite library, the tool as JSON, the fields an
// edit changes and the name that no longer states the size
// (tool_change_log.h).
#include "tools/tool_change_log.h"

#include "model/translate_noop.h"
#include "tools/tool_library_sqlite.h"
#include "tools/tool_store.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <sqlite3.h>

#include <cmath>
#include <cstdlib>
#include <ctime>
#include <pwd.h>
#include <regex>
#include <unistd.h>

namespace taiwa {

namespace {

using ordered = nlohmann::ordered_json;

ordered toolObject(const Tool& t)
{
    ordered j;
    j["id"] = t.id;
    j["name"] = t.name;
    j["names"] = t.names;
    j["type"] = toKey(t.type);
    j["diameter"] = t.diameter;
    j["cornerRadius"] = t.cornerRadius;
    j["taperAngle"] = t.taperAngle;
    j["pointAngle"] = t.pointAngle;
    j["fluteLength"] = t.fluteLength;
    j["stickout"] = t.stickout;
    j["holder"] = t.holder;
    j["holderDiameter"] = t.holderDiameter;
    j["holderLength"] = t.holderLength;
    j["flutes"] = t.flutes;
    j["centreCutting"] = t.centreCutting;
    j["lifeMinutes"] = t.lifeMinutes;
    j["usedMinutes"] = t.usedMinutes;
    j["cutting"] = ordered::array();
    for (const auto& c : t.cutting)
        j["cutting"].push_back({{"material", c.material},
                                {"surfaceSpeed", c.surfaceSpeed},
                                {"feedPerTooth", c.feedPerTooth},
                                {"plungeFactor", c.plungeFactor}});
    const TurningSpec& s = t.turning;
    j["turning"] = {{"insertCode", s.insertCode}, {"approachAngle", s.approachAngle}, {"hand", s.hand},
                    {"inside", s.inside},         {"minBore", s.minBore},             {"width", s.width},
                    {"maxDepth", s.maxDepth},     {"maxDiameter", s.maxDiameter},     {"pitchMin", s.pitchMin},
                    {"pitchMax", s.pitchMax},     {"threadAngle", s.threadAngle}};
    return j;
}

// A value as the dialog shows it: numbers without a trailing ".0", texts bare.
std::string shown(const ordered& v)
{
    if (v.is_string()) return v.get<std::string>();
    if (v.is_number_float()) return fmt::format("{}", v.get<double>());  // shortest: 8, 12.5
    return v.dump();
}

std::string userName()
{
    if (const passwd* p = ::getpwuid(::getuid()); p && p->pw_name && *p->pw_name) return p->pw_name;
    if (const char* u = std::getenv("USER"); u && *u) return u;
    return "?";
}

}  // namespace

std::string utcNow()
{
    const std::time_t t = std::time(nullptr);
    std::tm tm{};
    gmtime_r(&t, &tm);
    char buf[32];
    std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
    return buf;
}

std::string toolJson(const Tool& t) { return toolObject(t).dump(); }

std::vector<ToolFieldChange> toolChanges(const Tool& before, const Tool& after)
{
    const ordered a = toolObject(before), b = toolObject(after);
    std::vector<ToolFieldChange> out;
    for (auto it = a.begin(); it != a.end(); ++it)
        if (b.at(it.key()) != it.value()) out.push_back({it.key(), shown(it.value()), shown(b.at(it.key()))});
    return out;
}

std::optional<std::string> nameSizeMismatch(const Tool& t)
{
    // Lathe inserts are sized by their code, probes by their ball: the name's
    // millimetres say something else (a holder, a bore).
    const bool sized = t.type != ToolType::TurningInsert && t.type != ToolType::Grooving &&
                       t.type != ToolType::Threading && t.type != ToolType::Probe;
    if (!sized || !(t.diameter > 0.0)) return std::nullopt;
    // "8 mm", "8mm", "12.5 mm", "Ø8", "D8" (not part of a word or of a longer number).
    static const std::regex size(R"((?:^|[^0-9A-Za-z.])(?:(?:Ø|D)\s?([0-9]+(?:[.,][0-9]+)?)|([0-9]+(?:[.,][0-9]+)?)\s?mm\b))");
    std::vector<double> stated;
    for (std::sregex_iterator m(t.name.begin(), t.name.end(), size), end; m != end; ++m) {
        std::string n = (*m)[1].matched ? (*m)[1].str() : (*m)[2].str();
        for (char& c : n)
            if (c == ',') c = '.';
        stated.push_back(std::strtod(n.c_str(), nullptr));
    }
    if (stated.empty()) return std::nullopt;
    for (double d : stated)
        if (std::abs(d - t.diameter) <= 1e-3) return std::nullopt;
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the name says {:g} mm, the diameter is {:g} mm"), stated.front(),
                       t.diameter);
}

Result<void> logToolChange(sqlite3* db, const std::string& operation, int toolId, const std::string& oldValues,
                           const std::string& newValues)
{
    bool done = false;
    {
        tooldb::Statement s(db, "INSERT INTO tool_changes (tool_id, operation, who, station, at, old_values, new_values) "
                                "VALUES (?, ?, ?, ?, ?, ?, ?)");
        if (!s.ok()) return Failure{sqlite3_errmsg(db)};
        const std::string who = userName(), station = stationName(), at = utcNow();
        s.bind(1, toolId);
        int i = 2;
        for (const std::string* v : {&operation, &who, &station, &at, &oldValues, &newValues})
            s.bind(i++, *v);
        done = s.step() == SQLITE_DONE;
    }  // finalized before SQLite's message is read
    if (!done) return Failure{sqlite3_errmsg(db)};
    return {};
}

Result<std::vector<ToolChangeRecord>> readToolChanges(sqlite3* db, int toolId)
{
    std::vector<ToolChangeRecord> out;
    int rc = SQLITE_ROW;
    {
        tooldb::Statement s(db, "SELECT operation, who, station, at, old_values, new_values FROM tool_changes "
                                "WHERE tool_id = ? ORDER BY rowid");
        if (!s.ok()) return Failure{sqlite3_errmsg(db)};
        s.bind(1, toolId);
        while ((rc = s.step()) == SQLITE_ROW)
            out.push_back({s.text(0), s.text(1), s.text(2), s.text(3), s.text(4), s.text(5)});
    }  // finalized before SQLite's message is read
    if (rc != SQLITE_DONE) return Failure{sqlite3_errmsg(db)};
    return out;
}

}  // namespace taiwa
