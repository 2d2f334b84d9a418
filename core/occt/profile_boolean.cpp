// Booleans of half-section loops with OpenCASCADE (profile_boolean.h): each
// loop becomes a planar face in the XY plane (x = z, y = r), the faces are
// fused, cut and fused again with BRepAlgoAPI, and the edges of the result
// that bound exactly one face are read back as lines and arcs.
#include "occt/profile_boolean.h"

#include "model/turned_geometry.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepClass_FaceClassifier.hxx>
#include <BRep_Tool.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Vertex.hxx>
#include <gp_Ax2.hxx>
#include <gp_Circ.hxx>
#include <gp_Pnt.hxx>

#include <string>

namespace taiwa::turning {

namespace {

gp_Pnt toPnt(ZR p) { return gp_Pnt(p.z, p.r, 0.0); }
ZR toZR(const gp_Pnt& p) { return {p.X(), p.Y()}; }

// The loop turned counter-clockwise (a face with normal +Z).
Loop counterClockwise(const Loop& loop)
{
    if (signedArea(loop) >= 0.0) return loop;
    Loop r;
    for (auto it = loop.rbegin(); it != loop.rend(); ++it) r.push_back(reversed(*it));
    return r;
}

TopoDS_Face makeFace(const Loop& input)
{
    const Loop loop = counterClockwise(input);
    std::vector<TopoDS_Vertex> vertices;
    for (const auto& s : loop) vertices.push_back(BRepBuilderAPI_MakeVertex(toPnt(s.a)));
    BRepBuilderAPI_MakeWire wire;
    for (std::size_t i = 0; i < loop.size(); ++i) {
        const Segment& s = loop[i];
        const TopoDS_Vertex& va = vertices[i];
        const TopoDS_Vertex& vb = vertices[(i + 1) % loop.size()];
        if (!s.arc) {
            wire.Add(BRepBuilderAPI_MakeEdge(va, vb).Edge());
            continue;
        }
        const gp_Circ circle(gp_Ax2(toPnt(s.centre), gp::DZ()), s.radius);
        // An edge on a circle runs counter-clockwise about its axis; a
        // clockwise arc is the counter-clockwise one from b to a, reversed.
        if (s.ccw)
            wire.Add(BRepBuilderAPI_MakeEdge(circle, va, vb).Edge());
        else
            wire.Add(TopoDS::Edge(BRepBuilderAPI_MakeEdge(circle, vb, va).Edge().Reversed()));
    }
    if (!wire.IsDone()) throw Standard_Failure("a loop of the half-section does not close");
    BRepBuilderAPI_MakeFace face(wire.Wire(), true);
    if (!face.IsDone()) throw Standard_Failure("a loop of the half-section makes no face");
    return face.Face();
}

Segment toSegment(const TopoDS_Edge& edge)
{
    TopoDS_Vertex first, last;
    TopExp::Vertices(edge, first, last, true);  // in the edge's orientation
    const ZR a = toZR(BRep_Tool::Pnt(first)), b = toZR(BRep_Tool::Pnt(last));
    const BRepAdaptor_Curve curve(edge);
    if (curve.GetType() == GeomAbs_Line) return lineSegment(a, b);
    if (curve.GetType() != GeomAbs_Circle) throw Standard_Failure("a boolean gave an edge that is neither a line nor an arc");
    const gp_Circ c = curve.Circle();
    // The way round from the circle's own direction and the edge's
    // orientation: exact for any sweep. (Which side of the chord the arc's
    // middle lies on gave the wrong way round for an arc of a few
    // nanometres, a sliver of the booleans, whose chord is noise: the arc
    // became the rest of its circle, down through the axis; seed 3961 of
    // bench_turning_generator.)
    bool ccw = c.Axis().Direction().Z() > 0.0;
    if (edge.Orientation() == TopAbs_REVERSED) ccw = !ccw;
    Segment s = arcSegment(a, b, toZR(c.Location()), ccw);
    s.radius = c.Radius();
    return s;
}

// The loops united, after `first` when it is given.
TopoDS_Shape fuseAll(const std::vector<Loop>& loops, const TopoDS_Shape* first = nullptr)
{
    TopTools_ListOfShape args, tools;
    if (first) args.Append(*first);
    for (const Loop& l : loops) (args.IsEmpty() ? args : tools).Append(makeFace(l));
    if (tools.IsEmpty()) return args.First();
    BRepAlgoAPI_Fuse fuse;
    fuse.SetArguments(args);
    fuse.SetTools(tools);
    fuse.SetRunParallel(false);
    fuse.Build();
    if (!fuse.IsDone() || fuse.HasErrors()) throw Standard_Failure("OpenCASCADE could not unite the shapes");
    return fuse.Shape();
}

}  // namespace

Result<std::vector<Loop>> regionBoundary(const std::vector<Loop>& add, const std::vector<Loop>& cut,
                                         const std::vector<Loop>& keep)
{
    try {
        if (add.empty()) return keep.empty() ? std::vector<Loop>{} : regionBoundary(keep, {});
        TopoDS_Shape shape = fuseAll(add);
        if (!cut.empty()) {
            TopTools_ListOfShape args, tools;
            args.Append(shape);
            for (const auto& l : cut) tools.Append(makeFace(l));
            BRepAlgoAPI_Cut c;
            c.SetArguments(args);
            c.SetTools(tools);
            c.SetRunParallel(false);
            c.Build();
            if (!c.IsDone() || c.HasErrors()) throw Standard_Failure("OpenCASCADE could not cut the grooves");
            shape = c.Shape();
        }
        if (!keep.empty()) {
            const bool anyLeft = TopExp_Explorer(shape, TopAbs_FACE).More();
            shape = anyLeft ? fuseAll(keep, &shape) : fuseAll(keep);
        }
        // Edges bounding exactly one face bound the region.
        TopTools_IndexedDataMapOfShapeListOfShape facesOf;
        TopExp::MapShapesAndAncestors(shape, TopAbs_EDGE, TopAbs_FACE, facesOf);
        std::vector<Segment> pieces;
        for (TopExp_Explorer f(shape, TopAbs_FACE); f.More(); f.Next())
            for (TopExp_Explorer e(f.Current(), TopAbs_EDGE); e.More(); e.Next())
                if (facesOf.FindFromKey(e.Current()).Extent() == 1) pieces.push_back(toSegment(TopoDS::Edge(e.Current())));
        // Chain the pieces into loops, end to start.
        std::vector<Loop> loops;
        std::vector<bool> used(pieces.size(), false);
        for (std::size_t start = 0; start < pieces.size(); ++start) {
            if (used[start]) continue;
            Loop loop{pieces[start]};
            used[start] = true;
            for (;;) {
                const ZR end = loop.back().b;
                if (dist(end, loop.front().a) < 1e-6 && loop.size() > 1) break;
                std::size_t next = pieces.size();
                for (std::size_t j = 0; j < pieces.size(); ++j)
                    if (!used[j] && dist(pieces[j].a, end) < 1e-6) {
                        next = j;
                        break;
                    }
                if (next == pieces.size()) throw Standard_Failure("the result's boundary does not close");
                used[next] = true;
                loop.push_back(pieces[next]);
            }
            loops.push_back(std::move(loop));
        }
        return loops;
    } catch (const Standard_Failure& e) {
        return Failure{std::string("the half-section's booleans failed: ") + e.GetMessageString()};
    }
}

bool insideLoop(const Loop& loop, ZR p)
{
    try {
        const BRepClass_FaceClassifier classifier(makeFace(loop), toPnt(p), 1e-7);
        return classifier.State() == TopAbs_IN;
    } catch (const Standard_Failure&) {
        return false;
    }
}

}  // namespace taiwa::turning
