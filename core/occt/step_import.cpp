// STEP import of a turned part (step_import.h): read, check that every face
// is turned about one axis, cut with the half-plane, chain the section's
// outline and split it into the outer and inner profile.
#include "occt/step_import.h"

#include "model/translate_noop.h"
#include "model/turned_geometry.h"

#include <fmt/format.h>

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepAlgoAPI_Common.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <STEPControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Vertex.hxx>
#include <gp_Ax1.hxx>
#include <gp_Pln.hxx>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace taiwa::turning {

namespace {

const char* surfaceName(GeomAbs_SurfaceType t)
{
    switch (t) {
    case GeomAbs_Plane: return TAIWA_TRANSLATE_NOOP("taiwa::msg", "plane");
    case GeomAbs_Cylinder: return TAIWA_TRANSLATE_NOOP("taiwa::msg", "cylinder");
    case GeomAbs_Cone: return TAIWA_TRANSLATE_NOOP("taiwa::msg", "cone");
    case GeomAbs_Sphere: return TAIWA_TRANSLATE_NOOP("taiwa::msg", "sphere");
    case GeomAbs_Torus: return TAIWA_TRANSLATE_NOOP("taiwa::msg", "torus");
    case GeomAbs_SurfaceOfRevolution: return TAIWA_TRANSLATE_NOOP("taiwa::msg", "surface of revolution");
    case GeomAbs_BezierSurface: return TAIWA_TRANSLATE_NOOP("taiwa::msg", "Bézier surface");
    case GeomAbs_BSplineSurface: return TAIWA_TRANSLATE_NOOP("taiwa::msg", "B-spline surface");
    case GeomAbs_SurfaceOfExtrusion: return TAIWA_TRANSLATE_NOOP("taiwa::msg", "extruded surface");
    case GeomAbs_OffsetSurface: return TAIWA_TRANSLATE_NOOP("taiwa::msg", "offset surface");
    default: return TAIWA_TRANSLATE_NOOP("taiwa::msg", "free-form surface");
    }
}

// A point to 1 nm, so that what was modelled as 0 or 15 reads as 0 or 15.
double clean(double v)
{
    const double r = std::round(v * 1e6) / 1e6;
    return r == 0.0 ? 0.0 : r;
}

class Importer {
public:
    explicit Importer(std::string path) : path_(std::move(path)) {}

    ImportedProfiles run()
    {
        const TopoDS_Shape solid = readSolid();
        findAxis(solid);
        std::vector<Segment> loop = section(solid);
        return split(std::move(loop));
    }

private:
    // The file and what is wrong with it ("shaft.step: it holds no solid").
    [[noreturn]] void refuse(const std::string& why) const { throw Refusal(why, Place::inFile(path_)); }

    TopoDS_Shape readSolid()
    {
        // OpenCASCADE's reader talks on standard output; the program says what matters itself.
        static const bool quiet = [] {
            Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
            return true;
        }();
        static_cast<void>(quiet);
        std::error_code ec;
        if (!std::filesystem::is_regular_file(path_, ec)) refuse(TAIWA_TRANSLATE_NOOP("taiwa::msg", "cannot open it (no such file)"));
        STEPControl_Reader reader;
        if (reader.ReadFile(path_.c_str()) != IFSelect_RetDone) refuse(TAIWA_TRANSLATE_NOOP("taiwa::msg", "not a STEP file, or a broken one"));
        reader.TransferRoots();
        const TopoDS_Shape shape = reader.OneShape();
        std::vector<TopoDS_Shape> solids;
        for (TopExp_Explorer e(shape, TopAbs_SOLID); e.More(); e.Next()) solids.push_back(e.Current());
        if (solids.empty()) refuse(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the file holds no solid: a turned part is imported from its solid model"));
        if (solids.size() > 1)
            refuse(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the file holds {} solids; import one turned part at a time"), solids.size()));
        return solids.front();
    }

    // Every face turned about one axis, planes square to it.
    void findAxis(const TopoDS_Shape& solid)
    {
        struct Face {
            int index;
            GeomAbs_SurfaceType type;
            std::optional<gp_Ax1> axis;   // revolved faces
            std::optional<gp_Pnt> centre; // spheres
            std::optional<gp_Dir> normal; // planes
        };
        std::vector<Face> faces;
        int index = 0;
        for (TopExp_Explorer e(solid, TopAbs_FACE); e.More(); e.Next()) {
            ++index;
            const BRepAdaptor_Surface s(TopoDS::Face(e.Current()));
            Face f{index, s.GetType(), std::nullopt, std::nullopt, std::nullopt};
            switch (f.type) {
            case GeomAbs_Cylinder: f.axis = s.Cylinder().Axis(); break;
            case GeomAbs_Cone: f.axis = s.Cone().Axis(); break;
            case GeomAbs_Torus: f.axis = s.Torus().Axis(); break;
            case GeomAbs_SurfaceOfRevolution: f.axis = s.AxeOfRevolution(); break;
            case GeomAbs_Sphere: f.centre = s.Sphere().Location(); break;
            case GeomAbs_Plane: f.normal = s.Plane().Axis().Direction(); break;
            default:
                refuse(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "not a body of revolution: face {} is a {}, not turned about an axis"),
                                   f.index, surfaceName(f.type)));
            }
            faces.push_back(f);
        }
        const auto first = std::find_if(faces.begin(), faces.end(), [](const Face& f) { return f.axis.has_value(); });
        if (first == faces.end())
            refuse(TAIWA_TRANSLATE_NOOP("taiwa::msg", "not a body of revolution: no face of it is turned about an axis (cylinder, cone, torus, sphere)"));
        gp_Ax1 axis = *first->axis;
        const auto onAxis = [&](const gp_Pnt& p) { return gp_Lin(axis).Distance(p) < 1e-6; };
        for (const Face& f : faces) {
            // Each refusal names the face and the one whose axis it is not on.
            const auto notOn = [&](const char* why) {
                refuse(fmt::format(fmt::runtime(why), f.index, surfaceName(f.type), first->index, surfaceName(first->type)));
            };
            if (f.axis && (!f.axis->Direction().IsParallel(axis.Direction(), 1e-9) || !onAxis(f.axis->Location())))
                notOn(TAIWA_TRANSLATE_NOOP("taiwa::msg", "not a body of revolution: face {} (a {}) is not turned about the axis of face {} (a {})"));
            if (f.centre && !onAxis(*f.centre))
                notOn(TAIWA_TRANSLATE_NOOP("taiwa::msg", "not a body of revolution: face {} (a {}) is not centred on the axis of face {} (a {})"));
            if (f.normal && !f.normal->IsParallel(axis.Direction(), 1e-9))
                notOn(TAIWA_TRANSLATE_NOOP("taiwa::msg", "not a body of revolution: face {} (a {}) is not square to the axis of face {} (a {})"));
        }
        // The direction as the model's axis it is parallel to, + along it;
        // the point nearest the model's origin.
        gp_Dir d = axis.Direction();
        const double comps[] = {d.X(), d.Y(), d.Z()};
        int largest = 0;
        for (int i = 1; i < 3; ++i)
            if (std::abs(comps[i]) > std::abs(comps[largest])) largest = i;
        if (comps[largest] < 0) d.Reverse();
        const gp_Pnt o = axis.Location();
        const gp_Vec ov(o, gp_Pnt(0, 0, 0));
        origin_ = o.Translated(gp_Vec(d) * ov.Dot(gp_Vec(d)));
        dir_ = d;
        // The half-plane's direction: square to the axis, the model's X
        // where it can be.
        gp_Vec x(1, 0, 0);
        if (std::abs(gp_Vec(d).Dot(x)) > 0.9) x = gp_Vec(0, 1, 0);
        x -= gp_Vec(d) * x.Dot(gp_Vec(d));
        across_ = gp_Dir(x);
    }

    ZR toZR(const gp_Pnt& p) const
    {
        const gp_Vec v(origin_, p);
        return {clean(v.Dot(gp_Vec(dir_))), clean(v.Dot(gp_Vec(across_)))};
    }

    // The solid cut with the half-plane through the axis: its outline, one loop.
    std::vector<Segment> section(const TopoDS_Shape& solid)
    {
        Bnd_Box box;
        BRepBndLib::Add(solid, box);
        const double size = 2.0 * std::sqrt(box.SquareExtent()) + 10.0;
        const gp_Pln plane(gp_Ax3(origin_, dir_.Crossed(across_), across_));
        const TopoDS_Face half = BRepBuilderAPI_MakeFace(plane, 0.0, size, -size, size).Face();
        BRepAlgoAPI_Common common(solid, half);
        common.SetRunParallel(false);
        common.Build();
        if (!common.IsDone() || common.HasErrors()) refuse(TAIWA_TRANSLATE_NOOP("taiwa::msg", "OpenCASCADE could not cut the part with the half-plane"));
        const TopoDS_Shape cut = common.Shape();
        TopTools_IndexedDataMapOfShapeListOfShape facesOf;
        TopExp::MapShapesAndAncestors(cut, TopAbs_EDGE, TopAbs_FACE, facesOf);
        std::vector<Segment> pieces;
        for (TopExp_Explorer f(cut, TopAbs_FACE); f.More(); f.Next())
            for (TopExp_Explorer e(f.Current(), TopAbs_EDGE); e.More(); e.Next()) {
                if (facesOf.FindFromKey(e.Current()).Extent() != 1) continue;
                const TopoDS_Edge edge = TopoDS::Edge(e.Current());
                TopoDS_Vertex v1, v2;
                TopExp::Vertices(edge, v1, v2, true);
                const ZR a = toZR(BRep_Tool::Pnt(v1)), b = toZR(BRep_Tool::Pnt(v2));
                const BRepAdaptor_Curve c(edge);
                if (c.GetType() == GeomAbs_Line) {
                    pieces.push_back(lineSegment(a, b));
                } else if (c.GetType() == GeomAbs_Circle) {
                    const ZR mid = toZR(c.Value(0.5 * (c.FirstParameter() + c.LastParameter())));
                    Segment s = arcSegment(a, b, toZR(c.Circle().Location()), cross(mid - a, b - a) > 0.0);
                    s.radius = clean(c.Circle().Radius());
                    pieces.push_back(s);
                } else {
                    refuse(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the half-section has an edge that is neither a line nor an arc"));
                }
            }
        if (pieces.empty()) refuse(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the half-plane through the axis does not cut the part"));
        // Chain end to start.
        std::vector<Segment> loop{pieces.front()};
        std::vector<bool> used(pieces.size(), false);
        used[0] = true;
        while (dist(loop.back().b, loop.front().a) > 1e-6) {
            bool found = false;
            for (std::size_t j = 0; j < pieces.size() && !found; ++j)
                if (!used[j] && dist(pieces[j].a, loop.back().b) < 1e-6) {
                    used[j] = found = true;
                    loop.push_back(pieces[j]);
                }
            if (!found) refuse(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the half-section's outline does not close"));
        }
        if (std::find(used.begin(), used.end(), false) != used.end())
            refuse(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the half-section falls into several pieces (a closed cavity inside the part?)"));
        return loop;
    }

    static bool onAxis(const Segment& s) { return !s.arc && s.a.r < 1e-6 && s.b.r < 1e-6; }

    // Lines in line and arcs of one circle made one.
    static std::vector<Segment> merged(const std::vector<Segment>& run)
    {
        std::vector<Segment> out;
        for (const Segment& s : run) {
            if (!out.empty()) {
                Segment& last = out.back();
                const bool lines = !last.arc && !s.arc &&
                                   std::abs(cross(unit(last.b - last.a), unit(s.b - s.a))) < 1e-9 &&
                                   dot(last.b - last.a, s.b - s.a) > 0;
                const bool arcs = last.arc && s.arc && last.ccw == s.ccw && dist(last.centre, s.centre) < 1e-6 &&
                                  std::abs(last.radius - s.radius) < 1e-6;
                if (lines || arcs) {
                    last.b = s.b;
                    continue;
                }
            }
            out.push_back(s);
        }
        return out;
    }

    static std::vector<Segment> reversedRun(const std::vector<Segment>& run)
    {
        std::vector<Segment> r;
        for (auto it = run.rbegin(); it != run.rend(); ++it) r.push_back(reversed(*it));
        return r;
    }

    static TurnedProfile profileOf(const std::vector<Segment>& run, ProfileSide side)
    {
        TurnedProfile p;
        p.side = side;
        p.startX = clean(2.0 * run.front().a.r);
        p.startZ = run.front().a.z;
        int id = 0;
        for (const Segment& s : merged(run)) {
            ProfileRow row;
            row.id = ++id;
            row.x = clean(2.0 * s.b.r);
            row.z = s.b.z;
            if (s.arc) {
                row.kind = s.ccw ? ElementKind::ArcCCW : ElementKind::ArcCW;
                row.centreX = clean(2.0 * s.centre.r);
                row.centreZ = s.centre.z;
                row.radius = s.radius;
            }
            p.rows.push_back(row);
        }
        return p;
    }

    ImportedProfiles split(std::vector<Segment> loop)
    {
        ImportedProfiles out;
        out.axisPoint = {origin_.X(), origin_.Y(), origin_.Z()};
        out.axisDirection = {dir_.X(), dir_.Y(), dir_.Z()};
        const std::size_t n = loop.size();
        const auto axisEdge = std::find_if(loop.begin(), loop.end(), onAxis);
        if (axisEdge != loop.end()) {
            // A solid part: the run after the edges on the axis, from the front.
            std::size_t first = 0;
            for (std::size_t i = 0; i < n; ++i)
                if (onAxis(loop[i]) && !onAxis(loop[(i + 1) % n])) first = (i + 1) % n;
            std::vector<Segment> run;
            for (std::size_t k = 0; k < n && !onAxis(loop[(first + k) % n]); ++k) run.push_back(loop[(first + k) % n]);
            if (run.front().a.z < run.back().b.z) run = reversedRun(run);
            out.outer = profileOf(run, ProfileSide::Outer);
            return out;
        }
        // A hollow part: split at the front's and the back's innermost points.
        std::size_t f = 0, b = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const ZR p = loop[i].a, pf = loop[f].a, pb = loop[b].a;
            if (p.z > pf.z + 1e-9 || (std::abs(p.z - pf.z) <= 1e-9 && p.r < pf.r)) f = i;
            if (p.z < pb.z - 1e-9 || (std::abs(p.z - pb.z) <= 1e-9 && p.r < pb.r)) b = i;
        }
        std::vector<Segment> one, two;  // from f to b, and from b to f
        for (std::size_t i = f; i != b; i = (i + 1) % n) one.push_back(loop[i]);
        for (std::size_t i = b; i != f; i = (i + 1) % n) two.push_back(loop[i]);
        two = reversedRun(two);  // now from f to b as well
        double rOne = 0.0, rTwo = 0.0;
        for (const auto& s : one) rOne = std::max(rOne, std::max(s.a.r, s.b.r));
        for (const auto& s : two) rTwo = std::max(rTwo, std::max(s.a.r, s.b.r));
        if (rTwo > rOne) std::swap(one, two);
        out.outer = profileOf(one, ProfileSide::Outer);
        out.inner = profileOf(two, ProfileSide::Inner);
        return out;
    }

public:
    // Z0 on the front face (the largest Z), as lathe jobs have it.
    static void frontAtZero(ImportedProfiles& p)
    {
        double front = -1e300;
        for (const auto* prof : {&p.outer, &p.inner})
            if (*prof) {
                front = std::max(front, (*prof)->startZ);
                for (const auto& r : (*prof)->rows) front = std::max(front, r.z);
            }
        p.frontZ = front;
        for (auto* prof : {&p.outer, &p.inner})
            if (*prof) {
                (*prof)->startZ = clean((*prof)->startZ - front);
                for (auto& r : (*prof)->rows) {
                    r.z = clean(r.z - front);
                    if (r.centreZ) r.centreZ = clean(*r.centreZ - front);
                }
            }
    }

private:

    std::string path_;
    gp_Pnt origin_;
    gp_Dir dir_, across_;
};

}  // namespace

Result<ImportedProfiles> importStepProfiles(const std::string& path)
{
    try {
        ImportedProfiles p = Importer(path).run();
        Importer::frontAtZero(p);
        return p;
    } catch (const Refusal& r) {  // "FILE: why", the pattern the station translates part by part
        return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: {}"), path, r.message()), r.place()};
    } catch (const Standard_Failure& e) {
        return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: OpenCASCADE failed reading it: {}"), path, e.GetMessageString()),
                       Place::inFile(path)};
    }
}

}  // namespace taiwa::turning
