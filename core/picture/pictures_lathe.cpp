// The sheet's lathe pictures (pictures.h): the turned bar from the front,
// its outline the section's (sim::turnedStockAfter) mirrored about the
// axis, each pixel lit as the solid of revolution's surface there; the
// setup's bar in the chuck.
#include "picture/pictures.h"

#include "machine/machine.h"
#include "model/turned_geometry.h"
#include "model/turn_path.h"
#include "picture/canvas.h"
#include "sheet/sheet.h"
#include "sim/turned_stock.h"

#include <algorithm>
#include <cmath>

namespace taiwa::picture {

namespace {

using namespace colours;
using Loops = std::vector<std::vector<turning::ZR>>;

// The loops' inside (even-odd) mirrored about the axis, as `value` in
// `mask`: pixel (x, y) at z = (x + 0.5 - x0) / scale, r = (axisY - y - 0.5) / scale.
void fill(std::vector<std::uint8_t>& mask, int width, int height, const Loops& loops, double x0, double axisY, double scale,
          std::uint8_t value)
{
    std::vector<double> at;
    for (int y = 0; y < height; ++y) {
        const double r = std::abs((axisY - (y + 0.5)) / scale);
        at.clear();
        for (const auto& loop : loops)
            for (std::size_t k = 0; k < loop.size(); ++k) {
                const turning::ZR& a = loop[k];
                const turning::ZR& b = loop[(k + 1) % loop.size()];
                if ((a.r <= r) == (b.r <= r)) continue;
                at.push_back(a.z + (r - a.r) / (b.r - a.r) * (b.z - a.z));
            }
        std::sort(at.begin(), at.end());
        for (std::size_t k = 0; k + 1 < at.size(); k += 2) {
            const int from = std::max(0, static_cast<int>(std::ceil(x0 + at[k] * scale - 0.5)));
            const int to = std::min(width - 1, static_cast<int>(std::floor(x0 + at[k + 1] * scale - 0.5)));
            for (int x = from; x <= to; ++x) mask[static_cast<std::size_t>(y) * width + x] = value;
        }
    }
}

// A colour lit as a cylinder's surface at t = height / radius (-1..1), seen from the front.
Colour cylinderLit(const Canvas& canvas, Colour base, double t)
{
    t = std::clamp(t, -1.0, 1.0);
    return canvas.lit(base, {0, -std::sqrt(1 - t * t), t});
}

// A rectangle in the view's plane, z along the axis, r up, in `c` as it is.
void rect(Canvas& canvas, double z0, double z1, double r0, double r1, Colour c, double alpha = 1.0)
{
    const Projected p[4] = {canvas.project({z0, 0, r0}), canvas.project({z1, 0, r0}), canvas.project({z1, 0, r1}),
                            canvas.project({z0, 0, r1})};
    canvas.polygon(p, 4, c, alpha);
}

void markOrigin(Canvas& canvas, Picture& out, double length, const std::string& name)
{
    constexpr double kOnTop = 1e9;
    canvas.line({0, 0, 0}, {length, 0, 0}, kAxisZ, 2, kOnTop);
    canvas.line({0, 0, 0}, {0, 0, length}, kAxisX, 2, kOnTop);
    const Projected z = canvas.project({length, 0, 0}), x = canvas.project({0, 0, length}), o = canvas.project({0, 0, 0});
    out.labels.push_back({z.x + 3, z.y - 3, "Z", kAxisZ, 13, true, false});
    out.labels.push_back({x.x + 3, x.y - 3, "X", kAxisX, 13, true, false});
    out.labels.push_back({o.x + 10, o.y + 24, name, kText, 15, true, false});
}

}  // namespace

Picture turnedPicture(const Plan& plan, int step, int width, int height)
{
    const BarStock& bar = *plan.mmJob.bar;
    const double r = bar.diameter / 2, jawsFront = bar.face - barStickOut(plan);
    Canvas canvas(width, height, kBackground, Canvas::View::Front, {jawsFront, bar.face + 0.2 * r, 0, 0, -1.1 * r, 1.1 * r});
    const double scale = canvas.scale(), x0 = canvas.project({0, 0, 0}).x, axisY = canvas.project({0, 0, 0}).y;
    std::vector<std::uint8_t> mask(static_cast<std::size_t>(width) * height, 0);
    fill(mask, width, height, sim::turnedStockAfter(plan, step - 1), x0, axisY, scale, 1);
    fill(mask, width, height, sim::turnedStockAfter(plan, step), x0, axisY, scale, 2);
    // Each column's outer radius: its surface's curvature for the light.
    constexpr int kShades = 64;
    Colour shades[2][kShades + 1];
    for (int k = 0; k <= kShades; ++k) {
        const double t = 2.0 * k / kShades - 1;
        shades[0][k] = cylinderLit(canvas, kRemoved, t), shades[1][k] = cylinderLit(canvas, kMachined, t);
    }
    Image& image = canvas.image();
    for (int x = 0; x < width; ++x) {
        double outer = 0;
        for (int y = 0; y < height; ++y)
            if (mask[static_cast<std::size_t>(y) * width + x]) {
                outer = std::abs((axisY - (y + 0.5)) / scale);
                break;
            }
        if (outer <= 0) continue;
        for (int y = 0; y < height; ++y) {
            const std::uint8_t m = mask[static_cast<std::size_t>(y) * width + x];
            if (!m) continue;
            const double t = (axisY - (y + 0.5)) / scale / outer;
            const int k = std::clamp(static_cast<int>(std::lround((t + 1) / 2 * kShades)), 0, kShades);
            image.set(x, y, shades[m - 1][k]);
        }
    }
    // The axis, dash-dotted.
    for (int x = 0; x < width; ++x)
        if (const int p = x % 16; p < 9 || (p >= 11 && p < 13)) image.set(x, std::clamp(static_cast<int>(axisY), 0, height - 1), kCentreLine);
    // The path of the step: its feed moves in (z, r).
    const Step& s = plan.steps[static_cast<std::size_t>(step)];
    if (turnOf(s)) {
        turning::ZR at = turnOf(s)->path.start;
        for (const auto& m : turnOf(s)->path.moves) {
            if (m.kind == TurnMove::ArcCW || m.kind == TurnMove::ArcCCW) {
                const auto arc = turning::arcSegment(at, m.end, m.centre, m.kind == TurnMove::ArcCCW);
                const int n = std::max(2, static_cast<int>(std::ceil(turning::sweep(arc) / 0.1)));
                turning::ZR prev = at;
                for (int i = 1; i <= n; ++i) {
                    const turning::ZR q = turning::pointAt(arc, turning::length(arc) * i / n);
                    canvas.line({prev.z, 0, prev.r}, {q.z, 0, q.r}, kPath, 1, 1e9);
                    prev = q;
                }
            } else if (m.kind != TurnMove::Rapid) {
                canvas.line({at.z, 0, at.r}, {m.end.z, 0, m.end.r}, kPath, 1, 1e9);
            }
            at = m.end;
        }
    }
    return {canvas.take(), {}};
}

Picture latheSetupPicture(const Plan& plan, int width, int height)
{
    const BarStock& bar = *plan.mmJob.bar;
    const double r = bar.diameter / 2, jawsFront = bar.face - barStickOut(plan);
    const Machine* machine = findMachine(plan.mmJob.machine);
    const double chuckR = machine && machine->chuckDiameter > 2 * r ? machine->chuckDiameter / 2 : 2.5 * r;
    const double jawLength = std::max(0.6 * r, 10.0), jawHeight = 0.45 * (chuckR - r), chuckFront = jawsFront - jawLength;
    const double reach = 1.3 * (r + jawHeight);
    Canvas canvas(width, height, kBackground, Canvas::View::Front,
                  {chuckFront - 0.3 * chuckR, std::max(bar.face, 0.0) + 1.5 * r, 0, 0, -reach, reach});
    rect(canvas, chuckFront - 0.6 * chuckR, chuckFront, -chuckR, chuckR, canvas.lit(kChuck, {0, -1, 0}));
    // The bar out of the chuck, in strips lit as a cylinder.
    constexpr int kStrips = 48;
    for (int k = 0; k < kStrips; ++k) {
        const double t0 = 2.0 * k / kStrips - 1, t1 = 2.0 * (k + 1) / kStrips - 1;
        rect(canvas, chuckFront, bar.face, t0 * r, t1 * r, cylinderLit(canvas, kStock, (t0 + t1) / 2));
    }
    rect(canvas, chuckFront, jawsFront, r, r + jawHeight, canvas.lit(kClamp, {0, -1, 0}), 0.8);
    rect(canvas, chuckFront, jawsFront, -r - jawHeight, -r, canvas.lit(kClamp, {0, -1, 0}), 0.8);
    Picture out;
    markOrigin(canvas, out, std::max(1.3 * r, 5.0), plan.job.workOffset);
    out.image = canvas.take();
    return out;
}

}  // namespace taiwa::picture
