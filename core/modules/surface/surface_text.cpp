// The SURFACE unit's curves and boundary as the station's form shows and
// reads them (docs/surfaces.md, "The form"): a curve as points in space
// "5, 75, -6; 115, 75, -6", or as its two projections "XY: 5, 5; 60, 10 /
// ZX: -8, 5; -14, 60" (a projection may name a contour of the job's figure
// instead: "XY: K1 / ZX: K2"), a last piece "/ lines" for straight lines between
// the points; the boundary as paths of points "x, y, z; ... / x, y, z; ...".
#include "modules/surface/surface.h"

#include "figure/figure_text.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <string_view>

namespace taiwa::surfacemod {

namespace {

std::string_view trimmed(std::string_view s)
{
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}

// Pieces of `text` between `sep`, each trimmed (empty ones kept).
std::vector<std::string_view> split(std::string_view text, char sep)
{
    std::vector<std::string_view> out;
    for (std::size_t from = 0;;) {
        const std::size_t at = text.find(sep, from);
        out.push_back(trimmed(text.substr(from, at == std::string_view::npos ? std::string_view::npos : at - from)));
        if (at == std::string_view::npos) return out;
        from = at + 1;
    }
}

std::optional<double> readNumber(std::string_view s)
{
    s = trimmed(s);
    if (!s.empty() && s.front() == '+') s.remove_prefix(1);
    double v = 0.0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (s.empty() || ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
    return v;
}

// "a, b; a, b" (n = 2) or "x, y, z; ..." (n = 3): each point's n numbers;
// nothing when a point has another count or a word is no number.
std::optional<std::vector<std::vector<double>>> readTuples(std::string_view text, std::size_t n)
{
    std::vector<std::vector<double>> out;
    for (std::string_view piece : split(text, ';')) {
        if (piece.empty()) continue;
        std::vector<double> t;
        for (std::string_view word : split(piece, ',')) {
            const auto v = readNumber(word);
            if (!v) return std::nullopt;
            t.push_back(*v);
        }
        if (t.size() != n) return std::nullopt;
        out.push_back(std::move(t));
    }
    if (out.empty()) return std::nullopt;
    return out;
}

std::optional<std::vector<Point3>> readPoints3(std::string_view text)
{
    const auto t = readTuples(text, 3);
    if (!t) return std::nullopt;
    std::vector<Point3> out;
    for (const auto& p : *t) out.push_back({p[0], p[1], p[2]});
    return out;
}

std::string n(double v) { return figure::formatNumber(v); }

// A figure element's name: a letter, then letters, digits or '_'.
bool isName(std::string_view s)
{
    if (s.empty() || !std::isalpha(static_cast<unsigned char>(s.front()))) return false;
    for (const char ch : s)
        if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '_') return false;
    return true;
}

std::string writePoints3(const std::vector<Point3>& points)
{
    std::string text;
    for (const Point3 p : points) text += (text.empty() ? "" : "; ") + n(p.x) + ", " + n(p.y) + ", " + n(p.z);
    return text;
}

}  // namespace

std::string formatCurve(const SurfaceCurve& c)
{
    std::string text;
    if (!c.points.empty() || c.projections.empty()) text = writePoints3(c.points);
    else
        for (const SurfaceProjection& pr : c.projections) {
            std::string pts = pr.contour;
            if (pts.empty())
                for (const Point2 p : pr.points) pts += (pts.empty() ? "" : "; ") + n(p.x) + ", " + n(p.y);
            text += (text.empty() ? "" : " / ") + pr.plane + ": " + pts;
        }
    if (!c.smooth) text += " / lines";
    return text;
}

std::optional<SurfaceCurve> parseCurve(const std::string& text)
{
    SurfaceCurve c;
    bool points = false;
    for (std::string_view piece : split(text, '/')) {
        if (piece.empty()) return std::nullopt;
        if (piece == "lines" || piece == "LINES") {
            if (!c.smooth) return std::nullopt;
            c.smooth = false;
            continue;
        }
        const std::size_t colon = piece.find(':');
        if (colon == std::string_view::npos) {
            if (points || !c.projections.empty()) return std::nullopt;
            auto p = readPoints3(piece);
            if (!p) return std::nullopt;
            c.points = std::move(*p);
            points = true;
            continue;
        }
        std::string plane(trimmed(piece.substr(0, colon)));
        for (char& ch : plane) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
        if (points || plane.empty()) return std::nullopt;
        SurfaceProjection pr{plane, {}, {}, {}};
        // A figure contour's name ("XY: K1"), else the points.
        const std::string_view rest = trimmed(piece.substr(colon + 1));
        if (isName(rest)) {
            pr.contour = std::string(rest);
        } else {
            const auto t = readTuples(rest, 2);
            if (!t) return std::nullopt;
            for (const auto& p : *t) pr.points.push_back({p[0], p[1]});
        }
        c.projections.push_back(std::move(pr));
    }
    if (!points && c.projections.empty()) return std::nullopt;
    return c;
}

std::string formatBoundary(const std::vector<std::vector<Point3>>& paths)
{
    std::string text;
    for (const auto& path : paths) text += (text.empty() ? "" : " / ") + writePoints3(path);
    return text;
}

std::optional<std::vector<std::vector<Point3>>> parseBoundary(const std::string& text)
{
    std::vector<std::vector<Point3>> paths;
    if (trimmed(text).empty()) return paths;  // no boundary
    for (std::string_view piece : split(text, '/')) {
        auto p = readPoints3(piece);
        if (!p) return std::nullopt;
        paths.push_back(std::move(*p));
    }
    return paths;
}

}  // namespace taiwa::surfacemod
