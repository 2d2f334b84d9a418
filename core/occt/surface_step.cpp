// STEP export of a surface of paths and STEP import of a face set
// (surface_step.h): GeomAPI_PointsToBSplineSurface (or a B-spline of
// degree 1 × 1 on the paths' points) and STEPControl_Writer one way, STEPControl_Reader and a grid over each face's parameters the
// other (OpenCASCADE's own mesher, BRepMesh, took 70 s for a 2 µm mesh of
// one 60 × 60 mm face; the grid takes a fraction of a second).
#include "occt/surface_step.h"

#include "model/translate_noop.h"

#include <fmt/format.h>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepClass_FaceClassifier.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <GeomAPI_PointsToBSplineSurface.hxx>
#include <Geom_BSplineSurface.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <Geom_Surface.hxx>
#include <STEPControl_Reader.hxx>
#include <STEPControl_Writer.hxx>
#include <Standard_Failure.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopLoc_Location.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>

#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <fstream>
#include <iterator>
#include <cmath>
#include <filesystem>

namespace taiwa::surface {

namespace {

// OpenCASCADE's reader and writer print to the console by default.
void quiet()
{
    static const bool done = [] {
        Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
        return true;
    }();
    (void)done;
}

// One face sampled on a grid of its parameters fine enough that the chords
// stay within `deflection` (from its largest second derivatives on a 17 × 17
// grid), the quads whose corners lie on the face kept. A face on its whole
// surface (one wire of at most four edges along the parameter bounds) needs
// no classifying; a trimmed one, at least 256 cells across, loses the
// cells its trim crosses.
void meshFace(const TopoDS_Face& face, double deflection, TriangleMesh& mesh)
{
    TopLoc_Location loc;
    const Handle(Geom_Surface) s = BRep_Tool::Surface(face, loc);
    if (s.IsNull()) return;
    double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
    BRepTools::UVBounds(face, u0, u1, v0, v1);
    double d2u = 0, d2v = 0;
    for (int i = 0; i <= 16; ++i)
        for (int j = 0; j <= 16; ++j) {
            gp_Pnt p;
            gp_Vec du, dv, duu, dvv, duv;
            s->D2(u0 + (u1 - u0) * i / 16, v0 + (v1 - v0) * j / 16, p, du, dv, duu, dvv, duv);
            d2u = std::max(d2u, duu.Magnitude() + duv.Magnitude());
            d2v = std::max(d2v, dvv.Magnitude() + duv.Magnitude());
        }
    const auto count = [&](double span, double d2) {
        if (d2 < 1e-12) return 1;
        const double step = std::sqrt(8 * deflection / d2);
        return static_cast<int>(std::clamp(std::ceil(span / step), 1.0, 2000.0));
    };
    double su0 = 0, su1 = 0, sv0 = 0, sv1 = 0;
    s->Bounds(su0, su1, sv0, sv1);
    int wires = 0, edges = 0;
    for (TopExp_Explorer w(face, TopAbs_WIRE); w.More(); w.Next()) ++wires;
    for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next()) ++edges;
    const bool whole = wires == 1 && edges <= 4 && std::abs(u0 - su0) < 1e-9 && std::abs(u1 - su1) < 1e-9 &&
                       std::abs(v0 - sv0) < 1e-9 && std::abs(v1 - sv1) < 1e-9;
    // A trimmed face: at least kTrimCells cells across, so that its trim
    // (a hole, a cut-off corner) is seen and the band lost along it stays
    // narrow, however flat the face is.
    constexpr int kTrimCells = 256;
    const int nu = whole ? count(u1 - u0, d2u) : std::max(kTrimCells, count(u1 - u0, d2u));
    const int nv = whole ? count(v1 - v0, d2v) : std::max(kTrimCells, count(v1 - v0, d2v));
    const int base = static_cast<int>(mesh.vertices.size());
    std::vector<char> on(static_cast<std::size_t>((nu + 1) * (nv + 1)), 1);
    const double tol = BRep_Tool::Tolerance(face);
    for (int j = 0; j <= nv; ++j)
        for (int i = 0; i <= nu; ++i) {
            const double u = u0 + (u1 - u0) * i / nu, v = v0 + (v1 - v0) * j / nv;
            const gp_Pnt p = s->Value(u, v).Transformed(loc.Transformation());
            mesh.vertices.push_back({p.X(), p.Y(), p.Z()});
            if (!whole) {
                BRepClass_FaceClassifier c(face, gp_Pnt2d(u, v), tol);
                on[static_cast<std::size_t>(j * (nu + 1) + i)] = c.State() != TopAbs_OUT;
            }
        }
    const bool reversed = face.Orientation() == TopAbs_REVERSED;
    for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i) {
            const int a = j * (nu + 1) + i, b = a + 1, c = a + nu + 2, d = a + nu + 1;
            if (!on[static_cast<std::size_t>(a)] || !on[static_cast<std::size_t>(b)] ||
                !on[static_cast<std::size_t>(c)] || !on[static_cast<std::size_t>(d)])
                continue;
            if (reversed) {
                mesh.triangles.push_back({base + a, base + c, base + b});
                mesh.triangles.push_back({base + a, base + d, base + c});
            } else {
                mesh.triangles.push_back({base + a, base + b, base + c});
                mesh.triangles.push_back({base + a, base + c, base + d});
            }
        }
}

}  // namespace

namespace {

// The face through the paths: a B-spline interpolating every point
// (smooth), or of degree 1 × 1 with the points as its poles (each cell the
// bilinear patch of its four corners; knots whose removal moves nothing by
// more than 1 nm taken out, so a grid finer than its patches collapses to
// them).
TopoDS_Face faceThrough(const std::vector<std::vector<Point3>>& paths, SurfaceFit fit)
{
    const int n = static_cast<int>(paths.size()), m = static_cast<int>(paths.front().size());
    TColgp_Array2OfPnt pts(1, m, 1, n);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < m; ++j) {
            const Point3& p = paths[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
            pts.SetValue(j + 1, i + 1, gp_Pnt(p.x, p.y, p.z));
        }
    if (fit == SurfaceFit::Smooth) {
        GeomAPI_PointsToBSplineSurface interpolated;
        interpolated.Interpolate(pts);
        if (!interpolated.IsDone()) return {};
        return BRepBuilderAPI_MakeFace(interpolated.Surface(), 1e-7);
    }
    TColStd_Array1OfReal uk(1, m), vk(1, n);
    TColStd_Array1OfInteger um(1, m), vm(1, n);
    for (int j = 1; j <= m; ++j) uk(j) = j - 1, um(j) = j == 1 || j == m ? 2 : 1;
    for (int i = 1; i <= n; ++i) vk(i) = i - 1, vm(i) = i == 1 || i == n ? 2 : 1;
    Handle(Geom_BSplineSurface) s = new Geom_BSplineSurface(pts, uk, vk, um, vm, 1, 1);
    constexpr double kKnotTolerance = 1e-6;  // mm
    for (int k = s->NbUKnots() - 1; k >= 2; --k) s->RemoveUKnot(k, 0, kKnotTolerance);
    for (int k = s->NbVKnots() - 1; k >= 2; --k) s->RemoveVKnot(k, 0, kKnotTolerance);
    return BRepBuilderAPI_MakeFace(s, 1e-7);
}

Result<bool> checkedPaths(const std::vector<std::vector<Point3>>& paths)
{
    if (paths.size() < 2 || paths.front().size() < 2)
        return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                        "the surface's paths: at least 2 paths of 2 points are needed, "
                                                        "there are {}"),
                                   paths.size())};
    for (std::size_t i = 1; i < paths.size(); ++i)
        if (paths[i].size() != paths.front().size())
            return Failure{fmt::format(
                TAIWA_TRANSLATE_NOOP("taiwa::msg", "the surface's paths: path {} has {} points, path 1 has {}"), i + 1,
                paths[i].size(), paths.front().size())};
    return true;
}

}  // namespace

Result<bool> exportSurfaceStep(const std::vector<std::vector<Point3>>& paths, const std::string& file, SurfaceFit fit)
{
    if (auto ok = checkedPaths(paths); !ok) return ok;
    quiet();
    try {
        const TopoDS_Face face = faceThrough(paths, fit);
        if (face.IsNull())
            return Failure{
                TAIWA_TRANSLATE_NOOP("taiwa::msg", "the surface's paths: OpenCASCADE could not interpolate them")};
        STEPControl_Writer writer;
        Interface_Static::SetCVal("write.step.unit", "MM");
        if (writer.Transfer(face, STEPControl_AsIs) != IFSelect_RetDone)
            return Failure{fmt::format(
                TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: OpenCASCADE could not put the surface into STEP"), file)};
        if (writer.Write(file.c_str()) != IFSelect_RetDone)
            return Failure{
                fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: the STEP file could not be written"), file)};
        return true;
    } catch (const Standard_Failure& e) {
        return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: OpenCASCADE refused the surface ({})"), file,
                                   e.GetMessageString())};
    }
}

Result<std::string> surfaceStepText(const std::vector<std::vector<Point3>>& paths, SurfaceFit fit)
{
    // STEPControl_Writer writes files only (OpenCASCADE 7.6): a file of
    // this process's own in the temporary folder, read back and removed.
    static std::atomic<int> made{0};
    std::error_code ec;
    const std::filesystem::path tmp = std::filesystem::temp_directory_path(ec) /
                                      fmt::format("taiwa-surface-{}-{}.step", ::getpid(), ++made);
    if (ec)
        return Failure{
            fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "no temporary folder for the STEP file: {}"), ec.message())};
    const auto written = exportSurfaceStep(paths, tmp.string(), fit);
    std::string text;
    if (written) {
        std::ifstream in(tmp, std::ios::binary);
        text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    std::filesystem::remove(tmp, ec);
    if (!written) return Failure{written.error()};
    if (text.empty())
        return Failure{fmt::format(
            TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: the STEP file written could not be read back"), tmp.string())};
    return text;
}

Result<TriangleMesh> importStepFaces(const std::string& file, double deflection)
{
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec))
        return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: no such file"), file)};
    quiet();
    try {
        STEPControl_Reader reader;
        if (reader.ReadFile(file.c_str()) != IFSelect_RetDone)
            return Failure{
                fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: not a STEP file OpenCASCADE can read"), file)};
        reader.TransferRoots();
        const TopoDS_Shape shape = reader.OneShape();
        if (shape.IsNull())
            return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: the STEP file holds no shape"), file)};
        TriangleMesh mesh;
        int faces = 0;
        for (TopExp_Explorer ex(shape, TopAbs_FACE); ex.More(); ex.Next()) {
            ++faces;
            meshFace(TopoDS::Face(ex.Current()), deflection, mesh);
        }
        if (faces == 0)
            return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: the STEP file holds no face"), file)};
        if (mesh.triangles.empty())
            return Failure{
                fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: its {} faces gave no triangles"), file, faces)};
        return mesh;
    } catch (const Standard_Failure& e) {
        return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: OpenCASCADE refused it ({})"), file,
                                   e.GetMessageString())};
    }
}

}  // namespace taiwa::surface
