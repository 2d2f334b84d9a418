// The lathe tape oracle (turning_oracle.h): the verdict on a lathe tape from
// rs274's moves. Its own geometry of lines and arcs in the (z, r) half-plane,
// the part's material and the tools' shapes are in turning_oracle_shapes.h,
// the bar cut move by move in turning_oracle_stock.h.
#include "support/turning_oracle.h"

#include "support/turning_oracle_stock.h"

#include "post/lathe_post.h"
#include "model/turn_path.h"

#include <cstdio>

namespace taiwa::test {

using namespace lathe_oracle;

namespace {

int orientationFor(const Plan& plan, int toolId)
{
    for (const auto& s : plan.steps)
        if (s.tool && s.tool->toolId == toolId && turnOf(s)) return turnOf(s)->orientation;
    return 0;
}

const Tool* libraryTool(const Plan& plan, int id)
{
    if (const Tool* t = plan.tool(id)) return t;
    return findTool(plan.tools, id);
}

}  // namespace

Point2 orientationOffset(int orientation, double r)
{
    // LinuxCNC's lathe tool orientations: the controlled (imaginary tip)
    // point from the nose centre, X a radius; 9 (and a zero radius) is the
    // centre itself.
    switch (orientation) {
    case 1: return {r, -r};   // X -r, Z +r
    case 2: return {-r, -r};  // X -r, Z -r: outside, cutting toward the chuck
    case 3: return {-r, r};   // X +r, Z -r: boring toward the chuck
    case 4: return {r, r};    // X +r, Z +r
    default: return {0, 0};   // 5-8 (tip on an axis) are not modelled: no plan uses them with a nose radius
    }
}

std::string latheToolTable(const Plan& plan)
{
    std::string out;
    for (const auto& [station, id] : latheStations(plan.steps)) {
        const Tool* t = libraryTool(plan, id);
        const bool drill = t && (t->type == ToolType::Drill || t->type == ToolType::CentreDrill);
        const double nose = t && !drill ? t->cornerRadius : 0.0;
        char line[160];
        std::snprintf(line, sizeof line, "T%d P%d X0 Z0 D%.6f Q%d ;library T%d\n", station, station, 2.0 * nose / 25.4,
                      orientationFor(plan, id), id);
        out += line;
    }
    return out;
}

LatheVerdict judgeLatheTape(const Plan& plan, const Rs274Result& run, const LatheOracleOptions& o)
{
    LatheVerdict v;
    if (!plan.mmJob.bar) {
        v.problems << "not a lathe job: no bar stock";
        return v;
    }
    const BarStock& bar = *plan.mmJob.bar;
    const double k = run.inches ? 25.4 : 1.0;
    const auto zr = [&](const Point3& p) { return P{k * p.z, k * p.x}; };
    const double rTop = bar.diameter / 2.0 + 5.0;

    std::map<int, Shape> shapes;  // by turret station
    for (const auto& [station, id] : latheStations(plan.steps)) {
        const Tool* t = libraryTool(plan, id);
        if (!t) {
            v.problems << QString("station %1: library tool T%2 is not in the plan").arg(station).arg(id);
            continue;
        }
        shapes[station] = shapeOf(*t, orientationFor(plan, id));
        const int q = shapes[station].orientation;
        if (shapes[station].kind == Shape::Insert && t->cornerRadius > 0 && (q < 1 || q > 4))
            v.problems << QString("station %1: T%2 has a nose radius and orientation %3, which the oracle does not model").arg(station).arg(id).arg(q);
        if (shapes[station].kind == Shape::None)
            v.problems << QString("station %1: T%2 %3 is no lathe tool").arg(station).arg(id).arg(QString::fromStdString(t->name));
    }
    for (const auto& s : plan.steps)
        if (s.tool && turnOf(s) && turnOf(s)->orientation != orientationFor(plan, s.tool->toolId))
            v.problems << QString("%1 uses T%2 with orientation %3, the tool table has %4")
                              .arg(QString::fromStdString(s.label())).arg(s.tool->toolId).arg(turnOf(s)->orientation)
                              .arg(orientationFor(plan, s.tool->toolId));

    std::map<int, Material> materials, drawn;  // by unit: the deformed profile's material, the part as drawn
    for (const auto& part : plan.turned)
        if (!part.deformed.edges.empty() && !part.profile.edges.empty()) {
            materials.emplace(part.unit, Material(part, bar));
            drawn.emplace(part.unit, Material(part, bar, true));
        }
    double zBack = -kInf;
    for (const auto& [u, m] : materials) zBack = std::max(zBack, m.zFront() + 10.0);
    zBack = std::max(zBack, bar.face + 10.0);

    Stock stock(bar, o.cell);
    const std::size_t nSteps = plan.steps.size();
    std::vector<std::vector<P>> noseCentres(nSteps);              // finishing and facing: every sampled nose centre
    std::vector<std::vector<std::vector<P>>> toolSweeps(nSteps);   // grooving, parting, drilling: each cut's swept outline
    std::vector<int> cuts(nSteps, 0);
    int reported = 0;
    const auto problem = [&](const QString& s) {
        if (++reported <= 40) v.problems << s;
        else if (reported == 41) v.problems << "(more problems left out)";
    };

    for (std::size_t i = 0; i < run.moves.size(); ++i) {
        const CanonMove& m = run.moves[i];
        const P a = zr(m.start), b = zr(m.end);
        const auto st = shapes.find(m.tool);
        const Shape none;
        const Shape& s = st == shapes.end() ? none : st->second;
        const QString at = QString("move %1 (step %2, station T%3) %4 to %5").arg(i).arg(m.step).arg(m.tool).arg(where(a), where(b));

        if (m.kind == CanonMove::Traverse) {
            ++v.rapids;
            double z = 0;
            const double ov = stock.overlap(s, s.ref(a), s.ref(b), &z);
            if (ov > v.worstRapid) {
                v.worstRapid = ov;
                v.worstRapidMove = QString("%1, at Z%2").arg(at, mm(z));
            }
            if (ov > o.tolerance) problem(QString("rapid into stock not yet cut: %1 overlaps the stock left by %2 mm at Z%3").arg(at, mm(ov), mm(z)));
            continue;
        }
        if (m.plane != 18) problem(QString("cut outside G18: %1").arg(at));
        if (m.step < 1 || m.step > static_cast<int>(nSteps)) {
            problem(QString("cut outside any step: %1").arg(at));
            continue;
        }
        const std::size_t si = static_cast<std::size_t>(m.step - 1);
        const Step& step = plan.steps[si];
        ++cuts[si];
        ++v.feeds;
        if (!step.tool || s.id != step.tool->toolId)
            problem(QString("%1 cuts with library T%2, the step's tool is T%3").arg(at).arg(s.id).arg(step.tool ? step.tool->toolId : 0));
        if (s.kind == Shape::None) continue;

        // The move as reference points (nose centres for inserts): a line
        // its two ends, an arc as chords; and sampled every `sample` mm.
        std::vector<P> path{s.ref(a)};
        if (m.kind == CanonMove::Arc) {
            for (const auto& q : sampleArc(m, o.sample / k)) path.push_back(s.ref(zr(q)));
        } else {
            path.push_back(s.ref(b));
        }
        std::vector<P> pts{path.front()};
        for (std::size_t j = 0; j + 1 < path.size(); ++j) {
            const int n = std::max(1, static_cast<int>(std::ceil(distance(path[j], path[j + 1]) / o.sample)));
            for (int q = 1; q <= n; ++q) pts.push_back(path[j] + (static_cast<double>(q) / n) * (path[j + 1] - path[j]));
        }

        const auto mat = materials.find(step.unit);
        if (mat == materials.end()) {
            problem(QString("%1: unit %2 has no turned profile").arg(at).arg(step.unit + 1));
        } else if (s.kind == Shape::Insert) {
            const Material& part = mat->second;
            const bool roughing = step.kind == StepKind::TurnRoughing;
            const bool finishing = step.kind == StepKind::TurnFinishing;
            const bool threading = step.kind == StepKind::Threading;
            const double allowance = roughing && turnOf(step) ? std::min(turnOf(step)->allowanceX, turnOf(step)->allowanceZ) : 0.0;
            double worst = -kInf, closest = kInf, nearest = kInf;
            P worstAt{}, closestAt{}, nearestAt{};
            for (const P& c : pts) {
                const double sd = threading ? part.threadedDistance(c) : part.signedDistance(c);
                if (s.nose - sd > worst) {
                    worst = s.nose - sd;
                    worstAt = c;
                }
                if (roughing && sd - s.nose - allowance < closest) {
                    closest = sd - s.nose - allowance;
                    closestAt = c;
                }
                if (finishing) {
                    const double d = part.profileDistance(c);
                    if (d < nearest) {
                        nearest = d;
                        nearestAt = c;
                    }
                }
                if (finishing || step.kind == StepKind::Facing) noseCentres[si].push_back(c);
            }
            if (finishing && nearest < s.nose - o.tolerance)
                problem(QString("finishing nose centre %1 mm from the profile, less than the nose radius %2: %3, nearest at nose centre Z%4 R%5")
                            .arg(mm(nearest), mm(s.nose), at, mm(nearestAt.x), mm(nearestAt.y)));
            v.worstGouge = std::max(v.worstGouge, worst);
            if (worst > o.tolerance)
                problem(QString("gouge of %1 mm into unit %2's part by %3 (nose R%4): %5, deepest at nose centre Z%6 R%7")
                            .arg(mm(worst)).arg(step.unit + 1).arg(QString::fromStdString(step.label()), mm(s.nose), at, mm(worstAt.x), mm(worstAt.y)));
            // The whole cutting corner, for the reader.
            double body = -kInf, bodyDrawn = -kInf;
            for (std::size_t j = 0; j + 1 < path.size(); ++j) {
                std::vector<P> both = insertCorner(s, path[j], 5.0);
                if (both.empty()) break;
                const auto more = insertCorner(s, path[j + 1], 5.0);
                both.insert(both.end(), more.begin(), more.end());
                const auto hull = convexHull(both);
                body = std::max(body, penetration(part, hull, 0.05));
                bodyDrawn = std::max(bodyDrawn, penetrationOfBoth(part, drawn.at(step.unit), hull, 0.05));
            }
            if (body > std::max(worst, 0.0) + o.tolerance)
                v.insertBody << QString("step %1 %2: %3 mm into the deformed profile, %4 mm into the finished part (as drawn, less relief grooves); %5")
                                    .arg(m.step).arg(QString::fromStdString(step.label()), mm(body), mm(bodyDrawn), at);
            if (roughing) {
                v.closestRoughing = std::min(v.closestRoughing, closest);
                if (closest < -o.tolerance)
                    problem(QString("roughing leaves less than its allowance %1 mm: the nose comes %2 mm closer, %3, at nose centre Z%4 R%5")
                                .arg(mm(allowance), mm(-closest), at, mm(closestAt.x), mm(closestAt.y)));
            }
        } else {
            const Material& part = mat->second;
            for (std::size_t j = 0; j + 1 < path.size(); ++j) {
                std::vector<P> both = outline(s, path[j], rTop, zBack);
                const auto more = outline(s, path[j + 1], rTop, zBack);
                both.insert(both.end(), more.begin(), more.end());
                const auto hull = convexHull(both);
                const double pen = penetration(part, hull, o.sample);
                v.worstGouge = std::max(v.worstGouge, pen);
                if (pen > o.tolerance)
                    problem(QString("gouge of %1 mm into unit %2's part by %3 (%4): %5")
                                .arg(mm(pen)).arg(step.unit + 1).arg(QString::fromStdString(step.label()), QString::fromStdString(s.name), at));
                toolSweeps[si].push_back(hull);
            }
            if (s.kind == Shape::Drill && (std::abs(a.y) > 1e-6 || std::abs(b.y) > 1e-6))
                problem(QString("a drill off the axis: %1").arg(at));
        }
        for (std::size_t j = 0; j + 1 < path.size(); ++j) stock.cut(s, path[j], path[j + 1]);
    }

    // Every step cuts.
    for (std::size_t si = 0; si < nSteps; ++si)
        if (cuts[si] == 0) problem(QString("step %1 %2 cuts nothing").arg(si + 1).arg(QString::fromStdString(plan.steps[si].label())));

    // Finishing touches every element it must; the facing the front face.
    for (const auto& [unitIndex, part] : materials) {
        std::vector<P> finish, facing;
        double rFinish = 0, rFacing = 0;
        std::vector<const std::vector<P>*> blades;
        for (std::size_t si = 0; si < nSteps; ++si) {
            const Step& s = plan.steps[si];
            if (s.unit != unitIndex || !s.tool) continue;
            const Tool* t = libraryTool(plan, s.tool->toolId);
            if (s.kind == StepKind::TurnFinishing) {
                finish.insert(finish.end(), noseCentres[si].begin(), noseCentres[si].end());
                rFinish = t ? t->cornerRadius : 0;
            } else if (s.kind == StepKind::Facing) {
                facing.insert(facing.end(), noseCentres[si].begin(), noseCentres[si].end());
                rFacing = t ? t->cornerRadius : 0;
            } else {
                for (const auto& h : toolSweeps[si]) blades.push_back(&h);
            }
        }
        if (finish.empty()) continue;
        for (std::size_t ei = 0; ei < part.profile().size(); ++ei) {
            const Elem& e = part.profile()[ei];
            if (e.origin != turning::Origin::Original && e.origin != turning::Origin::Moved) continue;
            const bool front = part.onFrontFace(ei);
            const std::vector<P>& path = front ? facing : finish;
            const double rn = front ? rFacing : rFinish;
            if (front && path.empty()) continue;
            if (lengthOf(e) <= 2.0 * rn) continue;
            double d = kInf;
            for (const P& c : path) d = std::min(d, distanceTo(e, c));
            // A blade or drill finishes the element when it lies on all of it:
            // the farthest point of the element from every such cut.
            double blade = kInf;
            if (!front && !blades.empty()) {
                std::vector<P> corners, pts;
                flattenInto(e, 1e-4, corners);
                corners.push_back(e.b);
                for (std::size_t j = 0; j + 1 < corners.size(); ++j) {
                    const int n = std::max(1, static_cast<int>(std::ceil(distance(corners[j], corners[j + 1]) / 0.02)));
                    for (int q = 0; q < n; ++q) pts.push_back(corners[j] + (static_cast<double>(q) / n) * (corners[j + 1] - corners[j]));
                }
                pts.push_back(e.b);
                blade = 0.0;
                for (const P& p : pts) {
                    double nearest = kInf;
                    for (const auto* h : blades) nearest = std::min(nearest, distanceToPolygon(*h, p));
                    blade = std::max(blade, nearest);
                }
            }
            const bool touched = std::abs(d - rn) <= o.tolerance || blade <= o.tolerance;
            v.touched << QString("unit %1 %2 %3 %4").arg(unitIndex + 1).arg(QString::fromStdString(e.id), mm(d - rn), blade < kInf ? mm(blade) : "-");
            if (!touched)
                problem(QString("unit %1: %2 (%3, %4 mm long) is not %5 at the nose radius: the nearest nose centre is %6 mm from it, "
                                "not the nose radius %7%8")
                            .arg(unitIndex + 1).arg(QString::fromStdString(e.id), QString::fromLatin1(turning::toKey(e.origin)), mm(lengthOf(e)),
                                 QString::fromLatin1(front ? "faced" : "finished"),
                                 mm(d), mm(rn), blade < kInf ? QString("; blades and drills stay up to %1 mm off it").arg(mm(blade)) : QString()));
        }
    }

    // Grooving: withdrawn along the outward normal by the withdrawal.
    for (std::size_t si = 0; si < nSteps; ++si) {
        const Step& s = plan.steps[si];
        if (s.kind != StepKind::Grooving || !turnOf(s)) continue;
        const QString name = QString("step %1 %2").arg(si + 1).arg(QString::fromStdString(s.label()));
        std::optional<std::size_t> last;
        for (std::size_t i = 0; i < run.moves.size(); ++i)
            if (run.moves[i].step == static_cast<int>(si + 1) && run.moves[i].kind != CanonMove::Traverse) last = i;
        if (!last) continue;  // said above: cuts nothing
        const CanonMove& w = run.moves[*last];
        if (w.kind != CanonMove::Feed || *last + 1 >= run.moves.size() || run.moves[*last + 1].kind != CanonMove::Traverse) {
            problem(name + ": its last cut is not a straight feed followed by a rapid");
            continue;
        }
        const auto mat = materials.find(s.unit);
        const auto st = shapes.find(w.tool);
        if (mat == materials.end() || st == shapes.end()) continue;
        const P a = zr(w.start), b = zr(w.end);
        const double width = st->second.width;
        const P mid{a.x - width / 2.0, a.y};
        std::size_t nearest = 0;
        double dn = kInf;
        for (std::size_t ei = 0; ei < mat->second.profile().size(); ++ei) {
            const double d = distanceTo(mat->second.profile()[ei], mid);
            if (d < dn) {
                dn = d;
                nearest = ei;
            }
        }
        const P q = nearestOn(mat->second.profile()[nearest], mid);
        const P n = mat->second.airNormal(nearest, q);
        const P move = b - a;
        const double len = length(move), off = std::abs(cross(move, n)), along = dot(move, n);
        if (std::abs(len - turnOf(s)->withdrawal) > o.tolerance || off > o.tolerance || along <= 0)
            problem(QString("%1: the withdrawal %2 to %3 is %4 mm long (the step's withdrawal %5 mm), %6 mm off the outward normal "
                            "(%7, %8) of %9")
                        .arg(name, where(a), where(b), mm(len), mm(turnOf(s)->withdrawal), mm(off), mm(n.x), mm(n.y),
                             QString::fromStdString(mat->second.profile()[nearest].id)));
    }
    return v;
}

}  // namespace taiwa::test
