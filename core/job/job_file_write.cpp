// Writing the canonical text of a job (writeJob of job_file.h): keys in a
// fixed order (a unit's own keys in the order its module's door writes them),
// two-space indentation with points and other short lists on one line (text
// lines such as the figure's one a line),
// whole numbers without ".0", other numbers in nlohmann's shortest round-trip
// form, a final newline.
#include "job/job_file.h"

#include "io/json_write.h"
#include "modules/registry.h"

#include <nlohmann/json.hpp>

#include <algorithm>

#include <cmath>

namespace taiwa {

namespace {

using ordered = nlohmann::ordered_json;
using io::number;

ordered unitJson(const MachiningUnit& unit)
{
    ordered u;
    u["module"] = unit.module.name();
    u["name"] = unit.name;
    moduleKind(unit.module).write(unit.module, u);
    if (!unit.cutting.empty()) {
        ordered cutting = ordered::object();
        for (const auto& [key, c] : unit.cutting) {
            ordered o = ordered::object();
            if (c.speed) o["S"] = number(*c.speed);
            if (c.feed) o["F"] = number(*c.feed);
            cutting[key] = o;
        }
        u["cutting"] = cutting;
    }
    return u;
}

ordered jobJson(const Job& job)
{
    ordered j;
    j["format"] = "taiwa-job";
    j["version"] = formatVersionFor(job);
    j["name"] = job.name;
    j["lengthUnit"] = job.lengthUnit == LengthUnit::Inch ? "inch" : "mm";
    j["material"] = job.material;
    j["machine"] = job.machine;
    j["workOffset"] = job.workOffset;
    if (!job.dialect.empty()) j["dialect"] = job.dialect;
    if (!job.latheRoughingCycles) j["latheRoughing"] = "passes";
    if (job.twoPath != TwoPathSettings{}) {
        ordered t = ordered::object();
        t["dwellRevolutions"] = number(job.twoPath.dwellRevolutions);
        t["waitsEverywhere"] = job.twoPath.waitsEverywhere;
        if (job.twoPath.firstWait) t["firstWait"] = *job.twoPath.firstWait;
        j["twoPath"] = std::move(t);
    }
    const Stock& s = job.stock;
    if (job.bar)
        j["stock"] = {{"shape", "bar"},
                      {"diameter", number(job.bar->diameter)},
                      {"length", number(job.bar->length)},
                      {"face", number(job.bar->face)},
                      {"bore", number(job.bar->bore)}};
    else
        j["stock"] = {{"shape", "block"},         {"x", number(s.x)},           {"y", number(s.y)},
                      {"width", number(s.width)}, {"length", number(s.length)}, {"height", number(s.height)}};
    if (job.clamping)
        j["clamping"] = {{"fixture", "vice"},
                         {"grip", job.clamping->grip == Clamping::Grip::X ? "x" : "y"},
                         {"height", number(job.clamping->height)}};
    if (!job.technology.empty()) {
        ordered t = ordered::object();
        const TechnologyOverrides& o = job.technology;
        if (o.alpha1) t["alpha1"] = number(*o.alpha1);
        if (o.alpha2) t["alpha2"] = number(*o.alpha2);
        if (o.alpha3) t["alpha3"] = number(*o.alpha3);
        if (o.beta2) t["beta2"] = number(*o.beta2);
        if (o.gamma) t["gamma"] = number(*o.gamma);
        if (o.stepOver) t["stepOver"] = number(*o.stepOver);
        j["technology"] = std::move(t);
    }
    if (!job.figure.empty()) {
        ordered lines = ordered::array();
        std::size_t from = 0;
        for (;;) {
            const std::size_t to = job.figure.find('\n', from);
            lines.push_back(job.figure.substr(from, to == std::string::npos ? std::string::npos : to - from));
            if (to == std::string::npos) break;
            from = to + 1;
        }
        j["figure"] = std::move(lines);
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
    // Short lists of numbers or names on one line; text lines (the figure)
    // one a line.
    const auto longText = [&] {
        std::size_t chars = 0;
        for (const auto& e : v) chars += e.is_string() ? e.get_ref<const std::string&>().size() + 4 : 0;
        return chars > 80;
    };
    if (v.is_array() && std::none_of(v.begin(), v.end(), [](const ordered& e) { return e.is_structured(); }) && !longText()) {
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

int formatVersionFor(const Job& job)
{
    int v = Job::kOldestFormatVersion;
    for (const auto& u : job.units)
        if (const ModuleKind* k = findModuleKind(u.module.name())) v = std::max(v, k->formatVersion());
    if (job.twoPath != TwoPathSettings{}) v = std::max(v, 6);
    if (!job.figure.empty()) v = std::max(v, 5);
    if (job.clamping) v = std::max(v, 4);
    if (job.bar) v = std::max(v, 3);
    if (!job.dialect.empty()) v = std::max(v, 2);
    return v;
}

std::string writeJob(const Job& job)
{
    std::string out;
    emit(jobJson(job), 0, out);
    return out + '\n';
}

}  // namespace taiwa
