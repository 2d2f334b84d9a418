// The shipped technology table (compiled in from resources/technology) and
// the per-job overrides.
#include "model/technology.h"

#include "builtin_data.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <stdexcept>

namespace taiwa {

TechnologyTable TechnologyTable::fromJson(const std::string& text)
{
    const auto doc = nlohmann::json::parse(text);
    if (doc.value("format", "") != "taiwa-technology") throw std::runtime_error("technology table: format is not taiwa-technology");
    TechnologyTable table;
    for (const auto& m : doc.at("materials")) {
        MaterialTechnology mt;
        mt.id = m.at("id").get<std::string>();
        mt.description = m.value("description", mt.id);
        auto num = [&](const char* key) {
            if (!m.contains(key) || !m[key].is_number()) throw std::runtime_error("technology table: material " + mt.id + ": " + key + " is missing or not a number");
            const double v = m[key].get<double>();
            if (!std::isfinite(v) || v <= 0) throw std::runtime_error("technology table: material " + mt.id + ": " + key + " must be a positive number");
            return v;
        };
        mt.data = {num("alpha1"), num("alpha2"), num("alpha3"), num("beta2"), num("gamma")};
        table.materials_.push_back(std::move(mt));
    }
    return table;
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
