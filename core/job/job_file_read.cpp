// Reading a job document (readJob of job_file.h): the JSON tree from
// json_document, then every field checked for presence and kind, each unit's
// own fields by its module's door, collecting all problems as diagnostics.
// Values are kept as typed: whether they make sense (a code in its table, a
// pocket inside the stock) is input processing.
#include "job/job_file.h"
#include "model/translate_noop.h"

#include "io/job_io.h"
#include "io/job_messages.h"
#include "io/json_document.h"
#include "io/json_fields.h"
#include "io/json_objects.h"
#include "modules/registry.h"

#include <malloc.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <cctype>

namespace taiwa {

namespace {

using nlohmann::json;
using io::ObjectFields;

const std::vector<std::string> kJobKeys{"format",  "version", "name",     "lengthUnit", "material",      "machine", "workOffset",
                                        "dialect", "stock",   "clamping", "technology", "figure", "latheRoughing", "twoPath", "units"};
const std::vector<std::string> kStockShapes{"block", "bar"};
const std::vector<std::string> kBlockKeys{"shape", "x", "y", "width", "length", "height"};
const std::vector<std::string> kBarKeys{"shape", "diameter", "length", "face", "bore"};
const std::vector<std::string> kClampingKeys{"fixture", "grip", "height"};
const std::vector<std::string> kTwoPathKeys{"dwellRevolutions", "waitsEverywhere", "firstWait"};
const std::vector<std::string> kTechnologyKeys{"alpha1", "alpha2", "alpha3", "beta2", "gamma", "stepOver"};
bool isBlank(std::string_view text)
{
    return std::all_of(text.begin(), text.end(), [](char c) { return std::isspace(static_cast<unsigned char>(c)); });
}

Diagnostic fileProblem(std::string message) { return {Severity::Error, std::nullopt, "", "", std::move(message)}; }

// The module a unit names, when it is one this program knows.
std::string knownModule(const json& unit)
{
    if (!unit.is_object()) return {};
    const auto it = unit.find("module");
    if (it == unit.end() || !it->is_string()) return {};
    const auto& name = it->get_ref<const std::string&>();
    return findModuleKind(name) ? name : std::string();
}

// The unit's "cutting": {"roughing": {"S": 8000, "F": 1500}, ...}; which
// keys the module's steps have is the checks' to say.
std::map<std::string, CuttingOverride> readCutting(const ObjectFields& unit)
{
    std::map<std::string, CuttingOverride> out;
    const json* v = unit.find("cutting");
    if (!v) return out;
    if (!v->is_object()) {
        unit.error("cutting", msg::io::wrongType(TAIWA_TRANSLATE_NOOP("taiwa::msg", "an object"), *v));
        return out;
    }
    for (const auto& [key, value] : v->items()) {
        const std::string prefix = "cutting." + msg::io::fieldKey(key) + ".";
        if (!value.is_object()) {
            unit.error("cutting." + msg::io::fieldKey(key),
                       msg::io::wrongType(TAIWA_TRANSLATE_NOOP("taiwa::msg", "an object with S and/or F"), value));
            continue;
        }
        const ObjectFields c = unit.nested(value, prefix);
        c.rejectUnknown(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a step's speed and feed"), {"S", "F"});
        CuttingOverride o;
        o.speed = c.optionalNumber("S");
        o.feed = c.optionalNumber("F");
        if (o.empty()) unit.error("cutting." + msg::io::fieldKey(key), TAIWA_TRANSLATE_NOOP("taiwa::msg", "give S, F or both"));
        else out[key] = o;
    }
    return out;
}

std::optional<MachiningUnit> readUnit(const json& unit, int number, DiagnosticSink& sink)
{
    const std::string module = knownModule(unit);
    static const json kNoFields = json::object();
    const ObjectFields f(unit.is_object() ? unit : kNoFields, io::Place{number, module.empty() ? "?" : module, ""},
                         sink);
    if (!unit.is_object()) {
        f.error("", msg::io::wrongType(TAIWA_TRANSLATE_NOOP("taiwa::msg", "an object"), unit));
        return std::nullopt;
    }
    if (module.empty()) {
        const json* name = f.find("module");
        if (!name) f.error("module", msg::io::missing(msg::io::oneOf(moduleNames())));
        else if (!name->is_string())
            f.error("module", msg::io::wrongType(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a string"), *name));
        else f.error("module", msg::io::unknownModule(name->get<std::string>(), moduleNames()));
        return std::nullopt;
    }
    MachiningUnit out;
    out.name = f.string("name", "");
    out.module = findModuleKind(module)->read(f);
    out.cutting = readCutting(f);
    return out;
}

Stock readStock(const ObjectFields& job, std::optional<BarStock>& bar)
{
    Stock s;
    const json* v = job.find("stock");
    if (!v || !v->is_object()) {
        job.error("stock", v ? msg::io::wrongType(TAIWA_TRANSLATE_NOOP("taiwa::msg", "an object"), *v)
                             : msg::io::missing(TAIWA_TRANSLATE_NOOP("taiwa::msg", "an object")));
        return s;
    }
    const ObjectFields f(*v, io::Place{std::nullopt, "", "stock."}, job.sink());
    const auto shape = f.find("shape");
    if (shape && shape->is_string()
        && std::find(kStockShapes.begin(), kStockShapes.end(), shape->get<std::string>()) == kStockShapes.end()) {
        f.error("shape", msg::io::unknownStockShape(shape->get<std::string>(), kStockShapes));
        return s;
    }
    if (f.choice("shape", kStockShapes).value_or(0) == 1) {
        f.rejectUnknown(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a bar stock"), kBarKeys);
        BarStock b;
        b.diameter = f.number("diameter").value_or(0.0);
        b.length = f.number("length").value_or(0.0);
        b.face = f.number("face", 0.0);
        b.bore = f.number("bore", 0.0);
        bar = b;
        return s;
    }
    f.rejectUnknown(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a block stock"), kBlockKeys);
    s.x = f.number("x", 0.0);
    s.y = f.number("y", 0.0);
    s.width = f.number("width").value_or(0.0);
    s.length = f.number("length").value_or(0.0);
    s.height = f.number("height").value_or(0.0);
    return s;
}

// "figure": ["P1 = POINT/0, 0", "L1 = LINE/P1, P2", ...], one statement (or
// comment) a line; joined with line feeds into the text the figure language
// reads. Absent: no figure elements. The text's own refusals come from
// checking the job, with their line and column.
std::string readFigure(const ObjectFields& job)
{
    const json* v = job.find("figure");
    if (!v) return {};
    if (!v->is_array()) {
        job.error("figure", msg::io::wrongType(
                                TAIWA_TRANSLATE_NOOP("taiwa::msg", "an array of lines of figure-element text"), *v));
        return {};
    }
    std::string text;
    for (std::size_t i = 0; i < v->size(); ++i) {
        const json& line = (*v)[i];
        if (!line.is_string()) {
            job.error("figure[" + std::to_string(i) + "]",
                      msg::io::wrongType(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a line of text"), line));
            continue;
        }
        const auto& l = line.get_ref<const std::string&>();
        if (l.find('\n') != std::string::npos || l.find('\r') != std::string::npos) {
            job.error("figure[" + std::to_string(i) + "]", TAIWA_TRANSLATE_NOOP("taiwa::msg", "a line of the figure holds a line break; give each line as its own string"));
            continue;
        }
        text += l;
        if (i + 1 < v->size()) text += '\n';
    }
    return text;
}

// A job-level object read by `read` into T's defaults, its unknown keys
// refused as fields of `owner`; absent (or not an object): the defaults.
template <class T, class Read>
T readSection(const ObjectFields& job, const char* key, const char* owner, const std::vector<std::string>& known,
              Read read)
{
    T t{};
    if (const auto f = io::objectAt(job, key)) {
        f->rejectUnknown(owner, known);
        read(*f, t);
    }
    return t;
}

// "clamping": {"fixture": "vice", "grip": "y", "height": 10}; absent: not given.
std::optional<Clamping> readClamping(const ObjectFields& job)
{
    return readSection<std::optional<Clamping>>(
        job, "clamping", TAIWA_TRANSLATE_NOOP("taiwa::msg", "the clamping"), kClampingKeys,
        [](const ObjectFields& f, std::optional<Clamping>& clamping) {
            f.choice("fixture", {"vice"});  // the one fixture so far; the key leaves room for others
            Clamping& c = clamping.emplace();
            c.grip = f.choice("grip", {"x", "y"}).value_or(1) == 0 ? Clamping::Grip::X : Clamping::Grip::Y;
            c.height = f.number("height").value_or(0.0);
        });
}

// The two-path settings (version 6); absent: the defaults. Their ranges
// (the dwell, the wait code against the machine's) are the job check's.
TwoPathSettings readTwoPath(const ObjectFields& job)
{
    return readSection<TwoPathSettings>(
        job, "twoPath", TAIWA_TRANSLATE_NOOP("taiwa::msg", "the two-path settings"), kTwoPathKeys,
        [](const ObjectFields& f, TwoPathSettings& t) {
            t.dwellRevolutions = f.number("dwellRevolutions", t.dwellRevolutions);
            if (const json* w = f.find("waitsEverywhere")) {
                if (w->is_boolean())
                    t.waitsEverywhere = w->get<bool>();
                else
                    f.error("waitsEverywhere",
                            msg::io::wrongType(TAIWA_TRANSLATE_NOOP("taiwa::msg", "true or false"), *w));
            }
            if (f.find("firstWait")) t.firstWait = f.whole("firstWait");
        });
}

TechnologyOverrides readTechnology(const ObjectFields& job)
{
    return readSection<TechnologyOverrides>(
        job, "technology", TAIWA_TRANSLATE_NOOP("taiwa::msg", "the technology overrides"), kTechnologyKeys,
        [](const ObjectFields& f, TechnologyOverrides& t) {
            t.alpha1 = f.optionalNumber("alpha1");
            t.alpha2 = f.optionalNumber("alpha2");
            t.alpha3 = f.optionalNumber("alpha3");
            t.beta2 = f.optionalNumber("beta2");
            t.gamma = f.optionalNumber("gamma");
            t.stepOver = f.optionalNumber("stepOver");
        });
}

// A problem at a path of the document, reported where it is: in a unit
// ("units[2].depth": unit 3, field "depth", its module from `moduleOf`) or at
// job level ("stock.height").
Diagnostic atPath(const io::JsonPath& path, const std::function<std::string(std::size_t)>& moduleOf,
                  std::string message)
{
    Diagnostic d{Severity::Error, std::nullopt, "", io::joinPath(path.begin(), path.end()), std::move(message)};
    if (path.size() >= 3 && path[0] == "units" && path[1].starts_with("[")) {
        const std::size_t index = std::stoul(path[1].substr(1));
        const std::string module = moduleOf(index);
        d.unit = static_cast<int>(index + 1);
        d.module = module.empty() ? "?" : module;
        d.field = io::joinPath(path.begin() + 2, path.end());
    }
    return d;
}

// A key given twice, reported where it is.
void reportRepeated(const io::JsonPath& path, const json& root, DiagnosticSink& sink)
{
    const json* units = root.contains("units") && root["units"].is_array() ? &root["units"] : nullptr;
    sink.add(atPath(path, [units](std::size_t i) { return units && i < units->size() ? knownModule((*units)[i]) : ""; },
                    msg::io::duplicateKey()));
}

// Format and version come first: anything else of a file that is not a job,
// or of a newer format, is not read at all.
std::optional<Diagnostic> refuseFormat(const json& root)
{
    const auto format = root.find("format");
    if (format == root.end()) return fileProblem(msg::io::formatMissing());
    if (*format != "taiwa-job") return fileProblem(msg::io::formatWrong(*format));
    const auto version = root.find("version");
    if (version == root.end())
        return Diagnostic{Severity::Error, std::nullopt, "", "version",
                          msg::io::missing(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a whole number"))};
    // The one rule for whole numbers (as for "U": 1.0): 1.0 is the whole number 1.
    if (version->is_number_float() && version->get<double>() != std::floor(version->get<double>()))
        return Diagnostic{Severity::Error, std::nullopt, "", "version", msg::io::notWhole(*version)};
    if (!version->is_number())
        return Diagnostic{Severity::Error, std::nullopt, "", "version",
                          msg::io::wrongType(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a whole number"), *version)};
    if ((version->is_number_unsigned() && version->get<std::uint64_t>() > std::uint64_t{INT64_MAX}) ||
        (version->is_number_float() && version->get<double>() > 9.2e18))
        return fileProblem(msg::io::versionNewer(INT64_MAX, Job::kFormatVersion));
    const auto n = version->is_number_float() ? static_cast<std::int64_t>(version->get<double>()) : version->get<std::int64_t>();
    if (n > Job::kFormatVersion) return fileProblem(msg::io::versionNewer(n, Job::kFormatVersion));
    if (n < Job::kOldestFormatVersion) return fileProblem(msg::io::versionUnknown(n, Job::kFormatVersion));
    return std::nullopt;
}

}  // namespace

JobReadResult readJob(std::string_view text)
{
    JobReadResult result;
    if (isBlank(text)) {
        result.diagnostics.push_back(fileProblem(msg::io::fileEmpty()));
        return result;
    }
    io::ParsedDocument doc = io::parseDocument(text);
    if (!doc.root && !doc.errorPath.empty()) {
        // JSON, but a value no dimension can have (1e400): named at its field.
        const std::string module = findModuleKind(doc.errorModule) ? doc.errorModule : std::string();
        result.diagnostics.push_back(atPath(doc.errorPath, [&](std::size_t) { return module; }, doc.error));
        return result;
    }
    if (!doc.root) {
        result.diagnostics.push_back(fileProblem(doc.error));
        return result;
    }
    const json& root = *doc.root;
    if (!root.is_object()) {
        result.diagnostics.push_back(fileProblem(msg::io::notAnObject(root)));
        return result;
    }
    if (auto refused = refuseFormat(root)) {
        result.diagnostics.push_back(std::move(*refused));
        return result;
    }

    DiagnosticSink sink;
    for (const auto& path : doc.repeatedKeys) reportRepeated(path, root, sink);
    const ObjectFields f(root, io::Place{}, sink);
    f.rejectUnknown(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a job"), kJobKeys);
    Job job;
    job.name = f.string("name", "");
    job.lengthUnit = f.choice("lengthUnit", {"mm", "inch"}).value_or(0) == 1 ? LengthUnit::Inch : LengthUnit::Millimetre;
    job.material = f.string("material").value_or("");
    job.machine = f.string("machine", job.machine);
    job.workOffset = f.string("workOffset", job.workOffset);
    job.dialect = f.string("dialect", "");
    if (f.find("latheRoughing")) job.latheRoughingCycles = f.choice("latheRoughing", {"cycle", "passes"}).value_or(0) == 0;
    job.twoPath = readTwoPath(f);
    job.stock = readStock(f, job.bar);
    job.clamping = readClamping(f);
    job.technology = readTechnology(f);
    job.figure = readFigure(f);
    const json* units = f.find("units");
    if (!units)
        f.error("units", msg::io::missing(TAIWA_TRANSLATE_NOOP("taiwa::msg", "an array of machining units")));
    else if (!units->is_array())
        f.error("units", msg::io::wrongType(TAIWA_TRANSLATE_NOOP("taiwa::msg", "an array of machining units"), *units));
    else
        for (std::size_t i = 0; i < units->size(); ++i)
            if (auto unit = readUnit((*units)[i], static_cast<int>(i + 1), sink)) job.units.push_back(std::move(*unit));

    if (sink.empty()) result.job = std::move(job);
    result.diagnostics = std::move(sink).finish();
    return result;
}

}  // namespace taiwa

namespace taiwa {

JobReadResult readJobFile(const std::string& path)
{
    io::TextReadResult text = io::readTextFile(path, kMaxJobFileBytes);
    if (!text.text) return {std::nullopt, std::move(text.diagnostics)};
    JobReadResult read = readJob(*text.text);
    // A large job's JSON tree is gone now, in many small blocks the
    // allocator keeps for reuse; the plan's largest block (the steps) takes
    // fresh pages of its own, so the tree's pages were held through the
    // planning on top of it. Given back: taiwa check of 100,000 units peaked
    // at 429 MB with them, 389 MB without (README, "Benchmarks").
    if (text.text->size() > (1u << 20)) malloc_trim(0);
    return read;
}

}  // namespace taiwa
