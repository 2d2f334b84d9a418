// The circle and rectangle fits of work-centre probing, with Eigen: the
// algebraic circle (a linear least-squares problem) refined by Gauss-Newton
// on the points' distances, and the rectangle's direction as the principal
// axis of the pooled touches of every side touched twice.
#include "modules/probe/probe_fit.h"

#include "model/translate_noop.h"

#include <Eigen/Dense>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace taiwa::probe {

namespace {

constexpr double kCoincident = 1e-3;  // mm: two touches closer than this are one, whatever the tolerance

std::string mm(double v) { return fmt::format("{:.4g} mm", v); }

// Two touches closer than the tolerance (the scatter a touch may have) are
// one point measured twice: they tell nothing about the outline between
// them, and on one side of a rectangle they would turn it by up to 45°.
// The later one is named.
std::optional<FitProblem> coincident(const std::vector<Touch>& t, double tolerance)
{
    const double within = std::max(kCoincident, tolerance);
    for (std::size_t j = 1; j < t.size(); ++j)
        for (std::size_t i = 0; i < j; ++i)
            if (distance(t[i].at, t[j].at) < within)
                return FitProblem{static_cast<int>(j + 1),
                                  fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "point {} coincides with point {}: touch the outline elsewhere"), j + 1, i + 1)};
    return std::nullopt;
}

// The worst residual beyond the tolerance, if any.
std::optional<FitProblem> offFit(const std::vector<double>& residuals, double tolerance, const char* what)
{
    std::size_t worst = 0;
    for (std::size_t i = 1; i < residuals.size(); ++i)
        if (std::abs(residuals[i]) > std::abs(residuals[worst])) worst = i;
    if (residuals.empty() || std::abs(residuals[worst]) <= tolerance) return std::nullopt;
    return FitProblem{static_cast<int>(worst + 1),
                      fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "point {} is {} off the fitted {} (tolerance {}): touch it again, or check the "
                                  "shape and the order of the points"),
                                  worst + 1, mm(std::abs(residuals[worst])), what, mm(tolerance))};
}

}  // namespace

const char* toString(Side s)
{
    switch (s) {
    case Side::XMinus: return "-X";
    case Side::XPlus: return "+X";
    case Side::YMinus: return "-Y";
    case Side::YPlus: return "+Y";
    case Side::None: break;
    }
    return "none";
}

std::variant<CircleFit, FitProblem> fitCircle(const std::vector<Touch>& touches, const FitSettings& s)
{
    const std::size_t n = touches.size();
    if (n < 3)
        return FitProblem{0, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a round workpiece needs at least 3 touch points, {} given"), n)};
    if (auto p = coincident(touches, s.tolerance)) return *p;

    // About the points' mean, for the conditioning of the algebraic fit.
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
    for (const auto& t : touches) mean += Eigen::Vector2d(t.at.x, t.at.y);
    mean /= static_cast<double>(n);
    Eigen::MatrixXd pts(static_cast<Eigen::Index>(n), 2);
    for (std::size_t i = 0; i < n; ++i)
        pts.row(static_cast<Eigen::Index>(i)) = Eigen::Vector2d(touches[i].at.x, touches[i].at.y) - mean;

    // On a line (within the tolerance): no circle to speak of. Named: the
    // last point, which fails to leave the line of the others.
    const Eigen::Matrix2d scatter = pts.transpose() * pts;
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> axes(scatter);
    const Eigen::Vector2d normal = axes.eigenvectors().col(0);  // smallest eigenvalue first
    if ((pts * normal).cwiseAbs().maxCoeff() <= s.tolerance)
        return FitProblem{static_cast<int>(n),
                          fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "point {} lies on the line of points 1 to {} (within {}): a circle needs "
                                      "touches spread around it"),
                                      n, n - 1, mm(s.tolerance))};

    // Algebraic circle: x² + y² + D x + E y + F = 0 in the least-squares sense.
    Eigen::MatrixXd a(static_cast<Eigen::Index>(n), 3);
    Eigen::VectorXd b(static_cast<Eigen::Index>(n));
    for (Eigen::Index i = 0; i < a.rows(); ++i) {
        const double x = pts(i, 0), y = pts(i, 1);
        a.row(i) << x, y, 1.0;
        b(i) = -(x * x + y * y);
    }
    const Eigen::Vector3d def = a.colPivHouseholderQr().solve(b);
    Eigen::Vector3d c(-def(0) / 2, -def(1) / 2, 0.0);  // centre x, y and radius
    c(2) = std::sqrt(std::max(c(0) * c(0) + c(1) * c(1) - def(2), 0.0));

    // Geometric refinement: the points' distances to the circle, least squares.
    for (int it = 0; it < 100; ++it) {
        Eigen::MatrixXd j(static_cast<Eigen::Index>(n), 3);
        Eigen::VectorXd r(static_cast<Eigen::Index>(n));
        for (Eigen::Index i = 0; i < j.rows(); ++i) {
            const double dx = pts(i, 0) - c(0), dy = pts(i, 1) - c(1), d = std::hypot(dx, dy);
            r(i) = d - c(2);
            j.row(i) << -dx / d, -dy / d, -1.0;
        }
        const Eigen::Vector3d step = j.colPivHouseholderQr().solve(-r);
        c += step;
        if (step.norm() < 1e-13 * std::max(1.0, c(2))) break;
    }

    CircleFit fit;
    fit.centre = {c(0) + mean(0), c(1) + mean(1)};
    for (Eigen::Index i = 0; i < pts.rows(); ++i)
        fit.residuals.push_back(std::hypot(pts(i, 0) - c(0), pts(i, 1) - c(1)) - c(2));
    if (auto p = offFit(fit.residuals, s.tolerance, TAIWA_TRANSLATE_NOOP("taiwa::msg", "circle"))) return *p;
    fit.radius = s.inside ? c(2) + s.ballRadius : c(2) - s.ballRadius;
    if (fit.radius <= 0)
        return FitProblem{0, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the touches lie on a circle of radius {}, no larger than the stylus ball's "
                                         "radius {}: is the workpiece a bore rather than a boss?"),
                                         mm(c(2)), mm(s.ballRadius))};
    return fit;
}

std::variant<RectangleFit, FitProblem> fitRectangle(const std::vector<Touch>& touches, const FitSettings& s)
{
    const std::size_t n = touches.size();
    for (std::size_t i = 0; i < n; ++i)
        if (touches[i].side == Side::None)
            return FitProblem{static_cast<int>(i + 1), fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "point {}: the side it touches is not given"), i + 1)};
    for (const Side side : {Side::XMinus, Side::XPlus, Side::YMinus, Side::YPlus})
        if (std::none_of(touches.begin(), touches.end(), [&](const Touch& t) { return t.side == side; }))
            return FitProblem{0, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a rectangular workpiece needs a touch on every side: none on {}"),
                                             toString(side))};
    if (auto p = coincident(touches, s.tolerance)) return *p;

    // The direction of the part's X axis: the sides touched twice or more,
    // each about its own mean, the X sides turned a quarter so that they
    // run along X too, pooled; their principal axis.
    Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
    bool measured = false;
    for (const Side side : {Side::XMinus, Side::XPlus, Side::YMinus, Side::YPlus}) {
        std::vector<Eigen::Vector2d> on;
        for (const auto& t : touches)
            if (t.side == side) on.emplace_back(t.at.x, t.at.y);
        if (on.size() < 2) continue;
        measured = true;
        Eigen::Vector2d mean = Eigen::Vector2d::Zero();
        for (const auto& p : on) mean += p;
        mean /= static_cast<double>(on.size());
        for (const auto& p : on) {
            Eigen::Vector2d d = p - mean;
            if (side == Side::XMinus || side == Side::XPlus) d = Eigen::Vector2d(d.y(), -d.x());
            scatter += d * d.transpose();
        }
    }
    double angle = 0.0;
    if (measured) {
        Eigen::Vector2d e = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(scatter).eigenvectors().col(1);
        if (e.x() < 0) e = -e;
        angle = std::atan2(e.y(), e.x());
    }
    const Point2 ex{std::cos(angle), std::sin(angle)}, ey{-std::sin(angle), std::cos(angle)};

    // Each side's line: the mean of its touches across it.
    double sum[5] = {0, 0, 0, 0, 0};
    int count[5] = {0, 0, 0, 0, 0};
    const auto across = [&](const Touch& t) {
        return t.side == Side::XMinus || t.side == Side::XPlus ? dot(t.at, ex) : dot(t.at, ey);
    };
    for (const auto& t : touches) {
        sum[static_cast<int>(t.side)] += across(t);
        ++count[static_cast<int>(t.side)];
    }
    double line[5] = {0, 0, 0, 0, 0};
    for (int k = 1; k <= 4; ++k) line[k] = sum[k] / count[k];
    const auto firstOn = [&](Side side) {
        for (std::size_t i = 0; i < n; ++i)
            if (touches[i].side == side) return static_cast<int>(i + 1);
        return 0;
    };
    if (line[2] <= line[1])
        return FitProblem{firstOn(Side::XPlus),
                          fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the points on -X and +X are swapped: the +X side (point {}) lies at or left of "
                                      "the -X side (point {})"),
                                      firstOn(Side::XPlus), firstOn(Side::XMinus))};
    if (line[4] <= line[3])
        return FitProblem{firstOn(Side::YPlus),
                          fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the points on -Y and +Y are swapped: the +Y side (point {}) lies at or below "
                                      "the -Y side (point {})"),
                                      firstOn(Side::YPlus), firstOn(Side::YMinus))};

    RectangleFit fit;
    for (const auto& t : touches) {
        const double off = across(t) - line[static_cast<int>(t.side)];
        fit.residuals.push_back(t.side == Side::XMinus || t.side == Side::YMinus ? -off : off);
    }
    if (auto p = offFit(fit.residuals, s.tolerance, TAIWA_TRANSLATE_NOOP("taiwa::msg", "rectangle"))) return *p;
    const double ball = s.inside ? -2 * s.ballRadius : 2 * s.ballRadius;
    fit.width = line[2] - line[1] - ball;
    fit.length = line[4] - line[3] - ball;
    if (fit.width <= 0 || fit.length <= 0)
        return FitProblem{0, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the touches span {} x {}, no more than the stylus ball: is the workpiece a "
                                         "pocket rather than a block?"),
                                         mm(line[2] - line[1]), mm(line[4] - line[3]))};
    fit.centre = 0.5 * (line[1] + line[2]) * ex + 0.5 * (line[3] + line[4]) * ey;
    fit.rotation = angle * 180 / std::numbers::pi;
    fit.rotationMeasured = measured;
    return fit;
}

}  // namespace taiwa::probe
