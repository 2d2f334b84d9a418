// The parameter language of the probing programs (post/probe_program.h),
// evaluated as the control would, strictly: LinuxCNC's named and numbered
// parameters (#<x0>, #5061) and FANUC macro B's variables (#100, #5041),
// expressions in brackets with + - * / MOD **, EQ NE GT GE LT LE, AND OR
// XOR, the functions ABS SQRT SIN COS TAN ASIN ACOS ATAN[a]/[b] EXP LN FIX
// FUP ROUND, and a block's words whose values are expressions ("G38.3
// X[#<x0> - 32]", "G31 X#105 F80."). An unknown word or function, a
// parameter read before it is set, a division by zero or a malformed
// expression is refused (tape::refuse), never guessed. Internal to
// core/verify (the probing programs' reader, tape_reader_probe.cpp).
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace taiwa::verify::tape {

// A word of a block: its letter, its text after the letter as written
// ("38.3", "[#<x0> - 32]", "#105") and its value.
struct ParamWord {
    char letter = 0;
    std::string text;
    double value = 0.0;
    bool computed = false;  // written as a parameter or an expression
};

class Params {
public:
    // FANUC macro B (variables by number only) or LinuxCNC (names too).
    explicit Params(bool fanuc) : fanuc_(fanuc) {}

    // The value of parameter `name` ("5061", "<x0>"); refused when not set.
    double get(const std::string& name) const;
    void set(const std::string& name, double value) { values_[name] = value; }
    bool has(const std::string& name) const { return values_.contains(name); }

    // The value of the expression `text` (a number, a parameter, a
    // bracketed expression, a function): all of it, or refused.
    double evaluate(std::string_view text) const;

    // When `block` (its comments out) is an assignment "#<name> = expr" or
    // "#n = expr": the parameter's name and the value, set after the
    // block's other reads. Empty name: not an assignment.
    std::pair<std::string, double> assignment(std::string_view block) const;

    // The block's words, each value evaluated.
    std::vector<ParamWord> words(std::string_view block) const;

private:
    bool fanuc_;
    std::map<std::string, double> values_;
};

}  // namespace taiwa::verify::tape
