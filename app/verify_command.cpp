// taiwa verify's report, the verification before an export, the sheet's
// pictures of the steps and of the setup (verify_command.h).
#include "app/verify_command.h"

#include "export/verification_cache.h"

#include "pipeline/pipeline.h"
#include "post/post.h"
#include "verify/tape_readback.h"
#include "verify/two_path_check.h"

#include "export/sheet_pictures.h"

#include <nlohmann/json.hpp>

#include <iostream>
#include <stdexcept>

namespace taiwa::app {

// The plan verified, its findings placed on the tape of `dialect`.
verify::Report verified(const Plan& plan, const Options& o, const PostOptions& post, std::optional<PostedJob>& posted,
                        bool* reused)
{
    verify::Options v;
    v.resolution = o.resolution.value_or(verify::defaultResolution(plan));
    if (!o.resolution) v.maxCellVisits = verify::kDefaultCellVisits;  // a cell size the operator chose is kept
    verify::Report report = o.cache ? verifyPlanCached(plan, v, reused) : verify::verifyPlan(plan, v);
    if (!o.cache && reused) *reused = false;
    // The programs are posted once, to be read back (verify/tape_readback.h;
    // a two-path lathe's tape only to place the findings: its programs are
    // read) and written by the export as they are.
    try {
        const PostedJob& programs = posted.emplace(postJob(plan, post));
        verify::placeOnTape(report, programs.tape);
        verify::readBack(report, plan, programs, post::dialectNamed(post.dialect), post);
    } catch (const Refusal&) {
        posted.reset();
        // A dialect that cannot post this job: the findings keep their moves.
    }
    return report;
}

namespace {

// "0 gouges, 1 collisions, …"
std::string summary(const verify::Report& r)
{
    using K = verify::FindingKind;
    return std::to_string(r.count(K::Gouge)) + " gouges, " + std::to_string(r.count(K::Collision)) + " collisions, " +
           std::to_string(r.count(K::RapidIntoStock)) + " rapids into stock, " + std::to_string(r.count(K::TravelLimit)) +
           " travel limits, " + std::to_string(r.count(K::RestMaterial)) + " with material left, " +
           std::to_string(r.count(K::UnplannedMove) + r.count(K::UnreadTape) + r.count(K::UnpairedWait)) + " on the tape read back";
}

}  // namespace

bool printVerification(const Plan& plan, const Options& o, const std::string& name, const std::string& dialect)
{
    std::optional<PostedJob> posted;
    const verify::Report r = verified(plan, o, postOptions(plan, dialect), posted);
    // A two-path lathe: its balanced roughing on the timeline (deadlocks, lags below the set revolutions).
    const auto twoPath = verify::checkTwoPath(plan);
    const bool twoPathFault = twoPath && !twoPath->findings.empty();
    if (o.json) {
        nlohmann::ordered_json j;
        j["job"] = name;
        j["resolution"] = r.resolution;
        j["grid"] = {r.columns, r.rows};
        if (!r.skipped.empty()) j["skipped"] = r.skipped;
        if (!r.coarsened.empty()) j["coarsened"] = r.coarsened;
        j["findings"] = nlohmann::ordered_json::array();
        for (const auto& f : r.findings) {
            nlohmann::ordered_json e;
            e["kind"] = verify::toKey(f.kind);
            if (!f.part.empty()) e["part"] = f.part;
            e["fatal"] = f.fatal();
            e["step"] = f.step >= 0 ? nlohmann::ordered_json(f.step + 1) : nlohmann::ordered_json();
            e["unit"] = f.step >= 0 ? nlohmann::ordered_json(plan.steps[static_cast<std::size_t>(f.step)].unit + 1)
                                    : nlohmann::ordered_json();
            e["move"] = f.move >= 0 ? nlohmann::ordered_json(f.move + 1) : nlohmann::ordered_json();
            e["line"] = f.line > 0 ? nlohmann::ordered_json(f.line) : nlohmann::ordered_json();
            if (!f.program.empty()) e["program"] = f.program;  // a program other than the tape: STEM.p2.nc, STEM.u1.probe.nc
            e["position"] = {f.position.x, f.position.y, f.position.z};
            e["size"] = f.size;
            e["area"] = f.area;
            e["message"] = verify::describe(f, plan);
            j["findings"].push_back(e);
        }
        if (twoPath)
            j["twoPath"] = {{"findings", twoPath->findings}, {"seconds", twoPath->seconds}, {"leastLag", twoPath->leastLag}};
        j["fatal"] = r.fatal() || twoPathFault;
        std::cout << j.dump(2) << '\n';
    } else {
        for (const auto& f : r.findings) std::cout << name << ": " << verify::describe(f, plan) << '\n';
        if (!r.skipped.empty()) std::cout << name << ": not verified: " << r.skipped << '\n';
        if (!r.coarsened.empty()) std::cout << name << ": " << r.coarsened << '\n';
        else if (plan.mmJob.bar)  // the exact half-section: no grid
            std::cout << name << ": verified at " << r.resolution << " mm (half-section): " << summary(r) << '\n';
        else
            std::cout << name << ": verified at " << r.resolution << " mm (" << r.columns << " x " << r.rows
                      << " cells): " << summary(r) << '\n';
        if (twoPath) {
            for (const auto& f : twoPath->findings) std::cout << name << ": " << f << '\n';
            std::cout << name << ": two-path timeline: " << twoPath->findings.size() << " findings, roughing "
                      << twoPath->seconds << " s, least lag " << twoPath->leastLag << " revolutions\n";
        }
    }
    return r.fatal() || twoPathFault;
}

// Drawn by the core on the processor: no display needed (export/sheet_pictures.h).
void picturesFor(const Plan& plan, ExportOptions& e)
{
    if (const std::string problem = addSheetPictures(plan, e); !problem.empty())
        std::cerr << "taiwa: export: pictures missing: " << problem << '\n';
}

}  // namespace taiwa::app
