// What a module's form shows, described without any widget: one FormField
// per input (key, label, the checks' field names, its help line and drawing
// symbol, how to read and write the value on the module input). The station
// builds its forms and undo commands from these. A module's texts are its
// description file's (modules/module_text.h), its reading and writing
// bound by the makers below (modules/form_binding.h); labels and help lines
// are source texts of the translation (context "taiwa::ui::FieldSpec").
#pragma once

#include "model/geometry.h"
#include "model/module.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace taiwa {

// ContourName: the name of one contour of the job's figure ("K1");
// ContourNames: a list of them, typed separated by commas or blanks
// ("K2, K3"); Points: points in the job's length unit, "10, 20; 60, 20"
// (AREA's drawn passes). All three are text (getText/setText), not numbers.
enum class FormFieldKind { Number, OptionalNumber, Code, ContourName, ContourNames, Points };

struct FormField {
    std::string key;                      // widget objectName suffix: "P1.x", "depth", "U"
    std::string label;                    // "T (depth)"
    std::string placeholder;              // OptionalNumber, a text: what an empty field means
    std::vector<std::string> diagFields;  // check field names shown on this widget
    FormFieldKind kind = FormFieldKind::Number;
    std::vector<std::pair<int, std::string>> codes;  // Code: value and its meaning
    std::function<std::optional<double>(const ModuleInput&)> get;
    std::function<void(ModuleInput&, std::optional<double>)> set;
    // ContourName, ContourNames: the value as the form shows it ("K2, K3")
    // and set from what is typed (get/set then read nothing and set nothing).
    std::function<std::string(const ModuleInput&)> getText;
    std::function<void(ModuleInput&, const std::string&)> setText;
    bool isText() const
    {
        return kind == FormFieldKind::ContourName || kind == FormFieldKind::ContourNames || kind == FormFieldKind::Points;
    }
    // What the value is, in one line of plain words (source text, context
    // "taiwa::ui::FieldSpec"), and the id of its symbol in the module's
    // drawing ("sym-P1"; empty: none), highlighted while the field is typed in.
    std::string help;
    std::string symbol;
    // Number fields that hold a count: the form refuses a fraction instead
    // of rounding what was typed.
    bool whole = false;
};

namespace form {

// A number of module T read and written by two functions.
template <class T, class Get, class Set>
FormField number(std::string key, std::string label, std::vector<std::string> diag, Get get, Set set)
{
    FormField f;
    f.key = std::move(key);
    f.label = std::move(label);
    f.diagFields = std::move(diag);
    f.get = [get](const ModuleInput& m) -> std::optional<double> {
        if (const T* v = m.getIf<T>()) return get(*v);
        return std::nullopt;
    };
    f.set = [set](ModuleInput& m, std::optional<double> v) {
        if (T* p = m.getIf<T>(); p && v) set(*p, *v);
    };
    return f;
}

// A number member of module T.
template <class T>
FormField member(std::string key, std::string label, std::vector<std::string> diag, double T::*m)
{
    return number<T>(std::move(key), std::move(label), std::move(diag), [m](const T& t) { return t.*m; },
                     [m](T& t, double v) { t.*m = v; });
}

// An optional number member of module T: empty means `placeholder` says
// what (the technology's value, "same as θ1", "not touched").
template <class T>
FormField optionalMember(std::string key, std::string label, std::string placeholder, std::vector<std::string> diag,
                         std::optional<double> T::*m)
{
    FormField f;
    f.key = std::move(key);
    f.label = std::move(label);
    f.placeholder = std::move(placeholder);
    f.diagFields = std::move(diag);
    f.kind = FormFieldKind::OptionalNumber;
    f.get = [m](const ModuleInput& in) -> std::optional<double> {
        if (const T* v = in.getIf<T>()) return v->*m;
        return std::nullopt;
    };
    f.set = [m](ModuleInput& in, std::optional<double> v) {
        if (T* p = in.getIf<T>()) p->*m = v;
    };
    return f;
}
// An int member of module T: a count (`kind` Number, the form refuses a
// fraction) or a code (`kind` Code, offering `codes`, each value with its
// meaning, which the form puts after the code and translates in the core
// texts' context, ui/core_texts.cpp).
template <class T>
FormField intMember(std::string key, std::string label, int T::*m, FormFieldKind kind = FormFieldKind::Number,
                    std::vector<std::pair<int, std::string>> codes = {})
{
    FormField f = number<T>(
        key, std::move(label), {key}, [m](const T& t) { return static_cast<double>(t.*m); },
        [m](T& t, double v) { t.*m = static_cast<int>(std::lround(std::clamp(v, -1e6, 1e6))); });
    f.kind = kind;
    f.whole = kind == FormFieldKind::Number;
    f.codes = std::move(codes);
    return f;
}
// The names typed in a list field: separated by commas or blanks, empty
// pieces dropped ("K2, K3" and "K2 K3" alike).
inline std::vector<std::string> splitNames(std::string_view text)
{
    std::vector<std::string> names;
    std::string name;
    for (const char c : text) {
        if (c == ',' || c == ' ' || c == '\t' || c == '\n' || c == '\r') {
            if (!name.empty()) names.push_back(std::move(name));
            name.clear();
        } else {
            name += c;
        }
    }
    if (!name.empty()) names.push_back(std::move(name));
    return names;
}
inline std::string joinNames(const std::vector<std::string>& names)
{
    std::string text;
    for (const std::string& n : names) text += (text.empty() ? "" : ", ") + n;
    return text;
}

namespace detail {
inline FormField textField(std::string key, std::string label, std::vector<std::string> diag, FormFieldKind kind)
{
    FormField f;
    f.key = std::move(key);
    f.label = std::move(label);
    f.diagFields = std::move(diag);
    f.kind = kind;
    f.get = [](const ModuleInput&) -> std::optional<double> { return std::nullopt; };
    f.set = [](ModuleInput&, std::optional<double>) {};
    return f;
}
}  // namespace detail

// The name of one contour of the job's figure: a string of module T, reached
// by `m` (a member pointer, or a function of T& returning the string's
// reference); blanks around it dropped.
template <class T, class Access>
FormField contourName(std::string key, std::string label, std::vector<std::string> diag, Access m)
{
    FormField f = detail::textField(std::move(key), std::move(label), std::move(diag), FormFieldKind::ContourName);
    f.getText = [m](const ModuleInput& in) -> std::string {
        if (const T* v = in.getIf<T>()) return std::invoke(m, *v);
        return {};
    };
    f.setText = [m](ModuleInput& in, const std::string& text) {
        if (T* p = in.getIf<T>()) {
            const auto first = text.find_first_not_of(" \t");
            std::invoke(m, *p) =
                first == std::string::npos ? std::string() : text.substr(first, text.find_last_not_of(" \t") + 1 - first);
        }
    };
    return f;
}

// A list of contour names of module T (reached as contourName's), shown as "K2, K3".
template <class T, class Access>
FormField contourNames(std::string key, std::string label, std::vector<std::string> diag, Access m)
{
    FormField f = detail::textField(std::move(key), std::move(label), std::move(diag), FormFieldKind::ContourNames);
    f.getText = [m](const ModuleInput& in) -> std::string {
        if (const T* v = in.getIf<T>()) return joinNames(std::invoke(m, *v));
        return {};
    };
    f.setText = [m](ModuleInput& in, const std::string& text) {
        if (T* p = in.getIf<T>()) std::invoke(m, *p) = splitNames(text);
    };
    return f;
}

// Points of module T shown and typed as text by `format` and `parse`; what
// does not parse is kept in the member `bad` (for the check to refuse) and
// the points stay as they were.
template <class T, class Format, class Parse>
FormField points(std::string key, std::string label, std::vector<std::string> diag, std::vector<Point2> T::*m,
                 std::string T::*bad, Format format, Parse parse)
{
    FormField f = detail::textField(std::move(key), std::move(label), std::move(diag), FormFieldKind::Points);
    f.getText = [m, bad, format](const ModuleInput& in) -> std::string {
        if (const T* v = in.getIf<T>()) return (v->*bad).empty() ? format(v->*m) : v->*bad;
        return {};
    };
    f.setText = [m, bad, parse](ModuleInput& in, const std::string& text) {
        if (T* p = in.getIf<T>()) {
            if (const auto read = parse(text)) {
                p->*m = *read;
                (p->*bad).clear();
            } else {
                p->*bad = text;
            }
        }
    };
    return f;
}

}  // namespace form

}  // namespace taiwa
