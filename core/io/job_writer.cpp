// Writing the canonical text of a job (writeJob of job_io.h): keys in a fixed
// order, two-space indentation with points and other short number lists on
// one line, whole numbers without ".0", other numbers in nlohmann's shortest
// round-trip form, a final newline.
#include "io/job_io.h"

#include <nlohmann/json.hpp>

#include <cmath>

namespace taiwa {

namespace {

using ordered = nlohmann::ordered_json;

// A whole number is written as one ("20", not "20.0"); up to 2^53 every whole
// double is exact as an integer.
ordered number(double v)
{
    constexpr double kExactInteger = 9007199254740992.0;  // 2^53
    if (std::isfinite(v) && v == std::floor(v) && std::fabs(v) <= kExactInteger)
        return static_cast<std::int64_t>(v);
    return v;
}

ordered point(Point2 p) { return ordered::array({number(p.x), number(p.y)}); }

ordered pins(const ToolPins& tools)
{
    ordered out = ordered::object();
    for (const auto& [step, id] : tools) out[step] = id;
    return out;
}

ordered unitJson(const MachiningUnit& unit)
{
    ordered u;
    u["module"] = moduleName(unit.module);
    u["name"] = unit.name;
    if (const auto* m = std::get_if<M4Pocket>(&unit.module)) {
        u["corners"] = ordered::array();
        for (const auto& c : m->corners) u["corners"].push_back(point(c));
        u["cornerRadius"] = number(m->cornerRadius);
        u["depth"] = number(m->depth);
        u["taper"] = number(m->taper);
        u["U"] = m->toolUse;
        u["F"] = m->wallFinish;
        u["H"] = m->pilotHole;
        if (!m->tools.empty()) u["tools"] = pins(m->tools);
    } else {
        const auto& d = std::get<M2DPocket>(unit.module);
        u["corner"] = point(d.corner);
        u["L1"] = number(d.lengthX);
        u["L2"] = number(d.lengthY);
        u["depth"] = number(d.depth);
        u["theta1"] = number(d.theta1);
        if (d.theta2) u["theta2"] = number(*d.theta2);
        u["cornerRadius"] = number(d.cornerRadius);
        u["U"] = d.toolUse;
        u["H"] = d.pilotHole;
        u["scallop"] = number(d.scallop);
        if (!d.tools.empty()) u["tools"] = pins(d.tools);
    }
    return u;
}

ordered jobJson(const Job& job)
{
    ordered j;
    j["format"] = "taiwa-job";
    j["version"] = Job::kFormatVersion;
    j["name"] = job.name;
    j["lengthUnit"] = job.lengthUnit == LengthUnit::Inch ? "inch" : "mm";
    j["material"] = job.material;
    j["machine"] = job.machine;
    j["workOffset"] = job.workOffset;
    const Stock& s = job.stock;
    j["stock"] = {{"shape", "block"},           {"x", number(s.x)},           {"y", number(s.y)},
                  {"width", number(s.width)},   {"length", number(s.length)}, {"height", number(s.height)}};
    if (!job.technology.empty()) {
        ordered t = ordered::object();
        const TechnologyOverrides& o = job.technology;
        if (o.alpha1) t["alpha1"] = number(*o.alpha1);
        if (o.alpha2) t["alpha2"] = number(*o.alpha2);
        if (o.alpha3) t["alpha3"] = number(*o.alpha3);
        if (o.beta2) t["beta2"] = number(*o.beta2);
        if (o.gamma) t["gamma"] = number(*o.gamma);
        j["technology"] = std::move(t);
    }
    j["units"] = ordered::array();
    for (const auto& unit : job.units) j["units"].push_back(unitJson(unit));
    return j;
}

std::string scalar(const ordered& v)
{
    // Invalid UTF-8 (only possible in a job built in code) becomes U+FFFD rather than an exception.
    return v.dump(-1, ' ', false, ordered::error_handler_t::replace);
}

void emit(const ordered& v, std::size_t indent, std::string& out)
{
    const bool container = v.is_object() || v.is_array();
    if (!container || v.empty()) {
        out += container ? (v.is_object() ? "{}" : "[]") : scalar(v);
        return;
    }
    if (v.is_array() && std::none_of(v.begin(), v.end(), [](const ordered& e) { return e.is_structured(); })) {
        out += '[';
        for (std::size_t i = 0; i < v.size(); ++i) out += (i ? ", " : "") + scalar(v[i]);
        out += ']';
        return;
    }
    out += v.is_object() ? "{\n" : "[\n";
    const std::string pad(indent + 2, ' ');
    bool first = true;
    for (auto it = v.begin(); it != v.end(); ++it) {
        if (!first) out += ",\n";
        first = false;
        out += pad;
        if (v.is_object()) out += scalar(it.key()) + ": ";
        emit(it.value(), indent + 2, out);
    }
    out += '\n' + std::string(indent, ' ') + (v.is_object() ? '}' : ']');
}

}  // namespace

std::string writeJob(const Job& job)
{
    std::string out;
    emit(jobJson(job), 0, out);
    return out + '\n';
}

}  // namespace taiwa
