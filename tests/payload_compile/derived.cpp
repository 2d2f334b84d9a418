// Planted for test_payload_compile (run.cmake): a step payload that derives
// from MillingGeometry. StepPayload must refuse it at compile time, with its
// static_assert's words (model/step_payload.h).
#include "model/step_payload.h"

namespace {
struct DerivedPasses : taiwa::MillingGeometry {
    static constexpr const char* kName = "planted derived passes";
    int passes = 0;
    friend bool operator==(const DerivedPasses&, const DerivedPasses&) = default;
};
}  // namespace

taiwa::StepPayload plantedPayload() { return DerivedPasses{}; }
