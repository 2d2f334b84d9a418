// Evaluation of figure definitions (figure_text.h) into coordinates for
// display and picking: points, lines (a point and a unit direction), circles
// (centre and radius). Definitions are evaluated in order, each from the
// elements before it, so evaluating again after a change gives everything
// defined from the changed element anew. Geometric refusals (parallel lines
// intersected, a tangent that does not exist...) name the element. Contours
// evaluate to exact line/arc chains (figure_contour.h).
#pragma once

#include "figure/figure_contour.h"
#include "figure/figure_text.h"
#include "model/geometry.h"

#include <optional>
#include <string>
#include <unordered_map>
#include <variant>
#include <vector>

namespace taiwa::figure {


// An infinite line: a point on it and its unit direction. Its left normal is
// (-dir.y, dir.x); the line is normal·p = normal·point.
struct Line {
    Point2 point;
    Point2 dir;
};

struct Circle {
    Point2 centre;
    double radius = 0;
};

struct Element {
    std::string name;
    Kind kind = Kind::Point;
    Point2 point;      // Kind::Point
    Line line;      // Kind::Line
    Circle circle;  // Kind::Circle
};

// Every element that could be evaluated, in definition order, and the
// refusals (at the refused statement's line and column, the message starting
// with the element's name). An element defined from a refused one is not
// evaluated and not reported again: the first refusal is its cause.
// Contours are not elements (nothing is defined from them): they are kept
// apart, in definition order.
struct Evaluation {
    std::vector<Element> elements;
    std::vector<EvaluatedContour> contours;
    std::vector<FigureError> errors;
    bool ok() const { return errors.empty(); }
    // By name: through the index evaluate() keeps while it matches the
    // vectors (a figure of 200,000 elements looks each name up once, not
    // along all of them), else along the vector.
    const Element* find(const std::string& name) const;
    const EvaluatedContour* findContour(const std::string& name) const;
    std::unordered_map<std::string, std::size_t> elementIndex, contourIndex;
};

// Distances below this are zero (mm): coincident points, a point on a circle,
// a tangent touching.
constexpr double kTolerance = 1e-9;

// The definitions must be as parseFigure gives them (every name defined once
// and before use, each argument of the kind its place needs); definitions
// built otherwise that break this are a bug (std::logic_error).
Evaluation evaluate(const std::vector<Definition>& definitions);

// The contour `d` (Method::Contour) from the elements evaluated before it
// (`before`, every element it uses present), or its refusal: the message
// starts with the contour's name and is placed at the item it concerns.
// Used by evaluate(); defined in figure_contour.cpp.
std::variant<EvaluatedContour, FigureError> evaluateContour(const Definition& d, const Evaluation& before);

// The names of every element defined, directly or through others, from
// `name`: what changes when it changes.
std::vector<std::string> definedFrom(const std::vector<Definition>& definitions, const std::string& name);

}  // namespace taiwa::figure
