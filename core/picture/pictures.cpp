// The sheet's milling pictures and the setup's (pictures.h); the lathe's
// step pictures are in pictures_lathe.cpp.
#include "picture/pictures.h"

#include "picture/canvas.h"
#include "sim/stock_simulation.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace taiwa::picture {

namespace {

using namespace colours;

// The feed moves of a path, arcs flattened to 10 degrees or less.
void drawPath(Canvas& canvas, const ToolPath& path, double bias)
{
    Point3 at = path.start;
    for (const Move& m : path.moves) {
        switch (m.kind) {
        case MoveKind::Rapid: break;
        case MoveKind::Feed: canvas.line({at.x, at.y, at.z}, {m.end.x, m.end.y, m.end.z}, kPath, 1, bias); break;
        case MoveKind::ArcCW:
        case MoveKind::ArcCCW: {
            const double sweep = arcSweep(at, m);
            const double a0 = std::atan2(at.y - m.centre.y, at.x - m.centre.x);
            const double r = std::hypot(at.x - m.centre.x, at.y - m.centre.y);
            const int n = std::max(2, static_cast<int>(std::ceil(std::abs(sweep) / (std::numbers::pi / 18))));
            Vec3 prev{at.x, at.y, at.z};
            for (int k = 1; k <= n; ++k) {
                const double t = static_cast<double>(k) / n, a = a0 + t * sweep;
                const Vec3 next = k == n ? Vec3{m.end.x, m.end.y, m.end.z}
                                         : Vec3{m.centre.x + r * std::cos(a), m.centre.y + r * std::sin(a), at.z + t * (m.end.z - at.z)};
                canvas.line(prev, next, kPath, 1, bias);
                prev = next;
            }
            break;
        }
        case MoveKind::DrillCycle:  // the hole's axis, seen through the material above it
            canvas.line({m.end.x, m.end.y, m.retractZ}, {m.end.x, m.end.y, m.end.z}, kPath, 2, 1e9);
            break;
        }
        at = m.end;
    }
}

// Six faces of a box, outward.
void box(Canvas& canvas, const std::array<double, 6>& b, Colour c, double alpha = 1.0)
{
    const double x0 = b[0], x1 = b[1], y0 = b[2], y1 = b[3], z0 = b[4], z1 = b[5];
    canvas.face({{x0, y0, z1}, {x1, y0, z1}, {x1, y1, z1}, {x0, y1, z1}}, c, alpha);  // top
    canvas.face({{x0, y0, z0}, {x0, y1, z0}, {x1, y1, z0}, {x1, y0, z0}}, c, alpha);  // bottom
    canvas.face({{x0, y0, z0}, {x1, y0, z0}, {x1, y0, z1}, {x0, y0, z1}}, c, alpha);  // front (-y)
    canvas.face({{x1, y1, z0}, {x0, y1, z0}, {x0, y1, z1}, {x1, y1, z1}}, c, alpha);  // back (+y)
    canvas.face({{x0, y1, z0}, {x0, y0, z0}, {x0, y0, z1}, {x0, y1, z1}}, c, alpha);  // left (-x)
    canvas.face({{x1, y0, z0}, {x1, y1, z0}, {x1, y1, z1}, {x1, y0, z1}}, c, alpha);  // right (+x)
}

Picture millingSetup(const Job& job, int width, int height)
{
    const Stock& s = job.stock;
    std::array<double, 6> bounds{std::min(s.x, 0.0), std::max(s.x + s.width, 0.0), std::min(s.y, 0.0), std::max(s.y + s.length, 0.0),
                                 -s.height, 0.0};
    std::vector<std::array<double, 6>> jaws;
    if (job.clamping) {
        const double t = 0.1 * std::max(s.width, s.length), bottom = -s.height, top = bottom + job.clamping->height;
        const bool x = job.clamping->grip == Clamping::Grip::X;
        for (const double side : {0.0, 1.0}) {
            jaws.push_back(x ? std::array{s.x - t + side * (s.width + t), s.x + side * (s.width + t), s.y - t, s.y + s.length + t, bottom, top}
                             : std::array{s.x - t, s.x + s.width + t, s.y - t + side * (s.length + t), s.y + side * (s.length + t), bottom, top});
            for (int k = 0; k < 6; k += 2)
                bounds[static_cast<std::size_t>(k)] = std::min(bounds[static_cast<std::size_t>(k)], jaws.back()[static_cast<std::size_t>(k)]),
                bounds[static_cast<std::size_t>(k) + 1] = std::max(bounds[static_cast<std::size_t>(k) + 1], jaws.back()[static_cast<std::size_t>(k) + 1]);
        }
    }
    const double axes = 0.25 * std::min(s.width, s.length);
    bounds[0] = std::min(bounds[0], -0.15 * std::max(s.width, s.length));
    bounds[2] = std::min(bounds[2], -0.15 * std::max(s.width, s.length));
    bounds[5] = std::max(bounds[5], axes);
    Canvas canvas(width, height, kBackground, Canvas::View::Iso, bounds);
    box(canvas, {s.x, s.x + s.width, s.y, s.y + s.length, -s.height, 0.0}, kStock);
    for (const auto& jaw : jaws) box(canvas, jaw, kClamp, 0.55);
    Picture out;
    constexpr double kOnTop = 1e9;
    const struct {
        Vec3 end;
        Colour colour;
        const char* name;
    } axis[] = {{{axes, 0, 0}, kAxisX, "X"}, {{0, axes, 0}, kAxisY, "Y"}, {{0, 0, axes}, kAxisZ, "Z"}};
    for (const auto& a : axis) {
        canvas.line({0, 0, 0}, a.end, a.colour, 2, kOnTop);
        const Projected p = canvas.project(a.end);
        out.labels.push_back({p.x + 3, p.y - 3, a.name, a.colour, 13, true, false});
    }
    const Projected o = canvas.project({0, 0, 0});
    out.labels.push_back({o.x - 12, o.y - 8, job.workOffset, kText, 15, true, true});
    out.image = canvas.take();
    return out;
}

}  // namespace

Picture heightFieldPicture(const sim::HeightField& f, const sim::HeightField* before, const ToolPath* path, int width, int height)
{
    if (before && !(before->columns() == f.columns() && before->rows() == f.rows())) before = nullptr;
    const Stock& s = f.stock();
    const double zb = f.bottom();
    Canvas canvas(width, height, kBackground, Canvas::View::Iso, {s.x, s.x + s.width, s.y, s.y + s.length, zb, 0.0});
    const int nx = f.columns(), ny = f.rows();
    const double c = f.cellSize(), xEnd = s.x + s.width, yEnd = s.y + s.length;
    // The faces' lit colours for the level top and the two walls seen, per class.
    const Colour classes[] = {kStock, kMachined, kRemoved};
    Colour topLit[3], xWall[3], yWall[3];
    for (int k = 0; k < 3; ++k)
        topLit[k] = canvas.lit(classes[k], {0, 0, 1}), xWall[k] = canvas.lit(classes[k], {1, 0, 0}), yWall[k] = canvas.lit(classes[k], {0, -1, 0});
    const auto classOf = [&](int i, int j) {
        const double z = f.at(i, j), b = before ? before->at(i, j) : z;
        return z < b - 1e-4 ? 2 : z > -1e-4 ? 0 : 1;
    };
    const double smooth = 1.5 * c;  // a step smaller than this is a slope, not a wall
    // The view is affine: a point's place is its origin's plus x, y and z times the axes' steps.
    const Projected o = canvas.project({0, 0, 0}), ax = canvas.project({1, 0, 0}), ay = canvas.project({0, 1, 0}),
                    az = canvas.project({0, 0, 1});
    const auto step = [&](const Projected& a, double k) { return Projected{k * (a.x - o.x), k * (a.y - o.y), k * (a.depth - o.depth)}; };
    const auto at = [&](double x, double y, double z) {
        return Projected{o.x + x * (ax.x - o.x) + y * (ay.x - o.x) + z * (az.x - o.x), o.y + x * (ax.y - o.y) + y * (ay.y - o.y) + z * (az.y - o.y),
                         o.depth + x * (ax.depth - o.depth) + y * (ay.depth - o.depth) + z * (az.depth - o.depth)};
    };
    const Projected cellX = step(ax, c), cellY = step(ay, c);
    for (int j = 0; j < ny; ++j) {
        const double y0 = s.y + j * c, y1 = std::min(y0 + c, yEnd);
        const Projected alongY = y1 - y0 < c ? step(ay, y1 - y0) : cellY;
        for (int i = 0; i < nx; ++i) {
            const double x0 = s.x + i * c, x1 = std::min(x0 + c, xEnd);
            const Projected alongX = x1 - x0 < c ? step(ax, x1 - x0) : cellX;
            const double z = f.at(i, j);
            const int cls = classOf(i, j);
            // The top, lit by the slope to its neighbours where they are near its height.
            const auto slope = [&](int di, int dj) {
                const int a = i + di, b = j + dj;
                if (a < 0 || b < 0 || a >= nx || b >= ny) return 0.0;
                const double d = f.at(a, b) - z;
                return std::abs(d) <= smooth ? d : 0.0;
            };
            const double dx = (slope(1, 0) - slope(-1, 0)) / (2 * c), dy = (slope(0, 1) - slope(0, -1)) / (2 * c);
            const Colour top = dx == 0 && dy == 0 ? topLit[cls] : canvas.lit(classes[cls], {-dx, -dy, 1});
            const Projected corner = at(x0, y0, z);
            canvas.parallelogram(corner, alongX, alongY, top);
            // The walls facing the viewer (+x, -y) down to the lower neighbour, or to the bottom at the edge.
            const double zx = i + 1 < nx ? f.at(i + 1, j) : zb;
            if (zx < z - smooth || (i + 1 == nx && z > zb)) {
                const Colour w = i + 1 < nx ? xWall[classOf(i + 1, j)] : xWall[0];
                canvas.parallelogram(at(x1, y0, zx), alongY, step(az, z - zx), w);
            }
            const double zy = j > 0 ? f.at(i, j - 1) : zb;
            if (zy < z - smooth || (j == 0 && z > zb)) {
                const Colour w = j > 0 ? yWall[classOf(i, j - 1)] : yWall[0];
                canvas.parallelogram(at(x0, y0, zy), alongX, step(az, z - zy), w);
            }
        }
    }
    if (path) drawPath(canvas, *path, 2 * c);
    return {canvas.take(), {}};
}

Result<std::vector<Picture>> stepPictures(const Plan& plan, int width, int height, int limit)
{
    std::vector<Picture> out;
    const int n = std::min(static_cast<int>(plan.steps.size()), limit);
    if (n <= 0) return out;
    if (width < 16 || height < 16) return Failure{"picture size " + std::to_string(width) + "x" + std::to_string(height) + " is below 16 pixels"};
    if (plan.mmJob.bar) {
        for (int k = 0; k < n; ++k) out.push_back(turnedPicture(plan, k, width, height));
        return out;
    }
    // About one cell for every two pixels: a cell's top is about two pixels wide in the iso view.
    const auto cells = static_cast<std::size_t>(width) * static_cast<std::size_t>(height) / 2;
    sim::StockSimulation simulation(plan, sim::StockGrid{0.25, cells});
    for (int k = 0; k < n; ++k) {
        const auto before = simulation.before(k);
        const auto after = simulation.after(k);
        const Step& step = plan.steps[static_cast<std::size_t>(k)];
        out.push_back(heightFieldPicture(*after, before.get(), step.path ? &*step.path : nullptr, width, height));
    }
    return out;
}

Picture setupPicture(const Plan& plan, int width, int height)
{
    return plan.mmJob.bar ? latheSetupPicture(plan, width, height) : millingSetup(plan.mmJob, width, height);
}

}  // namespace taiwa::picture
