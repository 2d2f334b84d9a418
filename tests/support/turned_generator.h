// Random valid turned profiles with grinding-allowance tables, for proving
// the grinding allowance by generation (tests/test_turning_generator.cpp
// replays a few hundred seeds in CI, bench/bench_turning_generator.cpp
// 10,000): outer and inner (bore) profiles of faces, cylinders, tapers,
// shoulders up and down, convex and concave arcs, chamfers and roundings,
// with 1-4 picked edges, allowances, typed adjustments and relief grooves
// of every kind (auto, none, lateral, longitudinal, ring; widths, depths).
// A seed gives the same profile on every machine (its own 64-bit generator
// and its own uniform numbers, none of <random>'s distributions). Only
// profiles resolveProfile accepts are returned; the allowance table may
// still be refused by the deformer, which the caller counts.
//
// And the check the generator exists for: how deep the deformed profile
// goes inside the part as drawn (no allowance or groove may take finished
// material off), computed exactly on the lines and arcs.
#pragma once

#include "model/turned.h"
#include "turning/allowance.h"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace taiwa::test {

struct GeneratedProfile {
    turning::TurnedProfile profile;   // rows and allowance rows, in mm
    turning::AllowanceOptions options;  // the finishing tool's nose radius for tangent joints
    std::uint64_t seed = 0;
    int attempts = 0;  // profiles drawn until one resolved
    std::vector<std::string> shapes;  // generateLathePart: "ridge", "front rounding", "fillet under 0.4", …
};

GeneratedProfile generateTurnedProfile(std::uint64_t seed);

// Lathe parts for planning (issue 33, item 3): the same drawing with the
// shapes the planner tripped on added: acute ridges (a taper rising 45-75°,
// then one falling 30-60°), a rounding at the front corner, roundings at
// concave corners (fillets) smaller and larger than the library's nose
// radii; an allowance table on 60% of them. A stream of its own: the seeds
// of generateTurnedProfile draw what they drew before.
GeneratedProfile generateLathePart(std::uint64_t seed);

// The deepest point of the deformed profile inside the part (the region the
// profile as drawn bounds, closed as the deformer closes it): its depth
// (0 when none is inside) and where, on which deformed edge.
struct Intrusion {
    double depth = 0.0;
    turning::ZR where;
    std::string edge;
};
Intrusion deepestIntoPart(const turning::ResolvedProfile& part, const turning::DeformedProfile& deformed);

// One seed generated, deformed and checked.
struct SeedResult {
    std::uint64_t seed = 0;
    bool inner = false;
    bool accepted = false;   // the deformer took the allowance table
    std::string refusedOn;   // else the key of its first problem's field ("grooveWidth", "allowances")
    std::string refusal;     // and its message
    std::vector<turning::GrooveMade> grooves;
    int nonSquareGrooves = 0;  // grooves at a corner whose angle is not 270°
    std::string groovesMade;   // "ring at 225° (E2 0.3, E3 0.2)", one per groove
    Intrusion intrusion;     // of the deformed profile into the part, when accepted
};
SeedResult runSeed(std::uint64_t seed);

// The counts of a run of seeds; a seed fails when its deformed profile goes
// more than `tolerance` into the part.
struct GeneratorTally {
    double tolerance = 1e-4;  // 0.1 µm
    std::size_t shown = 5;    // failing seeds the summary lists
    int profiles = 0, inner = 0, accepted = 0, nonSquareGrooves = 0;
    std::map<std::string, int> refusedOn, groovesByKind;
    std::map<std::string, std::string> refusalExample;  // the first message of each refusal on the whole table
    std::vector<SeedResult> failing;
    void add(const SeedResult& r);
    std::string summary() const;
};

// The generated profile as a lathe job (tests/support/turned_generator_plan.cpp):
// a bar 3 mm over its largest diameter (a bore's: 12 mm), 30 mm longer than
// the profile, planned with the default library and verified (core/verify):
// what stopped the plan, or the findings by kind.
struct PlanCheck {
    bool planned = false;
    bool fatal = false;     // a finding the tape must not run with (all but rest material)
    bool rs274Run = false;  // the linuxcnc tape was read by rs274 (planAndVerify's `rs274`)
    std::string rs274Refusal;  // and what it refused it for; empty: it ran
    std::vector<std::string> warnings;  // the plan's notes (warnings): what it leaves and why
    std::string refusedOn;  // the first error's field
    std::string refusal;
    std::map<std::string, int> findings;        // by kind: "gouge", "rapid-into-stock", …
    std::map<std::string, std::string> first;   // the first finding of each kind in words
};
// `rs274`: the linuxcnc tape also run through LinuxCNC's rs274 with the
// library's nose radii as its tool table (tests/support/rs274.h; hold the
// rs274 lock).
PlanCheck planAndVerify(const GeneratedProfile& g, bool rs274 = false);
// The same for a profile of the caller's (seed 0).
PlanCheck planAndVerify(const turning::TurnedProfile& profile, bool rs274);

// The counts of plans: planned, refused (by field), clean, and per finding
// kind the profiles that have it with their first seeds.
struct PlanTally {
    int profiles = 0, planned = 0, clean = 0, rs274Run = 0, rs274Refused = 0;
    std::map<std::string, int> refusedOn, withFinding, shapes;
    std::map<std::string, std::vector<std::uint64_t>> seeds;  // the first 5 per kind
    std::map<std::string, std::string> example;              // the first finding of each kind in words
    std::map<std::string, std::string> refusal;              // the first refusal on each field
    std::vector<std::uint64_t> rs274Seeds, fatalSeeds;  // the first 5 the tape of which rs274 refused / with a fatal finding
    std::string rs274Example;
    void add(std::uint64_t seed, const PlanCheck& c, const std::vector<std::string>& shapes = {});
    std::string summary() const;
};

}  // namespace taiwa::test
