// The probing programs' parameter language evaluated (tape_params.h): a
// recursive descent over the text, one level of precedence a function
// (** over * / MOD over + - over the comparisons over AND OR XOR), angles in
// degrees, the comparisons equal within LinuxCNC's 0.0001.
#include "verify/tape_params.h"

#include "verify/tape_reader_machine.h"

#include <cctype>
#include <cmath>
#include <numbers>

namespace taiwa::verify::tape {

namespace {

std::string upper(std::string_view s)
{
    std::string u(s);
    for (char& c : u) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return u;
}

// One pass over an expression's text; each level reads what it can and
// leaves the position after it.
class Parser {
public:
    Parser(const Params& params, std::string_view text, bool fanuc) : params_(params), s_(text), fanuc_(fanuc) {}

    double whole()
    {
        const double v = logical();
        space();
        if (i_ != s_.size()) refuse("'" + std::string(s_.substr(i_)) + "' after the expression");
        return v;
    }
    // A parameter's name after '#': "<x0>" (LinuxCNC, lower-cased) or digits.
    std::string reference()
    {
        if (i_ < s_.size() && s_[i_] == '<') {
            if (fanuc_) refuse("a named parameter in a FANUC macro");
            const auto close = s_.find('>', i_);
            if (close == std::string_view::npos || close == i_ + 1) refuse("a parameter name with no '>'");
            std::string name(s_.substr(i_, close - i_ + 1));
            for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
            i_ = close + 1;
            return name;
        }
        const std::size_t from = i_;
        while (i_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i_]))) ++i_;
        if (i_ == from || i_ - from > 5) refuse("'#' with no parameter number or name");
        return std::string(s_.substr(from, i_ - from));
    }
    std::size_t at() const { return i_; }
    void space()
    {
        while (i_ < s_.size() && s_[i_] == ' ') ++i_;
    }
    bool take(std::string_view word)
    {
        space();
        if (upper(s_.substr(i_, word.size())) != word) return false;
        // A word of letters ends where its letters do (GT, not GTX).
        const bool letters = std::isalpha(static_cast<unsigned char>(word.front()));
        const std::size_t end = i_ + word.size();
        if (letters && end < s_.size() && std::isalpha(static_cast<unsigned char>(s_[end]))) return false;
        i_ = end;
        return true;
    }
    double bracketed()
    {
        if (!take("[")) refuse("'[' expected");
        const double v = logical();
        if (!take("]")) refuse("']' expected");
        return v;
    }

private:
    double logical()
    {
        double v = relation();
        for (;;) {
            int op = take("AND") ? 0 : take("OR") ? 1 : take("XOR") ? 2 : -1;
            if (op < 0) return v;
            const bool a = v != 0.0, b = relation() != 0.0;
            v = (op == 0 ? a && b : op == 1 ? a || b : a != b) ? 1.0 : 0.0;
        }
    }
    double relation()
    {
        double v = sum();
        static constexpr const char* kOps[] = {"EQ", "NE", "GT", "GE", "LT", "LE"};
        for (;;) {
            int op = -1;
            for (int k = 0; k < 6 && op < 0; ++k)
                if (take(kOps[k])) op = k;
            if (op < 0) return v;
            const double w = sum();
            const bool equal = std::abs(v - w) < 0.0001;
            const bool r[] = {equal, !equal, v > w && !equal, v > w || equal, v < w && !equal, v < w || equal};
            v = r[op] ? 1.0 : 0.0;
        }
    }
    double sum()
    {
        double v = product();
        for (;;) {
            if (take("+")) v += product();
            else if (take("-")) v -= product();
            else return v;
        }
    }
    double product()
    {
        double v = power();
        for (;;) {
            if (take("**")) refuse("'**' after a product's term");
            if (take("*")) v *= power();
            else if (take("/")) {
                const double w = power();
                if (w == 0.0) refuse("a division by zero");
                v /= w;
            } else if (take("MOD")) {
                const double w = power();
                if (w == 0.0) refuse("MOD by zero");
                v = v - w * std::floor(v / w);
            } else
                return v;
        }
    }
    double power()
    {
        const double v = unary();
        space();
        if (s_.substr(i_, 2) != "**") return v;
        i_ += 2;
        return std::pow(v, power());
    }
    double unary()
    {
        if (take("-")) return -unary();
        if (take("+")) return unary();
        return primary();
    }
    double primary()
    {
        space();
        if (i_ >= s_.size()) refuse("an expression ends where a value is expected");
        const char c = s_[i_];
        if (c == '[') return bracketed();
        if (c == '#') {
            ++i_;
            return params_.get(reference());
        }
        if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') return number();
        return function();
    }
    double number()
    {
        const std::size_t from = i_;
        while (i_ < s_.size() && (std::isdigit(static_cast<unsigned char>(s_[i_])) || s_[i_] == '.')) ++i_;
        const auto v = decimal(s_.substr(from, i_ - from), false);
        if (!v) refuse("'" + std::string(s_.substr(from, i_ - from)) + "' is not a number");
        return *v;
    }
    double function()
    {
        constexpr double deg = std::numbers::pi / 180.0;
        const auto domain = [](bool ok, const char* what) {
            if (!ok) refuse(std::string(what) + " of a value outside its domain");
        };
        if (take("ATAN")) {
            const double y = bracketed();
            if (!take("/")) refuse("ATAN[y]/[x] expected");
            return std::atan2(y, bracketed()) / deg;
        }
        static constexpr const char* kNames[] = {"ABS", "SQRT", "SIN", "COS", "TAN", "ASIN", "ACOS", "EXP", "LN", "FIX", "FUP", "ROUND"};
        for (const char* name : kNames) {
            if (!take(name)) continue;
            const double v = bracketed();
            const std::string f = name;
            if (f == "ABS") return std::abs(v);
            if (f == "SQRT") return domain(v >= 0.0, "SQRT"), std::sqrt(v);
            if (f == "SIN") return std::sin(v * deg);
            if (f == "COS") return std::cos(v * deg);
            if (f == "TAN") return domain(std::abs(std::cos(v * deg)) > 1e-12, "TAN"), std::tan(v * deg);
            if (f == "ASIN") return domain(std::abs(v) <= 1.0, "ASIN"), std::asin(v) / deg;
            if (f == "ACOS") return domain(std::abs(v) <= 1.0, "ACOS"), std::acos(v) / deg;
            if (f == "EXP") return std::exp(v);
            if (f == "LN") return domain(v > 0.0, "LN"), std::log(v);
            if (f == "FIX") return std::floor(v);
            if (f == "FUP") return std::ceil(v);
            return std::round(v);
        }
        refuse("'" + std::string(s_.substr(i_)) + "' is not understood in an expression");
    }

    const Params& params_;
    std::string_view s_;
    bool fanuc_;
    std::size_t i_ = 0;
};

}  // namespace

double Params::get(const std::string& name) const
{
    const auto it = values_.find(name);
    if (it == values_.end()) refuse("#" + name + " is read before it is set");
    return it->second;
}

double Params::evaluate(std::string_view text) const { return Parser(*this, text, fanuc_).whole(); }

std::pair<std::string, double> Params::assignment(std::string_view block) const
{
    const std::string b = trim(std::string(block));
    if (b.empty() || b.front() != '#') return {};
    Parser p(*this, b, fanuc_);
    p.take("#");
    std::string name = p.reference();
    if (!p.take("=")) refuse("an assignment with no '='");
    return {std::move(name), evaluate(std::string_view(b).substr(p.at()))};
}

std::vector<ParamWord> Params::words(std::string_view block) const
{
    std::vector<ParamWord> out;
    std::size_t i = 0;
    while (i < block.size()) {
        if (block[i] == ' ') {
            ++i;
            continue;
        }
        ParamWord w;
        w.letter = static_cast<char>(std::toupper(static_cast<unsigned char>(block[i])));
        if (w.letter < 'A' || w.letter > 'Z') refuse(std::string("'") + block[i] + "' where a word's letter is expected");
        const std::size_t from = ++i;
        if (i < block.size() && block[i] == '[') {
            int depth = 0;
            for (; i < block.size(); ++i) {
                depth += block[i] == '[' ? 1 : block[i] == ']' ? -1 : 0;
                if (depth == 0) break;
            }
            if (depth != 0) refuse("a '[' with no ']'");
            ++i;
        } else if (i < block.size() && block[i] == '#') {
            Parser p(*this, block.substr(i + 1), fanuc_);
            p.reference();
            i += 1 + p.at();
        } else {
            if (i < block.size() && (block[i] == '-' || block[i] == '+')) ++i;
            while (i < block.size() && (std::isdigit(static_cast<unsigned char>(block[i])) || block[i] == '.')) ++i;
        }
        w.text = std::string(block.substr(from, i - from));
        if (w.text.empty()) refuse(std::string("'") + w.letter + "' with no value");
        w.computed = w.text.front() == '[' || w.text.front() == '#';
        if (w.computed) w.value = evaluate(w.text);
        else if (const auto v = decimal(w.text, false)) w.value = *v;
        else refuse("'" + std::string(1, w.letter) + w.text + "' is not understood");
        out.push_back(std::move(w));
    }
    return out;
}

}  // namespace taiwa::verify::tape
