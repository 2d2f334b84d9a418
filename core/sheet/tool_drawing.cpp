// The side view of a milling tool in its holder for the instruction sheet's
// tool list (tool_drawing.h): laid out once on a fixed canvas, written as
// SVG here and painted from the same shapes in the PDF.
#include "sheet/tool_drawing.h"

#include "tools/holder_shape.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace taiwa::sheet {

namespace {

using Part = ToolDrawing::Part;

constexpr double kMargin = 4.0;
constexpr double kToolBottom = 42.0;  // the tool drawn between kMargin and this, the dimension below
constexpr double kDimensionY = 50.0, kTextY = 61.0, kArrow = 4.0;

const char* fillOf(Part p)
{
    switch (p) {
    case Part::Holder: return "#9aa3b2";
    case Part::Shank: return "#d9dde4";
    case Part::Flutes: return "#f5a03c";
    case Part::Arrow: return "#000000";
    }
    return "#000000";
}

bool isLatheTool(ToolType t) { return t == ToolType::TurningInsert || t == ToolType::Grooving || t == ToolType::Threading; }

}  // namespace

std::optional<ToolDrawing> toolDrawing(const Tool& tool, const std::function<std::string(double)>& length)
{
    if (isLatheTool(tool.type) || !(tool.stickout > 0) || !(tool.diameter > 0)) return std::nullopt;
    const tools::HolderShape holder = tools::holderShape(tool);
    const double flutes = std::clamp(tool.fluteLength, 0.0, tool.stickout);
    // A taper end mill widens from its tip up its flutes.
    const double fluteTop = tool.diameter + 2.0 * flutes * std::tan(tool.taperAngle * std::numbers::pi / 180.0);
    const double widest = std::max({holder.noseDiameter, holder.shankDiameter, tool.diameter, fluteTop});
    ToolDrawing d;
    d.scale = std::min((ToolDrawing::kWidth - 2 * kMargin) / (holder.noseLength + tool.stickout),
                       (kToolBottom - kMargin) / widest);
    const double s = d.scale, c = (kMargin + kToolBottom) / 2;
    const double face = kMargin + holder.noseLength * s, tip = face + tool.stickout * s, fluteStart = tip - flutes * s;
    const auto box = [&](Part part, double x0, double x1, double dia) {
        if (x1 - x0 > 1e-9 && dia > 0)
            d.shapes.push_back({part, {{x0, c - dia * s / 2}, {x1, c - dia * s / 2}, {x1, c + dia * s / 2}, {x0, c + dia * s / 2}},
                                fillOf(part)});
    };
    box(Part::Holder, kMargin, face, holder.noseDiameter);
    box(Part::Shank, face, fluteStart, holder.shankDiameter);
    // The flutes: a drill's point at its point angle, a taper's widening.
    const double r = tool.diameter * s / 2, top = fluteTop * s / 2;
    const bool pointed = tool.type == ToolType::Drill || tool.type == ToolType::CentreDrill;
    const double point = pointed ? std::min(r / std::tan(tool.pointAngle * std::numbers::pi / 360.0), tip - fluteStart) : 0.0;
    if (tip - fluteStart > 1e-9) {
        std::vector<Point2> f{{fluteStart, c - top}, {tip - point, c - r}};
        if (pointed) f.push_back({tip, c});
        else f.push_back({tip, c - r}), f.push_back({tip, c + r});
        f.push_back({tip - point, c + r});
        f.push_back({fluteStart, c + top});
        d.shapes.push_back({Part::Flutes, std::move(f), fillOf(Part::Flutes)});
    }
    d.lines.push_back({{kMargin - 2, c}, {tip + 3, c}, true});
    // The stick-out: from the holder's face to the tip, with extension lines.
    d.lines.push_back({{face, c + holder.noseDiameter * s / 2 + 1}, {face, kDimensionY + 2}});
    d.lines.push_back({{tip, c + (pointed ? 0.0 : r) + 1}, {tip, kDimensionY + 2}});
    d.lines.push_back({{face, kDimensionY}, {tip, kDimensionY}});
    const double a = std::min(kArrow, (tip - face) / 2);
    d.shapes.push_back({Part::Arrow, {{face, kDimensionY}, {face + a, kDimensionY - 1.5}, {face + a, kDimensionY + 1.5}}, fillOf(Part::Arrow)});
    d.shapes.push_back({Part::Arrow, {{tip, kDimensionY}, {tip - a, kDimensionY - 1.5}, {tip - a, kDimensionY + 1.5}}, fillOf(Part::Arrow)});
    // Centred under the dimension, kept on the canvas (about 0.55 of the text size a character).
    const std::string text = "stick-out " + length(tool.stickout);
    const double half = 0.275 * ToolDrawing::kTextSize * static_cast<double>(text.size());
    d.texts.push_back({{std::clamp((face + tip) / 2, kMargin + half, ToolDrawing::kWidth - kMargin - half), kTextY}, text});
    return d;
}

std::string toolDrawingSvg(const ToolDrawing& d)
{
    std::string svg = fmt::format(R"(<svg xmlns="http://www.w3.org/2000/svg" class="tool" width="{0:g}" height="{1:g}" viewBox="0 0 {0:g} {1:g}">)",
                                  ToolDrawing::kWidth, ToolDrawing::kHeight);
    for (const auto& shape : d.shapes) {
        svg += "<polygon points=\"";
        for (std::size_t i = 0; i < shape.points.size(); ++i)
            svg += fmt::format("{}{:.2f},{:.2f}", i ? " " : "", shape.points[i].x, shape.points[i].y);
        svg += fmt::format(R"(" fill="{}" stroke="{}" stroke-width="0.6"/>)", shape.fill,
                           shape.part == Part::Arrow ? "none" : "#000000");
    }
    for (const auto& l : d.lines)
        svg += fmt::format(R"(<line x1="{:.2f}" y1="{:.2f}" x2="{:.2f}" y2="{:.2f}" stroke="#000000" stroke-width="0.5"{}/>)",
                           l.from.x, l.from.y, l.to.x, l.to.y, l.dashed ? R"( stroke-dasharray="6 2 1 2")" : "");
    // The texts are the sheet's own numbers, nothing of the job's: no escaping needed.
    for (const auto& t : d.texts)
        svg += fmt::format(R"(<text x="{:.2f}" y="{:.2f}" font-size="{:g}" text-anchor="middle">{}</text>)", t.at.x, t.at.y,
                           ToolDrawing::kTextSize, t.text);
    return svg + "</svg>";
}

}  // namespace taiwa::sheet
