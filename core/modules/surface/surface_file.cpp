// Module SURFACE's keys in the job file (surface_file.h, docs/surfaces.md):
// a curve as points [x, y, z] or as two plane projections (points [a, b] or
// a figure contour), the surface or the boundary as paths of points: the
// unit's job-file table (io/unit_keys.h), which its door reads and writes
// it by.
#include "modules/surface/surface_file.h"

#include "io/json_write.h"
#include "io/unit_keys.h"

#include <algorithm>
#include <string>
#include <vector>

namespace taiwa::surfacemod {

namespace {

bool isNumbers(const nlohmann::json& v, std::size_t n)
{
    if (!v.is_array() || v.size() != n) return false;
    return std::all_of(v.begin(), v.end(), [](const nlohmann::json& x) { return x.is_number(); });
}

std::vector<Point3> readPoints3(const io::ObjectFields& f, const nlohmann::json& v, const std::string& field)
{
    std::vector<Point3> out;
    if (!v.is_array()) {
        f.error(field, "expected an array of points [x, y, z]");
        return out;
    }
    for (std::size_t i = 0; i < v.size(); ++i) {
        if (isNumbers(v[i], 3)) out.push_back({v[i][0].get<double>(), v[i][1].get<double>(), v[i][2].get<double>()});
        else f.error(field + "[" + std::to_string(i) + "]", "expected a point [x, y, z]");
    }
    return out;
}

SurfaceCurve readCurve(const io::ObjectFields& f, const char* key)
{
    SurfaceCurve c;
    const nlohmann::json* v = f.find(key);
    if (!v) {
        f.error(key, "missing: give the curve's points or its two projections");
        return c;
    }
    if (!v->is_object()) {
        f.error(key, "expected an object with \"points\" or \"projections\"");
        return c;
    }
    const io::ObjectFields cf = f.nested(*v, std::string(key) + ".");
    cf.rejectUnknown(std::string("curve ") + key, {"points", "projections", "smooth"});
    if (const auto* s = cf.find("smooth")) {
        if (s->is_boolean()) c.smooth = s->get<bool>();
        else cf.error("smooth", "expected true or false");
    }
    if (const auto* p = cf.find("points")) c.points = readPoints3(f, *p, std::string(key) + ".points");
    if (const auto* ps = cf.find("projections")) {
        if (!ps->is_array()) cf.error("projections", "expected two projections {\"plane\", \"points\"}");
        else
            for (std::size_t i = 0; i < ps->size(); ++i) {
                const std::string where = "projections[" + std::to_string(i) + "]";
                const nlohmann::json& pj = (*ps)[i];
                if (!pj.is_object()) {
                    cf.error(where, "expected {\"plane\": \"XY\", \"points\": [[a, b], ...]}");
                    continue;
                }
                const io::ObjectFields pf = cf.nested(pj, where + ".");
                pf.rejectUnknown("a projection", {"plane", "points", "contour"});
                SurfaceProjection pr;
                pr.plane = pf.string("plane").value_or("");
                if (pf.find("contour")) {
                    // A figure contour instead of points: not both.
                    pr.contour = pf.string("contour").value_or("");
                    if (pf.find("points")) pf.error("points", "give the projection's points or its contour, not both");
                } else if (const auto* pts = pf.find("points"); pts && pts->is_array())
                    for (std::size_t k = 0; k < pts->size(); ++k) {
                        if (isNumbers((*pts)[k], 2)) pr.points.push_back({(*pts)[k][0].get<double>(), (*pts)[k][1].get<double>()});
                        else pf.error("points[" + std::to_string(k) + "]", "expected a point [a, b]");
                    }
                else
                    pf.error("points", "expected an array of points [a, b] or a \"contour\" of the figure");
                c.projections.push_back(std::move(pr));
            }
    }
    return c;
}

nlohmann::ordered_json point3(Point3 p)
{
    return nlohmann::ordered_json::array({io::number(p.x), io::number(p.y), io::number(p.z)});
}

nlohmann::ordered_json writeCurve(const SurfaceCurve& c)
{
    nlohmann::ordered_json j;
    if (!c.points.empty() || c.projections.empty()) {
        auto pts = nlohmann::ordered_json::array();
        for (const Point3 p : c.points) pts.push_back(point3(p));
        j["points"] = pts;
    }
    if (!c.projections.empty()) {
        auto ps = nlohmann::ordered_json::array();
        for (const SurfaceProjection& pr : c.projections) {
            nlohmann::ordered_json pj;
            pj["plane"] = pr.plane;
            if (!pr.contour.empty()) {
                pj["contour"] = pr.contour;
            } else {
                auto pts = nlohmann::ordered_json::array();
                for (const Point2 p : pr.points) pts.push_back({io::number(p.x), io::number(p.y)});
                pj["points"] = pts;
            }
            ps.push_back(pj);
        }
        j["projections"] = ps;
    }
    if (!c.smooth) j["smooth"] = false;
    return j;
}

// Paths of points [x, y, z] under `key` (the surface as a STEP face set,
// the boundary); absent: none.
void readPaths(const io::ObjectFields& f, const char* key, std::vector<std::vector<Point3>>& into)
{
    const nlohmann::json* b = f.find(key);
    if (!b) return;
    if (!b->is_array()) f.error(key, "expected an array of paths, each an array of points [x, y, z]");
    else
        for (std::size_t i = 0; i < b->size(); ++i)
            into.push_back(readPoints3(f, (*b)[i], std::string(key) + "[" + std::to_string(i) + "]"));
}

nlohmann::ordered_json writePaths(const std::vector<std::vector<Point3>>& ps)
{
    auto out = nlohmann::ordered_json::array();
    for (const auto& path : ps) {
        auto pts = nlohmann::ordered_json::array();
        for (const Point3 p : path) pts.push_back(point3(p));
        out.push_back(pts);
    }
    return out;
}

// The surface: paths (a STEP face set), or the two curves it is ruled
// between. Read as the file has them; written, the surface when there is
// one, otherwise the curves.
void readShape(const io::ObjectFields& f, SurfaceUnit& u)
{
    readPaths(f, "surface", u.surface);
    if (!f.find("surface") || f.find("curve1") || f.find("curve2")) {
        u.curve1 = readCurve(f, "curve1");
        u.curve2 = readCurve(f, "curve2");
    }
}

void writeShape(const SurfaceUnit& u, nlohmann::ordered_json& j)
{
    if (u.surface.empty()) {
        j["curve1"] = writeCurve(u.curve1);
        j["curve2"] = writeCurve(u.curve2);
    } else {
        j["surface"] = writePaths(u.surface);
    }
}

namespace keys = io::keys;
const io::UnitKeys<SurfaceUnit> kKeys{
    {keys::custom<SurfaceUnit>({"curve1", "curve2", "surface"}, readShape, writeShape),
     // A face set's surface has no N.
     keys::custom<SurfaceUnit>(
         {"n"},
         [](const io::ObjectFields& f, SurfaceUnit& u) {
             if (u.surface.empty() || f.find("n")) u.n = f.whole("n").value_or(0);
         },
         [](const SurfaceUnit& u, nlohmann::ordered_json& j) {
             if (u.surface.empty() || u.n) j["n"] = u.n;
         }),
     keys::custom<SurfaceUnit>(
         {"m"}, [](const io::ObjectFields& f, SurfaceUnit& u) { if (f.find("m")) u.m = f.whole("m"); },
         [](const SurfaceUnit& u, nlohmann::ordered_json& j) { if (u.m) j["m"] = *u.m; }),
     keys::optional("curveStep", &SurfaceUnit::curveStep), keys::required("scallop", &SurfaceUnit::scallop),
     keys::number("allowance", &SurfaceUnit::allowance, 0.0),
     keys::custom<SurfaceUnit>(
         {"boundary"}, [](const io::ObjectFields& f, SurfaceUnit& u) { readPaths(f, "boundary", u.boundary); },
         [](const SurfaceUnit& u, nlohmann::ordered_json& j) {
             if (!u.boundary.empty()) j["boundary"] = writePaths(u.boundary);
         }),
     keys::pins(&SurfaceUnit::tools)}};

}  // namespace

const io::UnitKeys<SurfaceUnit>& surfaceKeys() { return kKeys; }

}  // namespace taiwa::surfacemod
