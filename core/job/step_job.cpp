// A lathe job from a STEP model (step_job.h).
#include "job/step_job.h"

#include "machine/machine.h"
#include "modules/registry.h"
#include "occt/step_import.h"

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

}  // namespace taiwa
