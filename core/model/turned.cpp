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
constexpr std::array<std::pair<Joint, const char*>, 6> kJoints{{{Joint::FreeEnd, "free end"},
                                                                {Joint::UpTo90, "0-90"},
                                                                {Joint::Obtuse, "90-180"},
                                                                {Joint::Tangent, "180"},
                                                                {Joint::Concave, "above 180"},
                                                                {Joint::BothSet, "both ground"}}};
constexpr std::array<std::pair<Origin, const char*>, 4> kOrigins{
    {{Origin::Original, "original"}, {Origin::Moved, "moved"}, {Origin::Side, "side"}, {Origin::Groove, "groove"}}};
static_assert(kJoints.size() == static_cast<std::size_t>(Joint::BothSet) + 1, "a key for every joint");
static_assert(kOrigins.size() == static_cast<std::size_t>(Origin::Groove) + 1, "a key for every origin");

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

const char* toKey(Joint j) { return toKeyIn(kJoints, j); }
const char* toKey(Origin o) { return toKeyIn(kOrigins, o); }

}  // namespace taiwa::turning
