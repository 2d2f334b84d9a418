// Contours to figure elements (figure_from_contours.h): each contour made
// ready (collinear lines and arcs on one circle merged), its definitions
// made (contour_writer.h) to 1e-6 mm and, where a junction amplifies the
// rounding, with more decimals, evaluated as the job will, and kept, noted
// or left out by how far it comes back; the one kept is written and read
// back.
#include "figure/figure_from_contours.h"

#include "figure/contour_names.h"
#include "figure/contour_writer.h"
#include "figure/figure_eval.h"
#include "figure/figure_parser.h"
#include "model/result.h"
#include "model/translate_noop.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

namespace taiwa {

namespace {

using figure::Definition;

constexpr double kMerge = 1e-7;  // mm: collinear lines, arcs on one circle
constexpr double kTwoPi = 2.0 * std::numbers::pi;

bool sameCircle(const ContourSegment& a, const ContourSegment& b)
{
    return a.isArc() && a.kind == b.kind && distance(a.centre, b.centre) <= kMerge &&
           std::abs(a.radius() - b.radius()) <= kMerge && std::abs(a.sweep()) + std::abs(b.sweep()) <= kTwoPi + 1e-12;
}

bool collinear(const ContourSegment& a, const ContourSegment& b)
{
    if (a.isArc() || b.isArc()) return false;
    const Point2 chord = b.end - a.start;
    const double len = length(chord);
    if (len <= kMerge || dot(a.end - a.start, b.end - b.start) <= 0.0) return false;
    return std::abs(cross(chord, a.end - a.start)) / len <= kMerge;
}

std::optional<ContourSegment> joined(const ContourSegment& a, const ContourSegment& b)
{
    if (collinear(a, b)) return ContourSegment::line(a.start, b.end);
    if (!sameCircle(a, b)) return std::nullopt;
    ContourSegment s = ContourSegment::arc(a.start, b.end, a.centre, a.kind == ContourSegment::Kind::ArcCCW);
    if (distance(s.start, s.end) <= 1e-9) s.end = s.start;  // round to where it started: the whole circle
    return s;
}

// The largest distance of `got`'s ends and centres from `want`'s, segment by
// segment; infinite when the segments differ in number or kind.
double deviation(const Contour& got, const Contour& want)
{
    if (got.closed != want.closed || got.segments.size() != want.segments.size())
        return std::numeric_limits<double>::infinity();
    double worst = 0.0;
    for (std::size_t i = 0; i < got.segments.size(); ++i) {
        const ContourSegment &g = got.segments[i], &w = want.segments[i];
        if (g.kind != w.kind) return std::numeric_limits<double>::infinity();
        worst = std::max({worst, distance(g.start, w.start), distance(g.end, w.end)});
        if (g.isArc()) worst = std::max(worst, distance(g.centre, w.centre));
    }
    return worst;
}

std::string describe(const Contour& c)
{
    int lines = 0, arcs = 0;
    for (const auto& s : c.segments) ++(s.isArc() ? arcs : lines);
    const auto count = [](int k, const char* one, const char* many) {
        return std::to_string(k) + " " + (k == 1 ? one : many);
    };
    if (c.closed && c.segments.size() == 1 && arcs == 1) return "closed, a full circle";
    return std::string(c.closed ? "closed, " : "open, ") + count(lines, "line", "lines") + ", " +
           count(arcs, "arc", "arcs");
}

}  // namespace

std::set<std::string> figureNames(std::string_view text)
{
    std::set<std::string> out;
    std::size_t i = 0;
    while (i < text.size()) {
        const std::size_t eol = std::min(text.find('\n', i), text.size());
        std::size_t j = i;
        while (j < eol && (text[j] == ' ' || text[j] == '\t')) ++j;
        std::string name;
        if (j < eol && figure::isLetter(text[j]))
            while (j < eol && (figure::isLetter(text[j]) || figure::isDigit(text[j]))) name += figure::upper(text[j++]);
        while (j < eol && (text[j] == ' ' || text[j] == '\t')) ++j;
        if (!name.empty() && j < eol && text[j] == '=') out.insert(name);
        i = eol + 1;
    }
    return out;
}

Contour figureReady(const Contour& c)
{
    const Contour in = withoutDegenerateSegments(c);
    Contour out;
    out.closed = in.closed;
    for (const auto& s : in.segments) {
        if (!out.segments.empty())
            if (const auto j = joined(out.segments.back(), s)) {
                out.segments.back() = *j;
                continue;
            }
        out.segments.push_back(s);
    }
    if (out.closed && out.segments.size() > 1)
        if (const auto j = joined(out.segments.back(), out.segments.front())) {
            out.segments.front() = *j;
            out.segments.pop_back();
        }
    if (out.closed && out.segments.size() == 1 && out.segments[0].isArc()) {
        ContourSegment& s = out.segments[0];
        s.start = s.end = Point2{s.centre.x + s.radius(), s.centre.y};
    }
    return out;
}

namespace {

// One contour's definitions with their numbers to the nearest 1/scale mm,
// and how far their contour comes back from `c`. The definitions are
// evaluated as they are: written and read back they are the same
// definitions (every number is a multiple of 1/scale, which the text
// writes exactly), so only the attempt kept is written (writeOut).
struct Attempt {
    std::vector<Definition> definitions;
    std::string text;
    double deviation = 0;
    double scale = 0;
};

Attempt attempt(figure::Namer& names, const Contour& c, double scale)
{
    Attempt a;
    a.scale = scale;
    a.definitions = figure::contourDefinitions(names, c, scale);
    const figure::Evaluation ev = figure::evaluate(a.definitions);
    if (!ev.ok()) throw Refusal(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "its text is refused: {}"), ev.errors.front().message));
    a.deviation = deviation(ev.contours.at(0).contour, c);
    return a;
}

// The kept attempt's text, read back as the job will read it. Should it
// read back as other definitions than were written, its deviation is
// measured again on what it does say.
void writeOut(Attempt& a, const Contour& c)
{
    a.text = figure::writeFigure(a.definitions);
    // Statement by statement against what was written, none of it kept (a
    // contour of 200,000 lines is 400,000 statements).
    std::size_t k = 0;
    bool same = true;
    try {
        figure::text::Parser(a.text).eachStatement([&](Definition&& d) {
            same = k < a.definitions.size() && d == a.definitions[k];
            ++k;
            return same;
        });
    } catch (const Refusal& r) {
        throw std::logic_error("figure from contours: written text refused: " + r.message());
    }
    if (same && k == a.definitions.size()) return;
    const figure::ParseResult read = figure::parseFigure(a.text);
    if (!read.ok()) throw std::logic_error("figure from contours: written text refused: " + read.error->text());
    const figure::Evaluation ev = figure::evaluate(read.definitions);
    a.deviation = ev.ok() ? deviation(ev.contours.at(0).contour, c) : std::numeric_limits<double>::infinity();
}

}  // namespace

FigureFromContours figureFromContours(const std::vector<Contour>& contours, const FigureNaming& naming)
{
    FigureFromContours out;
    figure::Namer names(naming);
    int number = 0;
    for (const Contour& given : contours) {
        ++number;
        const Contour c = figureReady(given);
        names.mark();
        // To 1e-6 mm; where a junction amplifies the rounding beyond
        // kFigureRoundTrip, the contour's numbers get more decimals.
        std::optional<Attempt> best;
        figure::Namer::Given bestNames;
        std::string why;  // why it is not written to 1e-6 mm
        for (const double scale : {1e6, 1e7, 1e8, 1e9}) {
            try {
                Attempt a = attempt(names, c, scale);
                if (why.empty() && a.deviation > kFigureRoundTrip)
                    why = std::isinf(a.deviation) ? std::string(TAIWA_TRANSLATE_NOOP("taiwa::msg", "its text gives back other segments"))
                                                  : fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "it comes back {:.7f} mm from the drawing"), a.deviation);
                if (a.deviation <= kFigureRoundTrip) {  // kept, with the names it was given
                    best = std::move(a);
                    break;
                }
                const bool better = !best || a.deviation < best->deviation;
                figure::Namer::Given taken = names.takeBack();
                if (better) best = std::move(a), bestNames = std::move(taken);
            } catch (const Refusal& r) {  // a contour that cannot be written; caught per contour
                names.takeBack();
                if (why.empty()) why = r.message();
            }
        }
        // An attempt within kFigureRoundTrip still has its names given;
        // the others' were taken back.
        const bool kept = best && best->deviation <= kFigureRoundTrip;
        if (best) writeOut(*best, c);
        if (!best || !(best->deviation <= kFigureUsable)) {
            if (kept) names.takeBack();
            out.refusals.push_back(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "contour {} is left out: {}"), number, why));
            out.text += fmt::format("$$ contour {} ({}) left out: {}\n", number, describe(c), why);
            out.names.emplace_back();
            out.deviations.push_back(0.0);
            continue;
        }
        if (!kept) names.giveAgain(bestNames);
        const std::string name = best->definitions.back().name;
        if (best->deviation > kFigureRoundTrip)
            out.notes.push_back(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "contour {} ({}) comes back {:.7f} mm from the drawing"), number, name,
                                            best->deviation));
        else if (best->scale > 1e6)
            out.notes.push_back(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "contour {} ({}) is written to {} mm: to 0.000001 mm {}"), number, name,
                                            figure::formatNumber(1.0 / best->scale), why));
        out.text += fmt::format("$$ contour {}: {}\n", number, describe(c));
        out.text += best->text;
        out.names.push_back(name);
        out.deviations.push_back(best->deviation);
    }
    return out;
}

std::string figureTextFromContours(const std::vector<Contour>& contours, const FigureNaming& naming)
{
    return figureFromContours(contours, naming).text;
}

}  // namespace taiwa
