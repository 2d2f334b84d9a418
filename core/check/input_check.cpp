// Input processing entry points: checkJob runs the job-level checks (material,
// stock, technology overrides), every unit's checks and the interference
// check, collecting all diagnostics (capped); jobTechnology gives the
// technology data in force.
#include "check/input_check.h"

#include "check/messages.h"
#include "check/unit_checks.h"

#include <cmath>

namespace taiwa {

namespace {

constexpr std::size_t kMaxDiagnostics = 100;

Diagnostic jobError(std::string field, std::string message)
{
    return {Severity::Error, std::nullopt, "", std::move(field), std::move(message)};
}

// Stock dimensions finite and positive; returns whether the stock is usable.
bool checkStock(const Stock& mm, LengthUnit shown, Diagnostics& out)
{
    bool ok = true;
    const std::pair<const char*, double> origin[] = {{"x", mm.x}, {"y", mm.y}};
    for (const auto& [key, v] : origin)
        if (!std::isfinite(v)) out.push_back(jobError(std::string("stock.") + key, msg::notFinite(std::string("the stock ") + key))), ok = false;
    const std::pair<const char*, double> sizes[] = {{"width", mm.width}, {"length", mm.length}, {"height", mm.height}};
    for (const auto& [key, v] : sizes) {
        const std::string field = std::string("stock.") + key;
        if (!std::isfinite(v)) out.push_back(jobError(field, msg::notFinite("the stock " + std::string(key)))), ok = false;
        else if (v <= 0.0) out.push_back(jobError(field, msg::stockNotPositive(key, {v, shown}))), ok = false;
    }
    return ok;
}

// Overrides finite and positive (lengths quoted in the job's unit, gamma as is).
bool checkOverrides(const TechnologyOverrides& mm, LengthUnit shown, Diagnostics& out)
{
    bool ok = true;
    const std::tuple<const char*, const char*, std::optional<double>> values[] = {
        {"alpha1", "α1", mm.alpha1}, {"alpha2", "α2", mm.alpha2}, {"alpha3", "α3", mm.alpha3},
        {"beta2", "β2", mm.beta2},   {"gamma", "γ", mm.gamma}};
    for (const auto& [key, name, v] : values) {
        if (!v) continue;
        const std::string field = std::string("technology.") + key;
        const bool isGamma = std::string(key) == "gamma";
        if (!std::isfinite(*v)) out.push_back(jobError(field, msg::notFinite(name))), ok = false;
        else if (*v <= 0.0)
            out.push_back(jobError(field, msg::technologyNotPositive(name, isGamma ? *v : fromMm(*v, shown),
                                                                     isGamma ? "" : std::string(" ") + unitSymbol(shown)))),
                ok = false;
    }
    return ok;
}

}  // namespace

std::optional<TechnologyData> jobTechnology(const Job& mmJob, const TechnologyTable& table)
{
    const MaterialTechnology* m = table.find(mmJob.material);
    if (!m) return std::nullopt;
    return effective(m->data, mmJob.technology);
}

Diagnostics checkJob(const Job& job, const TechnologyTable& table, const std::vector<Tool>& library)
{
    const Job mm = toMillimetres(job);
    const LengthUnit shown = job.lengthUnit;
    Diagnostics out;

    std::optional<TechnologyData> tech = jobTechnology(mm, table);
    if (!tech) {
        std::vector<std::string> known;
        for (const auto& m : table.materials()) known.push_back(m.id);
        out.push_back(jobError("material", msg::unknownMaterial(job.material, known)));
    }
    if (!checkOverrides(mm.technology, shown, out)) tech.reset();
    if (tech && tech->alpha3 >= tech->alpha2)
        out.push_back(jobError("technology.alpha3", msg::alpha3NotBelowAlpha2({tech->alpha3, shown}, {tech->alpha2, shown})));
    const bool stockOk = checkStock(mm.stock, shown, out);

    const check::Context ctx{shown, tech, stockOk ? &mm.stock : nullptr, &library};
    std::vector<bool> valid(mm.units.size(), false);
    for (std::size_t u = 0; u < mm.units.size(); ++u) {
        const int unitNo = static_cast<int>(u) + 1;
        const auto report = std::visit(
            [&](const auto& m) {
                if constexpr (std::is_same_v<std::decay_t<decltype(m)>, M4Pocket>) return check::checkM4(m, unitNo, ctx);
                else return check::checkM2D(m, unitNo, ctx);
            },
            mm.units[u].module);
        out.insert(out.end(), report.diagnostics.begin(), report.diagnostics.end());
        valid[u] = report.figureValid;
    }
    const Diagnostics overlaps = check::interferences(mm, valid, shown);
    out.insert(out.end(), overlaps.begin(), overlaps.end());

    if (out.size() > kMaxDiagnostics) {
        const std::size_t dropped = out.size() - (kMaxDiagnostics - 1);
        out.resize(kMaxDiagnostics - 1);
        out.push_back({Severity::Error, std::nullopt, "", "", msg::tooManyErrors(dropped)});
    }
    return out;
}

}  // namespace taiwa
