// The technology table's look-up and the per-job overrides; the table's
// file is read in io/technology_file.cpp.
#include "model/technology.h"

namespace taiwa {

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
