// Jobs from STEP files (step_job.h): a lathe job from a turned solid, a
// milling job from a face set.
#include "job/step_job.h"

#include "machine/machine.h"
#include "modules/registry.h"
#include "job/job_file.h"
#include "occt/step_import.h"
#include "occt/surface_step.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>

namespace taiwa {

Result<Job> latheJobFromStep(const std::string& stepPath, const std::string& material)
{
    auto imported = turning::importStepProfiles(stepPath);
    if (!imported) return imported.failure();
    const ModuleKind* turn = nullptr;
    for (const ModuleKind* k : moduleKinds())
        if (k->machineKind() == MachineKind::Lathe && k->turnedProfile(k->makeDefault({}))) turn = k;
    if (!turn) throw std::logic_error("no module kind takes a turned profile");
    const Machine* lathe = findMachine("lathe");
    if (!lathe) throw std::logic_error("the machine library has no lathe");
    Job job;
    job.name = std::filesystem::path(stepPath).stem().string();
    job.material = material;
    job.machine = lathe->id;
    double rMax = 0.0, zMin = 0.0;
    for (const auto* p : {&imported->outer, &imported->inner}) {
        if (!*p) continue;
        rMax = std::max(rMax, (*p)->startX / 2.0);
        zMin = std::min(zMin, (*p)->startZ);
        for (const auto& r : (*p)->rows) {
            rMax = std::max(rMax, r.x / 2.0);
            zMin = std::min(zMin, r.z);
        }
        MachiningUnit unit;
        unit.name = (*p)->side == turning::ProfileSide::Outer ? "Outside" : "Bore";
        unit.module = turn->makeDefault({});
        turn->setTurnedProfile(unit.module, **p);
        job.units.push_back(std::move(unit));
    }
    BarStock bar;
    bar.face = 1.0;
    bar.diameter = std::ceil(2.0 * rMax + 2.0);
    bar.length = std::ceil(-zMin + bar.face + lathe->jawLength);
    job.bar = bar;
    job.stock = {};
    return job;
}

Result<SurfaceImport> surfaceJobFromStep(const std::string& stepPath, const std::string& material, double spacing)
{
    auto sampled = surface::sampleStepFaces(stepPath, spacing);
    if (!sampled) return sampled.failure();
    double x0 = 1e300, y0 = 1e300, z0 = 1e300, x1 = -1e300, y1 = -1e300, z1 = -1e300;
    for (const auto& path : sampled->paths)
        for (const Point3& p : path) {
            x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), z0 = std::min(z0, p.z);
            x1 = std::max(x1, p.x), y1 = std::max(y1, p.y), z1 = std::max(z1, p.z);
        }
    // Through the job reader, as a file would come: the unit's keys are its
    // module's (modules/surface), checked there.
    nlohmann::json paths = nlohmann::json::array();
    for (const auto& path : sampled->paths) {
        nlohmann::json points = nlohmann::json::array();
        for (const Point3& p : path) points.push_back({p.x, p.y, p.z - z1});
        paths.push_back(std::move(points));
    }
    const nlohmann::json unit = {{"module", "SURFACE"}, {"name", std::filesystem::path(stepPath).stem().string()},
                                 {"surface", std::move(paths)}, {"scallop", 0.02}, {"allowance", 0.3}};
    const nlohmann::json j = {{"format", "taiwa-job"},
                              {"version", Job::kFormatVersion},
                              {"name", std::filesystem::path(stepPath).stem().string()},
                              {"lengthUnit", "mm"},
                              {"material", material},
                              {"machine", "vmc"},
                              {"stock", {{"shape", "block"}, {"x", x0}, {"y", y0}, {"width", x1 - x0}, {"length", y1 - y0},
                                         {"height", std::ceil(z1 - z0 + 5.0)}}},
                              {"units", nlohmann::json::array({unit})}};
    JobReadResult read = readJob(j.dump());
    if (!read.job)
        throw std::logic_error("the job made from a face set does not read: " +
                               (read.diagnostics.empty() ? std::string("?") : read.diagnostics.front().message));
    return SurfaceImport{std::move(*read.job), z1, sampled->deviation};
}

}  // namespace taiwa
