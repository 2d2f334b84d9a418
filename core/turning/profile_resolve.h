// From the profile table as typed to exact edges: each row's line or arc
// (an arc from its radius or its centre), the chamfers and roundings of the
// corner fields cut in, every edge with its stable id. Whatever cannot be
// built is a problem naming the row and field; the edges that could be built
// are still returned for the view.
#pragma once

#include "model/job.h"
#include "model/turned.h"

#include <string>
#include <vector>

namespace taiwa::turning {

// A refusal of one field of a turned-profile unit: "rows[3].radius" (rows
// and allowance rows numbered from 1, as the station shows them).
struct FieldProblem {
    std::string field;
    std::string message;
    friend bool operator==(const FieldProblem&, const FieldProblem&) = default;
};

struct Resolution {
    ResolvedProfile profile;
    std::vector<FieldProblem> problems;
    bool ok() const { return problems.empty(); }
};

// The most rows a profile and its allowance table may have: the chain check
// is quadratic in the rows and the union grows with the allowance rows
// (docs/turning.md); a job beyond them is refused, the station draws nothing.
constexpr std::size_t kMaxProfileRows = 1000, kMaxAllowanceRows = 200;

std::string rowField(std::size_t row, const char* key);        // "rows[3].radius" for index 2
std::string allowanceField(std::size_t row, const char* key);  // "allowances[1].edge" for index 0

// Lengths of `p` in mm; messages quote them in `shown`.
Resolution resolveProfile(const TurnedProfile& p, LengthUnit shown = LengthUnit::Millimetre);

// The closed outline of the part's half-section that the profile bounds:
// the profile, then back to the axis (outer profiles) or out to `outerRadius`
// (inner profiles) and to the start. Lines only are added.
std::vector<Segment> closure(const ResolvedProfile& p, double outerRadius);

}  // namespace taiwa::turning
