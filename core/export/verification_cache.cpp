// The verification cache (verification_cache.h): the key's SHA-256, the
// report as a small JSON file, reading it back as a miss whenever anything
// in it is not as written.
#include "export/verification_cache.h"

#include "io/job_io.h"
#include "job/job_file.h"
#include "machine/machine.h"

#include <QCryptographicHash>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <bit>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

namespace taiwa {

namespace fs = std::filesystem;

namespace {

// Bumped whenever the stored form or the key's content changes.
constexpr const char* kFormat = "taiwa verification cache 2";

// The key's material: every value with its length or its exact bits, so
// that no two different inputs run together into the same bytes.
class KeyWriter {
public:
    void text(std::string_view s)
    {
        number(static_cast<std::uint64_t>(s.size()));
        bytes_.append(s);
    }
    void number(std::uint64_t v)
    {
        for (int i = 0; i < 8; ++i) bytes_.push_back(static_cast<char>((v >> (8 * i)) & 0xff));
    }
    void real(double v) { number(std::bit_cast<std::uint64_t>(v)); }
    void integer(long long v) { number(static_cast<std::uint64_t>(v)); }
    void flag(bool v) { integer(v ? 1 : 0); }
    std::string sha256() const
    {
        return QCryptographicHash::hash(QByteArrayView(bytes_.data(), static_cast<qsizetype>(bytes_.size())),
                                        QCryptographicHash::Sha256)
            .toHex()
            .toStdString();
    }

private:
    std::string bytes_;
};

// This program's build: the running executable's path, size and time. A
// rebuild (another planner or verifier) is another key.
void writeBuild(KeyWriter& k)
{
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    k.text(ec ? std::string("?") : exe.string());
    const auto size = ec ? 0 : fs::file_size(exe, ec);
    k.number(ec ? 0 : size);
    const auto time = ec ? fs::file_time_type{} : fs::last_write_time(exe, ec);
    k.integer(ec ? 0 : static_cast<long long>(time.time_since_epoch().count()));
}

void writeTool(KeyWriter& k, const Tool& t)
{
    k.integer(t.id);
    k.text(t.name);
    k.integer(static_cast<int>(t.type));
    for (double v : {t.diameter, t.cornerRadius, t.taperAngle, t.pointAngle, t.fluteLength, t.stickout,
                     t.holderDiameter, t.holderLength, t.lifeMinutes, t.usedMinutes})
        k.real(v);
    k.text(t.holder);
    k.integer(t.flutes);
    k.flag(t.centreCutting);
    k.number(t.cutting.size());
    for (const auto& c : t.cutting) {
        k.text(c.material);
        for (double v : {c.surfaceSpeed, c.feedPerTooth, c.plungeFactor}) k.real(v);
    }
    const TurningSpec& s = t.turning;
    k.text(s.insertCode);
    k.text(s.hand);
    k.flag(s.inside);
    for (double v : {s.approachAngle, s.minBore, s.width, s.maxDepth, s.maxDiameter, s.pitchMin, s.pitchMax,
                     s.threadAngle})
        k.real(v);
}

void writeMachine(KeyWriter& k, const std::string& id)
{
    const Machine* m = findMachine(id);
    k.flag(m != nullptr);
    if (!m) return;
    k.text(m->id);
    k.text(m->source);
    k.integer(static_cast<int>(m->kind));
    k.flag(m->xDiameter);
    k.number(m->travel.size());
    for (const auto& [axis, t] : m->travel) {
        k.text(axis);
        k.real(t.min);
        k.real(t.max);
    }
    for (double v : {m->maxSpindleSpeed, m->maxFeed, m->chuckDiameter, m->maxBarDiameter, m->jawLength}) k.real(v);
    k.integer(m->toolPockets);
    k.integer(m->turretStations);
}

nlohmann::json toJson(const verify::Report& r)
{
    nlohmann::json j;
    j["format"] = kFormat;
    j["resolution"] = r.resolution;
    j["columns"] = r.columns;
    j["rows"] = r.rows;
    j["removed"] = r.removed;
    j["cellVisits"] = r.cellVisits;
    j["skipped"] = r.skipped;
    j["coarsened"] = r.coarsened;
    j["findings"] = nlohmann::json::array();
    for (const auto& f : r.findings)
        j["findings"].push_back({{"kind", static_cast<int>(f.kind)},
                                 {"step", f.step},
                                 {"move", f.move},
                                 {"position", {f.position.x, f.position.y, f.position.z}},
                                 {"size", f.size},
                                 {"area", f.area},
                                 {"part", f.part}});
    return j;
}

// Throws nlohmann's exceptions on anything missing or of the wrong type, and
// Refusal (model/result.h) on a value out of place.
verify::Report fromJson(const nlohmann::json& j)
{
    if (j.at("format").get<std::string>() != kFormat) throw Refusal("another format", Place::atKey("format"));
    verify::Report r;
    r.resolution = j.at("resolution").get<double>();
    r.columns = j.at("columns").get<int>();
    r.rows = j.at("rows").get<int>();
    r.removed = j.at("removed").get<std::vector<double>>();
    r.cellVisits = j.at("cellVisits").get<double>();
    r.skipped = j.at("skipped").get<std::string>();
    r.coarsened = j.at("coarsened").get<std::string>();
    for (const auto& e : j.at("findings")) {
        verify::Finding f;
        const int kind = e.at("kind").get<int>();
        if (kind < 0 || kind > static_cast<int>(verify::FindingKind::RestMaterial)) throw Refusal("no such kind", Place::atKey("findings.kind"));
        f.kind = static_cast<verify::FindingKind>(kind);
        f.step = e.at("step").get<int>();
        f.move = e.at("move").get<int>();
        const auto p = e.at("position").get<std::vector<double>>();
        if (p.size() != 3) throw Refusal("not three numbers", Place::atKey("findings.position"));
        f.position = {p[0], p[1], p[2]};
        f.size = e.at("size").get<double>();
        f.area = e.at("area").get<double>();
        f.part = e.at("part").get<std::string>();
        r.findings.push_back(std::move(f));
    }
    return r;
}

fs::path fileFor(const std::string& key) { return fs::path(verificationCacheFolder()) / (key + ".json"); }

// Only a key this file could have made names a file (no path in it).
bool wellFormed(const std::string& key)
{
    return key.size() == 64 && std::all_of(key.begin(), key.end(), [](char c) {
               return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f');
           });
}

void prune(const fs::path& folder)
{
    std::error_code ec;
    std::vector<std::pair<fs::file_time_type, fs::path>> files;
    for (const auto& e : fs::directory_iterator(folder, ec))
        if (e.is_regular_file(ec) && e.path().extension() == ".json") files.emplace_back(e.last_write_time(ec), e.path());
    if (files.size() <= static_cast<std::size_t>(kCachedVerifications)) return;
    std::sort(files.begin(), files.end());
    for (std::size_t i = 0; i + kCachedVerifications < files.size(); ++i) fs::remove(files[i].second, ec);
}

}  // namespace

std::string verificationCacheFolder()
{
    if (const char* own = std::getenv("TAIWA_CACHE_DIR"); own && *own) return own;
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return (fs::path(xdg) / "taiwa/verification").string();
    const char* home = std::getenv("HOME");
    return (fs::path(home && *home ? home : "/tmp") / ".cache/taiwa/verification").string();
}

std::string verificationKey(const Plan& plan, const verify::Options& options)
{
    KeyWriter k;
    k.text(kFormat);
    writeBuild(k);
    k.real(options.resolution);
    k.real(options.maxCellVisits);
    k.text(writeJob(plan.job));
    k.number(plan.tools.size());
    for (const auto& t : plan.tools) writeTool(k, t);
    writeMachine(k, plan.mmJob.machine);
    return k.sha256();
}

std::optional<verify::Report> loadVerification(const std::string& key)
{
    if (!wellFormed(key)) return std::nullopt;
    std::ifstream in(fileFor(key), std::ios::binary);
    if (!in) return std::nullopt;
    std::ostringstream text;
    text << in.rdbuf();
    try {
        return fromJson(nlohmann::json::parse(text.str()));
    } catch (const std::exception&) {
        return std::nullopt;  // damaged or of another format: verified again, and stored anew
    }
}

Result<void> storeVerification(const std::string& key, const verify::Report& report)
{
    if (!wellFormed(key)) return Failure{"not a verification key: " + key};
    const fs::path file = fileFor(key);
    std::error_code ec;
    fs::create_directories(file.parent_path(), ec);
    if (ec) return Failure{"cannot create " + file.parent_path().string() + ": " + ec.message()};
    auto written = writeFileAtomically(file.string(), toJson(report).dump());
    if (!written) return written;
    prune(file.parent_path());
    return {};
}

verify::Report verifyPlanCached(const Plan& plan, const verify::Options& options, bool* reused)
{
    const std::string key = verificationKey(plan, options);
    if (auto stored = loadVerification(key)) {
        if (reused) *reused = true;
        return std::move(*stored);
    }
    if (reused) *reused = false;
    verify::Report fresh = verifyPlan(plan, options);
    (void)storeVerification(key, fresh);  // without the cache the next export verifies again: nothing lost
    return fresh;
}

}  // namespace taiwa
