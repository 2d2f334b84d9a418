// Names of the turned-profile value types (model/turned.h) as the job file,
// the station and steps.json spell them.
#include "model/turned.h"

#include <array>
#include <utility>

namespace taiwa::turning {

namespace {

template <class E, std::size_t N>
std::optional<E> fromKey(const std::array<std::pair<E, const char*>, N>& table, const std::string& key)
{
    for (const auto& [value, name] : table)
        if (key == name) return value;
    return std::nullopt;
}
template <class E, std::size_t N>
const char* toKeyIn(const std::array<std::pair<E, const char*>, N>& table, E value)
{
    for (const auto& [v, name] : table)
        if (v == value) return name;
    return "";
}

constexpr std::array<std::pair<ElementKind, const char*>, 3> kElementKinds{
    {{ElementKind::Line, "line"}, {ElementKind::ArcCW, "cw"}, {ElementKind::ArcCCW, "ccw"}}};
constexpr std::array<std::pair<CornerKind, const char*>, 3> kCornerKinds{
    {{CornerKind::None, "none"}, {CornerKind::Chamfer, "chamfer"}, {CornerKind::Rounding, "rounding"}}};
constexpr std::array<std::pair<GrooveKind, const char*>, 5> kGrooveKinds{{{GrooveKind::Auto, "auto"},
                                                                          {GrooveKind::None, "none"},
                                                                          {GrooveKind::Lateral, "lateral"},
                                                                          {GrooveKind::Longitudinal, "longitudinal"},
                                                                          {GrooveKind::Ring, "ring"}}};
constexpr std::array<std::pair<ProfileSide, const char*>, 2> kSides{
    {{ProfileSide::Outer, "outer"}, {ProfileSide::Inner, "inner"}}};

}  // namespace

std::string edgeId(int rowId) { return "E" + std::to_string(rowId); }
std::string cornerEdgeId(int rowId) { return edgeId(rowId) + ".c"; }

const char* toKey(ElementKind k) { return toKeyIn(kElementKinds, k); }
const char* toKey(CornerKind k) { return toKeyIn(kCornerKinds, k); }
const char* toKey(GrooveKind k) { return toKeyIn(kGrooveKinds, k); }
const char* toKey(ProfileSide s) { return toKeyIn(kSides, s); }
std::optional<ElementKind> elementKindFromKey(const std::string& s) { return fromKey(kElementKinds, s); }
std::optional<CornerKind> cornerKindFromKey(const std::string& s) { return fromKey(kCornerKinds, s); }
std::optional<GrooveKind> grooveKindFromKey(const std::string& s) { return fromKey(kGrooveKinds, s); }
std::optional<ProfileSide> profileSideFromKey(const std::string& s) { return fromKey(kSides, s); }

const char* toKey(Joint j)
{
    switch (j) {
    case Joint::FreeEnd: return "free end";
    case Joint::UpTo90: return "0-90";
    case Joint::Obtuse: return "90-180";
    case Joint::Tangent: return "180";
    case Joint::Concave: return "above 180";
    case Joint::BothSet: return "both ground";
    }
    return "";
}

const char* toKey(Origin o)
{
    switch (o) {
    case Origin::Original: return "original";
    case Origin::Moved: return "moved";
    case Origin::Side: return "side";
    case Origin::Groove: return "groove";
    }
    return "";
}

}  // namespace taiwa::turning
