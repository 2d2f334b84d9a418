// Parsing of the command line of docs/command-line.md into Options.
#include "app/options.h"

#include "post/post.h"

#include <algorithm>
#include <charconv>
#include <string_view>
#include <vector>

namespace taiwa::app {

namespace {

std::optional<int> toInt(std::string_view s)
{
    int v = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
    return v;
}

Result<void> parseSize(std::string_view s, Options& o)
{
    const auto x = s.find('x');
    const auto w = toInt(s.substr(0, x)), h = x == std::string_view::npos ? std::nullopt : toInt(s.substr(x + 1));
    // The upper bound is the renderer's (viz::kMaxRenderSide, checked by `render`).
    if (!w || !h || *w < 16 || *h < 16)
        return Failure{"--size wants WIDTHxHEIGHT in pixels, at least 16, e.g. 800x600; got '" + std::string(s) + "'"};
    o.width = *w;
    o.height = *h;
    return {};
}

// Option `a` with its value `v` (not empty) into `o`; what is wrong with it,
// or that it does not go with the command.
Result<void> valueOption(std::string_view a, std::string_view v, Options& o)
{
    const bool forExport = o.command == Command::Export, forRender = o.command == Command::Render,
               forImport = o.command == Command::Import, forDxf = o.command == Command::FigureFromDxf;
    if (a == "--tools" && !forImport && !forDxf) o.tools = v;
    else if (a == "--out" && (forExport || forRender || forImport)) o.out = v;
    else if (a == "--material" && forImport) o.material = v;
    else if (a == "--from-store" && forExport) o.fromStore = v;
    else if (a == "--dialect" && forExport) {
        if (!isDialect(std::string(v))) {
            std::string names;
            for (const auto& n : dialectNames()) names += (names.empty() ? "" : ", ") + n;
            return Failure{"unknown dialect '" + std::string(v) + "'; known: " + names};
        }
        o.dialect = v;
    } else if (a == "--units" && (forExport || forDxf)) {
        if (v == "mm") o.units = LengthUnit::Millimetre;
        else if (v == "inch") o.units = LengthUnit::Inch;
        else return Failure{"--units is mm or inch, not '" + std::string(v) + "'"};
    } else if (a == "--step" && forRender) {
        if (v == "all") o.step.reset();
        else if (const auto k = toInt(v)) o.step = *k;
        else return Failure{"--step wants a step number or 'all', not '" + std::string(v) + "'"};
    } else if (a == "--size" && forRender) {
        if (auto size = parseSize(v, o); !size) return size;
    } else if (a == "--resolution" && (forExport || o.command == Command::Verify)) {
        double r = 0.0;
        const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), r);
        if (ec != std::errc() || end != v.data() + v.size() || !(r >= 0.005) || r > 5.0)
            return Failure{"--resolution wants a cell size in mm from 0.005 to 5, not '" + std::string(v) + "'"};
        o.resolution = r;
    } else if (a == "--layers" && forDxf) {
        for (std::size_t from = 0; from <= v.size();) {
            const std::size_t comma = std::min(v.find(',', from), v.size());
            if (comma == from) return Failure{"--layers wants layer names separated by commas, not '" + std::string(v) + "'"};
            o.layers.emplace_back(v.substr(from, comma - from));
            from = comma + 1;
        }
    } else if (a == "--gap" && forDxf) {
        double g = 0.0;
        const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), g);
        if (ec != std::errc() || end != v.data() + v.size())
            return Failure{"--gap wants a distance in mm, not '" + std::string(v) + "'"};
        o.gap = g;  // its range is the DXF import's to check
    } else if (a == "--surface" && forImport) {
        double d = 0.0;
        const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), d);
        if (ec != std::errc() || end != v.data() + v.size() || !(d >= 0.05) || d > 10.0)
            return Failure{"--surface wants the paths' spacing in mm from 0.05 to 10, not '" + std::string(v) + "'"};
        o.surfaceSpacing = d;
    } else if (a == "--view" && forRender) {
        if (v != "iso" && v != "top" && v != "front" && v != "profile")
            return Failure{"--view is iso, top, front or profile, not '" + std::string(v) + "'"};
        o.view = v;
    } else {
        return Failure{"option " + std::string(a) + " does not go with this command"};
    }
    return {};
}

// What the command still lacks once every argument is read (its file, the
// store's job name, --out), or what does not go together.
Result<void> missing(const Options& o)
{
    if (o.command == Command::Import && o.job.empty()) return Failure{std::string("no STEP file given")};
    if (o.command == Command::FigureFromDxf && o.job.empty()) return Failure{std::string("no DXF file given")};
    if (o.command == Command::ImportTools && o.job.empty()) return Failure{std::string("no SQLite tool library given")};
    if (o.command == Command::Store) {
        const bool named = o.storeAction == "history" || o.storeAction == "unlock";
        if (!named && !o.job.empty()) return Failure{"store " + o.storeAction + " takes no job name ('" + o.job + "')"};
        if (named && o.job.empty()) return Failure{"store " + o.storeAction + " needs the job's name"};
        return {};
    }
    if (!o.fromStore.empty() && !o.job.empty()) return Failure{"give a job file or --from-store, not both ('" + o.job + "', '" + o.fromStore + "')"};
    if (o.command != Command::Station && o.job.empty() && o.fromStore.empty()) return Failure{std::string("no job file given")};
    if ((o.command == Command::Export || o.command == Command::Render || o.command == Command::Import) && o.out.empty())
        return Failure{std::string("--out is required")};
    return {};
}

}  // namespace

Result<void> parseOptions(int argc, char** argv, Options& o)
{
    std::vector<std::string_view> args(argv + 1, argv + argc);
    std::size_t i = 0;
    if (!args.empty()) {
        const auto first = args[0];
        if (first == "--help" || first == "-h") { o.command = Command::Help; return {}; }
        if (first == "--version") { o.command = Command::Version; return {}; }
        if (first == "--list-machines" || first == "--list-dialects") {
            if (args.size() > 1) return Failure{"'" + std::string(first) + "' takes no arguments"};
            o.command = first == "--list-machines" ? Command::ListMachines : Command::ListDialects;
            return {};
        }
        if (first == "check") o.command = Command::Check, i = 1;
        else if (first == "export") o.command = Command::Export, i = 1;
        else if (first == "render") o.command = Command::Render, i = 1;
        else if (first == "verify") o.command = Command::Verify, i = 1;
        else if (first == "import") o.command = Command::Import, i = 1;
        else if (first == "figure-from-dxf") o.command = Command::FigureFromDxf, i = 1;
        else if (first == "import-tools") o.command = Command::ImportTools, i = 1;
        else if (first == "store") {  // store list, store history NAME, store locks, store unlock NAME [--force]
            o.command = Command::Store, i = 2;
            if (args.size() < 2 || (args[1] != "list" && args[1] != "history" && args[1] != "locks" && args[1] != "unlock"))
                return Failure{std::string("store wants 'list', 'history NAME', 'locks' or 'unlock NAME [--force]'") +
                               (args.size() < 2 ? "" : ", not '" + std::string(args[1]) + "'")};
            o.storeAction = args[1];
        }
    }
    auto value = [&]() -> std::optional<std::string_view> {
        if (i + 1 >= args.size()) return std::nullopt;
        return args[++i];
    };
    std::vector<std::string_view> seen;  // options given so far
    for (; i < args.size(); ++i) {
        const auto a = args[i];
        if (a.empty()) return Failure{std::string("an empty argument")};
        if (a[0] != '-' || a == "-") {
            if (!o.job.empty()) return Failure{"more than one job file given: '" + o.job + "' and '" + std::string(a) + "'"};
            o.job = a;
            continue;
        }
        const bool takesValue = a == "--out" || a == "--dialect" || a == "--units" || a == "--tools" || a == "--step" ||
                                a == "--size" || a == "--view" || a == "--material" || a == "--resolution" ||
                                a == "--layers" || a == "--gap" || a == "--from-store" || a == "--surface";
        if (a == "--no-cache") {  // verify and export: the verification run afresh
            if (o.command != Command::Verify && o.command != Command::Export)
                return Failure{"option --no-cache does not go with this command"};
            o.cache = false;
            continue;
        }
        if (a == "--stock" || a == "--json" || a == "--force" || a == "--no-pictures") {
            const Command wanted = a == "--stock" ? Command::Render : a == "--json" ? Command::Verify : Command::Export;
            const bool unlockForce = a == "--force" && o.command == Command::Store && o.storeAction == "unlock";
            if (o.command != wanted && !unlockForce) return Failure{"option " + std::string(a) + " does not go with this command"};
            if (a == "--no-pictures") o.pictures = false;
            else (a == "--stock" ? o.stock : a == "--json" ? o.json : o.force) = true;
            continue;
        }
        if (!takesValue) return Failure{"unknown option '" + std::string(a) + "'"};
        const auto v = value();
        if (!v) return Failure{"option " + std::string(a) + " needs a value"};
        // Each option once, with a value: a second --out would silently win.
        if (std::find(seen.begin(), seen.end(), a) != seen.end())
            return Failure{"option " + std::string(a) + " is given twice"};
        seen.push_back(a);
        if (v->empty()) return Failure{"option " + std::string(a) + " needs a value, not an empty one"};
        if (auto taken = valueOption(a, *v, o); !taken) return taken;
    }
    return missing(o);
}

}  // namespace taiwa::app
