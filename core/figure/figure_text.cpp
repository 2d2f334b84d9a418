// The figure language's lexer, recursive-descent parser and writer
// (figure_text.h). The parser also checks what text alone can check: names
// defined once and before use, each argument of the kind its place needs,
// positive radii and distances; for contours, a direction before every circle,
// modifiers only where two elements may meet twice, corners only between two
// elements. Geometry is figure_eval.cpp's and figure_contour.cpp's.
#include "figure/figure_text.h"

#include "model/translate_noop.h"

#include <fmt/format.h>

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <system_error>

namespace taiwa::figure {

Kind kindOf(Method m)
{
    switch (m) {
    case Method::PointXY:
    case Method::PointIntof:
    case Method::PointCenter: return Kind::Point;
    case Method::LineTwoPoints:
    case Method::LineAtAngle:
    case Method::LineParallel:
    case Method::LinePointTangent:
    case Method::LineTwoCircles: return Kind::Line;
    case Method::CircleCenterRadius:
    case Method::CircleThreePoints:
    case Method::CircleTwoLines:
    case Method::CircleLineCircle: return Kind::Circle;
    case Method::Contour: return Kind::Contour;
    }
    throw std::logic_error("figure: unknown method");
}

const char* keyword(Kind k)
{
    switch (k) {
    case Kind::Point: return "POINT";
    case Kind::Line: return "LINE";
    case Kind::Circle: return "CIRCLE";
    case Kind::Contour: return "CONTOUR";
    }
    throw std::logic_error("figure: unknown kind");
}

const char* noun(Kind k)
{
    switch (k) {
    case Kind::Point: return TAIWA_TRANSLATE_NOOP("taiwa::msg", "a point");
    case Kind::Line: return TAIWA_TRANSLATE_NOOP("taiwa::msg", "a line");
    case Kind::Circle: return TAIWA_TRANSLATE_NOOP("taiwa::msg", "a circle");
    case Kind::Contour: return TAIWA_TRANSLATE_NOOP("taiwa::msg", "a contour");
    }
    throw std::logic_error("figure: unknown kind");
}

const char* keyword(Modifier m)
{
    switch (m) {
    case Modifier::XLarge: return "XLARGE";
    case Modifier::XSmall: return "XSMALL";
    case Modifier::YLarge: return "YLARGE";
    case Modifier::YSmall: return "YSMALL";
    case Modifier::Left: return "LEFT";
    case Modifier::Right: return "RIGHT";
    case Modifier::Out: return "OUT";
    case Modifier::In: return "IN";
    }
    throw std::logic_error("figure: unknown modifier");
}

std::string FigureError::text() const
{
    return std::to_string(line) + ":" + std::to_string(column) + ": " + message;
}

namespace {

// ---------------------------------------------------------------- lexer

enum class Tok { Word, Number, Comma, Equals, Slash, EndOfLine, EndOfText, Bad };

struct Token {
    Tok tok = Tok::EndOfText;
    std::string text;  // as written (a word upper-cased)
    double value = 0;  // a number's value
    int line = 1;
    int column = 1;
};

bool isLetter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }
bool isDigit(char c) { return c >= '0' && c <= '9'; }

// The text of a byte that is not printable ASCII, so that messages stay one
// line of valid UTF-8 whatever the input.
std::string printable(std::string_view s)
{
    std::string out;
    for (const char ch : s) {
        const auto u = static_cast<unsigned char>(ch);
        if (u >= 0x20 && u < 0x7f) {
            out += ch;
        } else {
            std::array<char, 8> buf{};
            std::snprintf(buf.data(), buf.size(), "\\x%02X", static_cast<unsigned>(u));
            out += buf.data();
        }
    }
    return out;
}

class Lexer {
public:
    explicit Lexer(std::string_view text) : s_(text) {}

    Token next()
    {
        skipBlanksAndComments();
        Token t;
        t.line = line_;
        t.column = static_cast<int>(i_ - lineStart_) + 1;
        if (i_ >= s_.size()) return t;
        const char c = s_[i_];
        if (c == '\n') {
            t.tok = Tok::EndOfLine;
            ++i_;
            ++line_;
            lineStart_ = i_;
            return t;
        }
        if (isLetter(c)) {
            t.tok = Tok::Word;
            while (i_ < s_.size() && (isLetter(s_[i_]) || isDigit(s_[i_]))) {
                const char w = s_[i_++];
                t.text += (w >= 'a' && w <= 'z') ? static_cast<char>(w - 'a' + 'A') : w;
            }
            return t;
        }
        const bool sign = c == '+' || c == '-';
        const std::size_t body = i_ + (sign ? 1 : 0);
        const bool startsNumber =
            body < s_.size() &&
            (isDigit(s_[body]) || (s_[body] == '.' && body + 1 < s_.size() && isDigit(s_[body + 1])));
        if (startsNumber) return number(t, sign);
        ++i_;
        t.text = std::string(1, c);
        t.tok = c == ',' ? Tok::Comma : c == '=' ? Tok::Equals : c == '/' ? Tok::Slash : Tok::Bad;
        return t;
    }

private:
    void skipBlanksAndComments()
    {
        while (i_ < s_.size()) {
            const char c = s_[i_];
            if (c == ' ' || c == '\t' || c == '\r') {
                ++i_;
            } else if (c == '$' && i_ + 1 < s_.size() && s_[i_ + 1] == '$') {
                while (i_ < s_.size() && s_[i_] != '\n') ++i_;  // $$ comment to the end of the line
            } else {
                return;
            }
        }
    }

    // APT numbers: an optional sign, digits with an optional decimal point
    // (`10`, `10.`, `.5`, `-2.25`); no exponent.
    Token number(Token t, bool sign)
    {
        const std::size_t start = i_;
        const bool negative = sign && s_[i_] == '-';
        if (sign) ++i_;
        const std::size_t digits = i_;
        while (i_ < s_.size() && isDigit(s_[i_])) ++i_;
        if (i_ < s_.size() && s_[i_] == '.') {
            ++i_;
            while (i_ < s_.size() && isDigit(s_[i_])) ++i_;
        }
        t.tok = Tok::Number;
        t.text = std::string(s_.substr(start, i_ - start));
        double v = 0;
        const auto r = std::from_chars(s_.data() + digits, s_.data() + i_, v, std::chars_format::fixed);
        if (r.ec != std::errc() || r.ptr != s_.data() + i_) v = HUGE_VAL;  // out of range: refused by the parser
        t.value = negative ? -v : v;
        return t;
    }

    std::string_view s_;
    std::size_t i_ = 0;
    std::size_t lineStart_ = 0;
    int line_ = 1;
};

// ---------------------------------------------------------------- parser

const std::map<std::string, Modifier, std::less<>>& modifierWords()
{
    static const std::map<std::string, Modifier, std::less<>> m{
        {"XLARGE", Modifier::XLarge}, {"XSMALL", Modifier::XSmall}, {"YLARGE", Modifier::YLarge},
        {"YSMALL", Modifier::YSmall}, {"LEFT", Modifier::Left},     {"RIGHT", Modifier::Right},
        {"OUT", Modifier::Out},       {"IN", Modifier::In}};
    return m;
}

bool isReserved(std::string_view w)
{
    static const std::array<std::string_view, 15> words{"POINT",  "LINE",   "CIRCLE", "INTOF",   "CENTER",
                                                        "ATANGL", "PARLEL", "TANTO",  "RADIUS",  "ON",
                                                        "CONTOUR", "CLW",   "CCLW",   "ROUND",   "CHAMF"};
    for (const auto r : words)
        if (w == r) return true;
    return modifierWords().count(w) > 0;
}

bool isXY(Modifier m)
{
    return m == Modifier::XLarge || m == Modifier::XSmall || m == Modifier::YLarge || m == Modifier::YSmall;
}

constexpr const char* kXY = TAIWA_TRANSLATE_NOOP("taiwa::msg", "XLARGE, XSMALL, YLARGE or YSMALL");

// Thrown inside the parser only, caught by parseFigure and turned into the
// value it returns: the recursive descent stays readable.
struct Refusal {
    FigureError error;
};

class Parser {
public:
    explicit Parser(std::string_view text) : lex_(text) { advance(); }

    std::vector<Definition> statements()
    {
        std::vector<Definition> out;
        for (;;) {
            while (cur_.tok == Tok::EndOfLine) advance();
            if (cur_.tok == Tok::EndOfText) return out;
            out.push_back(statement());
        }
    }

private:
    struct Defined {
        Kind kind;
        int line;
    };

    void advance()
    {
        prev_ = cur_;
        cur_ = lex_.next();
    }

    static std::string describe(const Token& t)
    {
        switch (t.tok) {
        case Tok::EndOfLine: return TAIWA_TRANSLATE_NOOP("taiwa::msg", "the end of the line");
        case Tok::EndOfText: return TAIWA_TRANSLATE_NOOP("taiwa::msg", "the end of the text");
        case Tok::Bad: return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the character '{}'"), printable(t.text));
        default: {
            std::string s = printable(t.text);
            if (s.size() > 24) s = s.substr(0, 24) + "...";
            return "'" + s + "'";
        }
        }
    }

    std::string after() const
    {
        if (prev_.tok == Tok::Word || prev_.tok == Tok::Number) return "'" + printable(prev_.text) + "'";
        return "'" + prev_.text + "'";
    }

    [[noreturn]] void fail(const Token& at, std::string message) const
    {
        throw Refusal{FigureError{at.line, at.column, std::move(message)}};
    }

    [[noreturn]] static void failAt(const Place& at, std::string message)
    {
        throw Refusal{FigureError{at.line, at.column, std::move(message)}};
    }

    [[noreturn]] void expected(const std::string& what) const
    {
        fail(cur_, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "expected {} after {}, found {}"), what, after(), describe(cur_)));
    }

    bool atWord(std::string_view w) const { return cur_.tok == Tok::Word && cur_.text == w; }

    std::optional<Modifier> atModifier() const
    {
        if (cur_.tok != Tok::Word) return std::nullopt;
        const auto it = modifierWords().find(cur_.text);
        if (it == modifierWords().end()) return std::nullopt;
        return it->second;
    }

    bool atName() const { return cur_.tok == Tok::Word && !isReserved(cur_.text); }

    void comma()
    {
        if (cur_.tok != Tok::Comma) expected("','");
        advance();
    }

    void word(const char* w)
    {
        if (!atWord(w)) expected(w);
        advance();
    }

    Modifier modifier(bool xy, const char* what)
    {
        const auto m = atModifier();
        if (!m || isXY(*m) != xy) expected(what);
        advance();
        return *m;
    }

    Modifier leftRight()
    {
        const auto m = atModifier();
        if (!m || (*m != Modifier::Left && *m != Modifier::Right)) expected(TAIWA_TRANSLATE_NOOP("taiwa::msg", "LEFT or RIGHT"));
        advance();
        return *m;
    }

    // A number; with `quantity` ("the radius") zero and negatives are refused.
    double number(const std::string& what, const char* quantity = nullptr)
    {
        if (cur_.tok != Tok::Number) expected(what);
        const double v = cur_.value;
        if (!(std::abs(v) <= kMaxNumber))
            fail(cur_, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the number {} is out of range (at most 1000000 either way)"), describe(cur_)));
        if (quantity && !(v > 0)) fail(cur_, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} must be greater than 0, found {}"), quantity, describe(cur_)));
        advance();
        return v;
    }

    // A reference to an element defined earlier, of the kind its place needs.
    std::string ref(Kind wanted, const std::string& what)
    {
        if (!atName()) expected(what);
        const auto it = defined_.find(cur_.text);
        if (it == defined_.end())
            fail(cur_, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "in {}, {} is not defined: an element must be defined before it is used"), name_, cur_.text));
        if (it->second.kind != wanted)
            fail(cur_, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "in {}, {} is {} where {} is needed"), name_, cur_.text,
                                   noun(it->second.kind), noun(wanted)));
        std::string n = cur_.text;
        advance();
        return n;
    }

    // Either a line or a circle (an intersection's arguments).
    std::string curve(Kind& kind)
    {
        if (!atName()) expected(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a line or circle name"));
        const auto it = defined_.find(cur_.text);
        if (it == defined_.end())
            fail(cur_, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "in {}, {} is not defined: an element must be defined before it is used"), name_, cur_.text));
        if (it->second.kind != Kind::Line && it->second.kind != Kind::Circle)
            fail(cur_, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "in {}, {} is {} where a line or a circle is needed"), name_, cur_.text,
                                   noun(it->second.kind)));
        kind = it->second.kind;
        std::string n = cur_.text;
        advance();
        return n;
    }

    Definition statement()
    {
        Definition d;
        d.line = cur_.line;
        d.column = cur_.column;
        if (cur_.tok != Tok::Word)
            fail(cur_, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "expected an element name at the start of a statement, found {}"), describe(cur_)));
        if (isReserved(cur_.text))
            fail(cur_, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "'{}' is a word of the language and cannot name an element"), cur_.text));
        d.name = cur_.text;
        name_ = d.name;
        if (const auto it = defined_.find(d.name); it != defined_.end())
            fail(cur_, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} is already defined on line {}"), d.name, it->second.line));
        const Token nameToken = cur_;
        advance();
        if (cur_.tok != Tok::Equals) expected("'='");
        advance();
        if (atWord("POINT")) {
            advance();
            slash();
            point(d);
        } else if (atWord("LINE")) {
            advance();
            slash();
            line(d);
        } else if (atWord("CIRCLE")) {
            advance();
            slash();
            circle(d);
        } else if (atWord("CONTOUR")) {
            advance();
            slash();
            contour(d);
        } else {
            expected(TAIWA_TRANSLATE_NOOP("taiwa::msg", "POINT, LINE, CIRCLE or CONTOUR"));
        }
        if (cur_.tok != Tok::EndOfLine && cur_.tok != Tok::EndOfText) expected(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the end of the statement"));
        defined_[d.name] = Defined{d.kind(), nameToken.line};
        return d;
    }

    void slash()
    {
        if (cur_.tok != Tok::Slash) expected("'/'");
        advance();
    }

    void point(Definition& d)
    {
        if (cur_.tok == Tok::Number) {  // POINT/x, y
            d.method = Method::PointXY;
            d.numbers.push_back(number(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a number")));
            comma();
            d.numbers.push_back(number(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a number (the y coordinate)")));
        } else if (atWord("CENTER")) {  // POINT/CENTER, C1
            advance();
            d.method = Method::PointCenter;
            comma();
            d.refs.push_back(ref(Kind::Circle, TAIWA_TRANSLATE_NOOP("taiwa::msg", "a circle name")));
        } else if (atWord("INTOF") || (atModifier() && isXY(*atModifier()))) {
            d.method = Method::PointIntof;
            Token modTok = cur_;
            if (!atWord("INTOF")) {
                d.modifiers.push_back(modifier(true, kXY));
                comma();
                if (!atWord("INTOF")) expected("INTOF");
            }
            advance();
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

    void line(Definition& d)
    {
        if (atWord("PARLEL")) {  // LINE/PARLEL, L1, XLARGE, 5
            advance();
            d.method = Method::LineParallel;
            comma();
            d.refs.push_back(ref(Kind::Line, TAIWA_TRANSLATE_NOOP("taiwa::msg", "a line name")));
            comma();
            d.modifiers.push_back(modifier(true, kXY));
            comma();
            d.numbers.push_back(number(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a number (the distance)"), TAIWA_TRANSLATE_NOOP("taiwa::msg", "the distance")));
        } else if (const auto m = atModifier(); m && (*m == Modifier::Left || *m == Modifier::Right)) {
            d.method = Method::LineTwoCircles;  // LINE/LEFT, TANTO, C1, RIGHT, TANTO, C2
            d.modifiers.push_back(leftRight());
            comma();
            word("TANTO");
            comma();
            d.refs.push_back(ref(Kind::Circle, TAIWA_TRANSLATE_NOOP("taiwa::msg", "a circle name")));
            comma();
            d.modifiers.push_back(leftRight());
            comma();
            word("TANTO");
            comma();
            d.refs.push_back(ref(Kind::Circle, TAIWA_TRANSLATE_NOOP("taiwa::msg", "a circle name")));
        } else if (atName()) {
            d.refs.push_back(ref(Kind::Point, TAIWA_TRANSLATE_NOOP("taiwa::msg", "a point name")));
            comma();
            if (atWord("ATANGL")) {  // LINE/P1, ATANGL, 30
                advance();
                d.method = Method::LineAtAngle;
                comma();
                d.numbers.push_back(number(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a number (the angle in degrees)")));
            } else if (atModifier()) {  // LINE/P1, LEFT, TANTO, C1
                d.method = Method::LinePointTangent;
                d.modifiers.push_back(leftRight());
                comma();
                word("TANTO");
                comma();
                d.refs.push_back(ref(Kind::Circle, TAIWA_TRANSLATE_NOOP("taiwa::msg", "a circle name")));
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

    void circle(Definition& d)
    {
        if (atWord("CENTER")) {  // CIRCLE/CENTER, P1, RADIUS, 5
            advance();
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

    void radius(Definition& d)
    {
        comma();
        word("RADIUS");
        comma();
        d.numbers.push_back(number(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a number (the radius)"), TAIWA_TRANSLATE_NOOP("taiwa::msg", "the radius")));
    }

    static Place placeOf(const Token& t) { return {t.line, t.column, static_cast<int>(t.text.size())}; }

    // The kind of an element already defined, or a refusal naming it.
    Kind definedKind() const
    {
        if (!atName()) return Kind::Point;  // not reached: callers check atName()
        const auto it = defined_.find(cur_.text);
        if (it == defined_.end())
            fail(cur_, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "in {}, {} is not defined: an element must be defined before it is used"), name_, cur_.text));
        return it->second.kind;
    }

    // CONTOUR/[P1,] step, step... [, P2] with step = [XLARGE,] [CLW|CCLW,] NAME [, ROUND|CHAMF, value].
    void contour(Definition& d)
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

    Lexer lex_;
    Token cur_;
    Token prev_;
    std::string name_;  // the element being defined, for messages
    std::map<std::string, Defined, std::less<>> defined_;
};

}  // namespace

ParseResult parseFigure(std::string_view text)
{
    ParseResult r;
    try {
        Parser p(text);
        r.definitions = p.statements();
    } catch (const Refusal& refusal) {
        r.definitions.clear();
        r.error = refusal.error;
    }
    return r;
}

// ---------------------------------------------------------------- writer

std::string formatNumber(double v)
{
    if (v == 0) return "0";  // also -0
    // Fixed notation (the language has no exponent), shortest that reads back
    // to the same double; |v| <= kMaxNumber keeps it short enough.
    std::array<char, 400> buf{};
    const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), v, std::chars_format::fixed);
    if (r.ec != std::errc()) throw std::logic_error("figure: number too long to write");
    return std::string(buf.data(), r.ptr);
}

std::string writeDefinition(const Definition& d)
{
    // Indexed, not through counting lambdas: the operands of + are not
    // evaluated in a guaranteed order.
    const auto r = [&](std::size_t i) { return d.refs.at(i); };
    const auto m = [&](std::size_t i) { return std::string(keyword(d.modifiers.at(i))); };
    const auto n = [&](std::size_t i) { return formatNumber(d.numbers.at(i)); };
    std::string s = d.name + " = " + keyword(d.kind()) + "/";
    switch (d.method) {
    case Method::PointXY: s += n(0) + ", " + n(1); break;
    case Method::PointIntof:
        if (!d.modifiers.empty()) s += m(0) + ", ";
        s += "INTOF, " + r(0) + ", " + r(1);
        break;
    case Method::PointCenter: s += "CENTER, " + r(0); break;
    case Method::LineTwoPoints: s += r(0) + ", " + r(1); break;
    case Method::LineAtAngle: s += r(0) + ", ATANGL, " + n(0); break;
    case Method::LineParallel: s += "PARLEL, " + r(0) + ", " + m(0) + ", " + n(0); break;
    case Method::LinePointTangent: s += r(0) + ", " + m(0) + ", TANTO, " + r(1); break;
    case Method::LineTwoCircles: s += m(0) + ", TANTO, " + r(0) + ", " + m(1) + ", TANTO, " + r(1); break;
    case Method::CircleCenterRadius: s += "CENTER, " + r(0) + ", RADIUS, " + n(0); break;
    case Method::CircleThreePoints: s += r(0) + ", " + r(1) + ", " + r(2); break;
    case Method::CircleTwoLines: s += m(0) + ", " + r(0) + ", " + m(1) + ", " + r(1) + ", RADIUS, " + n(0); break;
    case Method::CircleLineCircle:
        s += m(0) + ", " + r(0) + ", " + m(1) + ", " + m(2) + ", " + r(1) + ", RADIUS, " + n(0);
        break;
    case Method::Contour: {
        const ContourText& c = d.contour;
        std::string items = c.start.empty() ? "" : c.start + ", ";
        for (const auto& st : c.steps) {
            if (st.junction) items += std::string(keyword(*st.junction)) + ", ";
            if (st.turn != Turn::None) items += st.turn == Turn::Clockwise ? "CLW, " : "CCLW, ";
            items += st.element + ", ";
            if (st.corner != CornerKind::None)
                items += (st.corner == CornerKind::Round ? "ROUND, " : "CHAMF, ") + formatNumber(st.value) + ", ";
        }
        if (!c.end.empty()) items += c.end + ", ";
        s += items.substr(0, items.size() >= 2 ? items.size() - 2 : 0);
        break;
    }
    }
    return s;
}

std::string writeFigure(const std::vector<Definition>& definitions)
{
    std::string s;
    for (const auto& d : definitions) s += writeDefinition(d) + "\n";
    return s;
}

}  // namespace taiwa::figure
