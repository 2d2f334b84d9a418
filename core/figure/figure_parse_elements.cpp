// The figure language's element statements, read by the parser
// (figure_parser.h): POINT, LINE, CIRCLE with their methods, RADIUS, and
// CONTOUR with its steps, modifiers and corners.
#include "figure/figure_parser.h"

namespace taiwa::figure::text {

void Parser::point(Definition& d)
{
    if (cur_.tok == Tok::Number) {  // POINT/x, y
        d.method = Method::PointXY;
        d.numbers.push_back(number(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a number")));
        comma();
        d.numbers.push_back(number(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a number (the y coordinate)")));
    } else if (accept("CENTER")) {  // POINT/CENTER, C1
        d.method = Method::PointCenter;
        comma();
        d.refs.push_back(ref(Kind::Circle, TAIWA_TRANSLATE_NOOP("taiwa::msg", "a circle name")));
    } else if (atWord("INTOF") || (atModifier() && isXY(*atModifier()))) {
        d.method = Method::PointIntof;
        Token modTok = cur_;
        if (!atWord("INTOF")) {
            d.modifiers.push_back(modifier(true, kXY));
            comma();
        }
        word("INTOF");
        comma();
        Kind k1 = Kind::Line;
        Kind k2 = Kind::Line;
        d.refs.push_back(curve(k1));
        comma();
        const Token second = cur_;
        d.refs.push_back(curve(k2));
        const bool circle = k1 == Kind::Circle || k2 == Kind::Circle;
        if (circle && d.modifiers.empty())
            fail(second, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "in {}, {} and {} may meet twice: write XLARGE, XSMALL, YLARGE or YSMALL before INTOF to choose"),
                                     name_, d.refs[0], d.refs[1]));
        if (!circle && !d.modifiers.empty())
            fail(modTok, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "in {}, two lines meet once: no {} before INTOF"), name_, keyword(d.modifiers[0])));
    } else {
        expected(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a number, CENTER, INTOF or XLARGE/XSMALL/YLARGE/YSMALL"));
    }
}

void Parser::line(Definition& d)
{
    if (accept("PARLEL")) {  // LINE/PARLEL, L1, XLARGE, 5
        d.method = Method::LineParallel;
        comma();
        d.refs.push_back(ref(Kind::Line, TAIWA_TRANSLATE_NOOP("taiwa::msg", "a line name")));
        comma();
        d.modifiers.push_back(modifier(true, kXY));
        comma();
        d.numbers.push_back(number(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a number (the distance)"), TAIWA_TRANSLATE_NOOP("taiwa::msg", "the distance")));
    } else if (const auto m = atModifier(); m && (*m == Modifier::Left || *m == Modifier::Right)) {
        d.method = Method::LineTwoCircles;  // LINE/LEFT, TANTO, C1, RIGHT, TANTO, C2
        tangentCircle(d);
        comma();
        tangentCircle(d);
    } else if (atName()) {
        d.refs.push_back(ref(Kind::Point, TAIWA_TRANSLATE_NOOP("taiwa::msg", "a point name")));
        comma();
        if (accept("ATANGL")) {  // LINE/P1, ATANGL, 30
            d.method = Method::LineAtAngle;
            comma();
            d.numbers.push_back(number(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a number (the angle in degrees)")));
        } else if (atModifier()) {  // LINE/P1, LEFT, TANTO, C1
            d.method = Method::LinePointTangent;
            tangentCircle(d);
        } else if (atName()) {  // LINE/P1, P2
            d.method = Method::LineTwoPoints;
            d.refs.push_back(ref(Kind::Point, TAIWA_TRANSLATE_NOOP("taiwa::msg", "a point name")));
        } else {
            expected(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a point name, ATANGL, LEFT or RIGHT"));
        }
    } else {
        expected(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a point name, PARLEL, LEFT or RIGHT"));
    }
}

void Parser::tangentCircle(Definition& d)
{
    d.modifiers.push_back(leftRight());
    comma();
    word("TANTO");
    comma();
    d.refs.push_back(ref(Kind::Circle, TAIWA_TRANSLATE_NOOP("taiwa::msg", "a circle name")));
}

void Parser::circle(Definition& d)
{
    if (accept("CENTER")) {  // CIRCLE/CENTER, P1, RADIUS, 5
        d.method = Method::CircleCenterRadius;
        comma();
        d.refs.push_back(ref(Kind::Point, TAIWA_TRANSLATE_NOOP("taiwa::msg", "a point name")));
        radius(d);
    } else if (atName()) {  // CIRCLE/P1, P2, P3
        d.method = Method::CircleThreePoints;
        d.refs.push_back(ref(Kind::Point, TAIWA_TRANSLATE_NOOP("taiwa::msg", "a point name")));
        comma();
        d.refs.push_back(ref(Kind::Point, TAIWA_TRANSLATE_NOOP("taiwa::msg", "a point name")));
        comma();
        d.refs.push_back(ref(Kind::Point, TAIWA_TRANSLATE_NOOP("taiwa::msg", "a point name")));
    } else if (const auto m = atModifier(); m && isXY(*m)) {
        d.modifiers.push_back(modifier(true, kXY));
        comma();
        d.refs.push_back(ref(Kind::Line, TAIWA_TRANSLATE_NOOP("taiwa::msg", "a line name")));
        comma();
        d.modifiers.push_back(modifier(true, kXY));
        comma();
        if (const auto m3 = atModifier(); m3 && (*m3 == Modifier::Out || *m3 == Modifier::In)) {
            d.method = Method::CircleLineCircle;  // CIRCLE/XLARGE, L1, YLARGE, OUT, C1, RADIUS, 5
            d.modifiers.push_back(*m3);
            advance();
            comma();
            d.refs.push_back(ref(Kind::Circle, TAIWA_TRANSLATE_NOOP("taiwa::msg", "a circle name")));
        } else if (atName()) {
            d.method = Method::CircleTwoLines;  // CIRCLE/XLARGE, L1, YSMALL, L2, RADIUS, 5
            d.refs.push_back(ref(Kind::Line, TAIWA_TRANSLATE_NOOP("taiwa::msg", "a line name")));
        } else {
            expected(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a line name, OUT or IN"));
        }
        radius(d);
    } else {
        expected(TAIWA_TRANSLATE_NOOP("taiwa::msg", "CENTER, a point name or XLARGE/XSMALL/YLARGE/YSMALL"));
    }
}

void Parser::radius(Definition& d)
{
    comma();
    word("RADIUS");
    comma();
    d.numbers.push_back(number(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a number (the radius)"), TAIWA_TRANSLATE_NOOP("taiwa::msg", "the radius")));
}

// The kind of an element already defined, or a refusal naming it.
Kind Parser::definedKind() const
{
    if (!atName()) return Kind::Point;  // not reached: callers check atName()
    const auto it = defined_.find(cur_.text);
    if (it == defined_.end())
        fail(cur_, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "in {}, {} is not defined: an element must be defined before it is used"), name_, cur_.text));
    return it->second.kind;
}

// CONTOUR/[P1,] step, step... [, P2] with step = [XLARGE,] [CLW|CCLW,] NAME [, ROUND|CHAMF, value].
void Parser::contour(Definition& d)
{
    d.method = Method::Contour;
    ContourText& c = d.contour;
    std::vector<Kind> kinds;         // of each step's element
    std::optional<Token> firstMod;   // the first step's modifier (a closed contour's closing junction)
    std::optional<Token> lastCorner; // the last step's ROUND or CHAMF
    if (atName() && definedKind() == Kind::Point) {
        c.start = cur_.text;
        c.startAt = placeOf(cur_);
        d.refs.push_back(c.start);
        advance();
        comma();
    }
    for (;;) {
        ContourStep s;
        std::optional<Token> modTok;
        std::optional<Token> turnTok;
        if (const auto m = atModifier(); m && isXY(*m)) {
            modTok = cur_;
            s.junction = *m;
            advance();
            comma();
        }
        if (atWord("CLW") || atWord("CCLW")) {
            turnTok = cur_;
            s.turn = atWord("CLW") ? Turn::Clockwise : Turn::CounterClockwise;
            advance();
            comma();
        }
        if (!atName())
            expected(turnTok  ? TAIWA_TRANSLATE_NOOP("taiwa::msg", TAIWA_TRANSLATE_NOOP("taiwa::msg", "a circle name"))
                     : modTok ? TAIWA_TRANSLATE_NOOP("taiwa::msg", "a line or circle name, CLW or CCLW")
                              : TAIWA_TRANSLATE_NOOP("taiwa::msg", "an element name, XLARGE/XSMALL/YLARGE/YSMALL, CLW or CCLW"));
        const Kind k = definedKind();
        if (k == Kind::Point && !c.steps.empty() && !modTok && !turnTok) {  // the end of an open contour
            if (c.closed())
                fail(cur_, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "in {}, {} ends the contour but no point starts it: an open contour runs from a point to a point"),
                                       name_, cur_.text));
            if (lastCorner)
                fail(*lastCorner, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "in {}, {} after {} is not between two elements: the contour ends at {}"),
                                              name_, lastCorner->text, c.steps.back().element, cur_.text));
            c.end = cur_.text;
            c.endAt = placeOf(cur_);
            d.refs.push_back(c.end);
            advance();
            if (cur_.tok == Tok::Comma)
                fail(prev_, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "in {}, {} is a point: only the first and the last item of a contour may be points"),
                                        name_, c.end));
            return;
        }
        if (k != Kind::Line && k != Kind::Circle)
            fail(cur_, turnTok ? fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "in {}, {} is {} where a circle is needed"), name_, cur_.text, noun(k))
                               : fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "in {}, {} is {} where a line or a circle is needed"), name_, cur_.text,
                                             noun(k)));
        if (k == Kind::Circle && !turnTok)
            fail(cur_, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "in {}, {} is a circle: write CLW or CCLW before it"), name_, cur_.text));
        if (k == Kind::Line && turnTok)
            fail(*turnTok, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "in {}, {} is a line: no {} before it (CLW and CCLW are for circles)"), name_,
                                       cur_.text, turnTok->text));
        if (!c.steps.empty() && c.steps.back().element == cur_.text)
            fail(cur_, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "in {}, {} follows itself: the same element twice in a row"), name_, cur_.text));
        if (modTok && c.steps.empty() && !c.closed())
            fail(*modTok, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "in {}, {} starts at {}: no {} before it"), name_, cur_.text, c.start,
                                      modTok->text));
        if (modTok && !c.steps.empty() && k == Kind::Line && kinds.back() == Kind::Line)
            fail(*modTok, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "in {}, two lines meet once: no {} before {}"), name_, modTok->text, cur_.text));
        if (c.steps.empty()) firstMod = modTok;
        s.element = cur_.text;
        s.at = placeOf(cur_);
        d.refs.push_back(s.element);
        kinds.push_back(k);
        advance();
        lastCorner.reset();
        bool more = false;
        if (cur_.tok == Tok::Comma) {
            advance();
            more = true;
            if (atWord("ROUND") || atWord("CHAMF")) {
                lastCorner = cur_;
                const bool round = atWord("ROUND");
                s.corner = round ? CornerKind::Round : CornerKind::Chamfer;
                advance();
                comma();
                s.valueAt = placeOf(cur_);
                s.value = number(round ? TAIWA_TRANSLATE_NOOP("taiwa::msg", "a number (the radius)") : TAIWA_TRANSLATE_NOOP("taiwa::msg", "a number (the chamfer)"),
                                 round ? TAIWA_TRANSLATE_NOOP("taiwa::msg", "the radius") : TAIWA_TRANSLATE_NOOP("taiwa::msg", "the chamfer"));
                more = cur_.tok == Tok::Comma;
                if (more) advance();
            }
        }
        c.steps.push_back(std::move(s));
        if (!more) break;
    }
    if (!c.closed())
        fail(cur_, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "in {}, the contour starts at {} and needs a point at its end, on {}"), name_,
                               c.start, c.steps.back().element));
    const ContourStep& first = c.steps.front();
    if (c.steps.size() == 1) {
        if (kinds.front() == Kind::Line)
            failAt(first.at, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "in {}, a closed contour needs two elements or more, or a single circle"), name_));
        if (firstMod)
            fail(*firstMod, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "in {}, {} alone is a full circle: no {} before it"), name_,
                                        first.element, firstMod->text));
        if (lastCorner)
            fail(*lastCorner, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "in {}, {} alone is a full circle: no {} on it"), name_,
                                          first.element, lastCorner->text));
        return;
    }
    if (c.steps.back().element == first.element)
        failAt(c.steps.back().at,
               fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "in {}, {} follows itself: the same element twice in a row (the last element joins the first)"),
                           name_, first.element));
    if (firstMod && kinds.front() == Kind::Line && kinds.back() == Kind::Line)
        fail(*firstMod, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "in {}, two lines meet once: no {} before {}"), name_, firstMod->text, first.element));
}

}  // namespace taiwa::figure::text
