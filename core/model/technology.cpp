// The shipped technology table (compiled in from resources/technology) and
// the per-job overrides.
#include "model/technology.h"

#include "builtin_data.h"
#include "model/local_names_json.h"
#include "model/result.h"

#include <nlohmann/json.hpp>

#include <cmath>

namespace taiwa {

namespace {
constexpr const char* kTable = "technology table";  // the place every refusal names
}  // namespace

TechnologyTable TechnologyTable::fromJson(const std::string& text)
try {
    const auto doc = nlohmann::json::parse(text);
    if (doc.value("format", "") != "taiwa-technology") throw Refusal("format is not taiwa-technology", Place::inFile(kTable));
    TechnologyTable table;
    for (const auto& m : doc.at("materials")) {
        MaterialTechnology mt;
        mt.id = m.at("id").get<std::string>();
        mt.description = m.value("description", mt.id);
        if (m.contains("names")) {
            auto names = localNamesFrom(m["names"]);
            if (!names) throw Refusal(names.error(), Place::inFile(kTable, 0, "material " + mt.id + ": names"));
            mt.names = std::move(*names);
        }
        auto num = [&](const char* key) {
            if (!m.contains(key) || !m[key].is_number()) throw Refusal(key + std::string(" is missing or not a number"), Place::inFile(kTable, 0, "material " + mt.id));
            const double v = m[key].get<double>();
            if (!std::isfinite(v) || v <= 0) throw Refusal(key + std::string(" must be a positive number"), Place::inFile(kTable, 0, "material " + mt.id));
            return v;
        };
        mt.data.alpha1 = num("alpha1");
        mt.data.alpha2 = num("alpha2");
        mt.data.alpha3 = num("alpha3");
        mt.data.beta2 = num("beta2");
        mt.data.gamma = num("gamma");
        // Turning: optional per material (a table without it turns with the defaults).
        if (m.contains("turning")) {
            const auto& t = m["turning"];
            auto turn = [&](const char* key, double& v) {
                if (!t.contains(key)) return;
                if (!t[key].is_number() || !std::isfinite(t[key].get<double>()) || t[key].get<double>() <= 0)
                    throw Refusal("turning." + std::string(key) + " must be a positive number", Place::inFile(kTable, 0, "material " + mt.id));
                v = t[key].get<double>();
            };
            turn("depthOfCut", mt.data.turning.depthOfCut);
            turn("allowanceX", mt.data.turning.allowanceX);
            turn("allowanceZ", mt.data.turning.allowanceZ);
            turn("retract", mt.data.turning.retract);
            turn("clearance", mt.data.turning.clearance);
            turn("withdrawal", mt.data.turning.withdrawal);
        }
        table.materials_.push_back(std::move(mt));
    }
    return table;
} catch (const nlohmann::json::exception& e) {  // not JSON, or a key missing or of another type
    throw Refusal(e.what(), Place::inFile(kTable));
}

const TechnologyTable& TechnologyTable::builtIn()
{
    static const TechnologyTable table = fromJson(builtin::kMaterialsJson);
    return table;
}

const MaterialTechnology* TechnologyTable::find(const std::string& id) const
{
    for (const auto& m : materials_)
        if (m.id == id) return &m;
    return nullptr;
}

TechnologyData effective(const TechnologyData& base, const TechnologyOverrides& o)
{
    TechnologyData d = base;
    if (o.alpha1) d.alpha1 = *o.alpha1;
    if (o.alpha2) d.alpha2 = *o.alpha2;
    if (o.alpha3) d.alpha3 = *o.alpha3;
    if (o.beta2) d.beta2 = *o.beta2;
    if (o.gamma) d.gamma = *o.gamma;
    if (o.stepOver) d.stepOver = *o.stepOver;
    return d;
}

}  // namespace taiwa
