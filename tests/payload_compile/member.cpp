// Planted for test_payload_compile (run.cmake): a step payload that holds
// its geometry as its member `milling`, as the modules' payloads do. It must
// compile, so that the refusal of derived.cpp is the static_assert's alone.
#include "model/step_payload.h"

namespace {
struct MemberPasses {
    static constexpr const char* kName = "planted member passes";
    taiwa::MillingGeometry milling;
    int passes = 0;
    friend bool operator==(const MemberPasses&, const MemberPasses&) = default;
};
}  // namespace

taiwa::StepPayload plantedPayload() { return MemberPasses{}; }
