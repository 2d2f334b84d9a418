// Typed, diagnosing access to the fields of a job document (json_fields.h).
#include "io/json_fields.h"
#include "model/translate_noop.h"

#include "io/job_messages.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace taiwa::io {

using nlohmann::json;

ObjectFields::ObjectFields(const json& object, Place place, DiagnosticSink& sink)
    : object_(object), place_(std::move(place)), sink_(sink)
{
}

const json* ObjectFields::find(const char* key) const
{
    const auto it = object_.find(key);
    return it == object_.end() ? nullptr : &*it;
}

void ObjectFields::error(const std::string& field, const std::string& message) const
{
    sink_.add({Severity::Error, place_.unit, place_.module, path(field), message});
}

std::optional<double> ObjectFields::numberValue(const json& v, const std::string& field) const
{
    if (!v.is_number()) {
        error(field, msg::io::wrongType(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a number"), v));
        return std::nullopt;
    }
    return v.get<double>();
}

std::optional<int> ObjectFields::wholeValue(const json& v, const std::string& field) const
{
    if (v.is_number_integer() || v.is_number_unsigned()) {
        if (v.is_number_unsigned() ? v.get<std::uint64_t>() <= std::uint64_t{std::numeric_limits<int>::max()}
                                   : (v.get<std::int64_t>() >= std::numeric_limits<int>::min()
                                      && v.get<std::int64_t>() <= std::numeric_limits<int>::max()))
            return static_cast<int>(v.get<std::int64_t>());
        error(field, msg::io::wholeOutOfRange(v));
        return std::nullopt;
    }
    if (v.is_number_float()) {
        const double d = v.get<double>();
        if (d != std::floor(d)) error(field, msg::io::notWhole(v));
        else if (d < std::numeric_limits<int>::min() || d > std::numeric_limits<int>::max())
            error(field, msg::io::wholeOutOfRange(v));
        else return static_cast<int>(d);
        return std::nullopt;
    }
    error(field, msg::io::wrongType(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a whole number"), v));
    return std::nullopt;
}

namespace {

// How one value is read and refused (ObjectFields::numberValue, wholeValue, point).
template <class T>
using ValueReader = std::optional<T> (ObjectFields::*)(const json&, const std::string&) const;

// A required field's value, read by `read`; missing: refused as not `what`,
// and nothing.
template <class T>
std::optional<T> required(const ObjectFields& o, const char* key, const char* what, ValueReader<T> read)
{
    if (const json* v = o.find(key)) return (o.*read)(*v, key);
    o.error(key, msg::io::missing(what));
    return std::nullopt;
}

// A field that may be missing, read by `read`: `fallback` when it is
// missing or refused.
template <class T>
T orFallback(const ObjectFields& o, const char* key, T fallback, ValueReader<T> read)
{
    const json* v = o.find(key);
    return v ? (o.*read)(*v, key).value_or(fallback) : fallback;
}

}  // namespace

std::optional<double> ObjectFields::number(const char* key) const
{
    return required<double>(*this, key, TAIWA_TRANSLATE_NOOP("taiwa::msg", "a number"), &ObjectFields::numberValue);
}

double ObjectFields::number(const char* key, double fallback) const
{
    return orFallback<double>(*this, key, fallback, &ObjectFields::numberValue);
}

std::optional<double> ObjectFields::optionalNumber(const char* key) const
{
    const json* v = find(key);
    return v ? numberValue(*v, key) : std::nullopt;
}

std::optional<int> ObjectFields::whole(const char* key) const
{
    return required<int>(*this, key, TAIWA_TRANSLATE_NOOP("taiwa::msg", "a whole number"), &ObjectFields::wholeValue);
}

int ObjectFields::whole(const char* key, int fallback) const
{
    return orFallback<int>(*this, key, fallback, &ObjectFields::wholeValue);
}

std::optional<std::string> ObjectFields::string(const char* key) const
{
    const json* v = find(key);
    if (!v)
        error(key, msg::io::missing(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a string")));
    else if (!v->is_string())
        error(key, msg::io::wrongType(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a string"), *v));
    else return v->get<std::string>();
    return std::nullopt;
}

std::string ObjectFields::string(const char* key, const std::string& fallback) const
{
    return find(key) ? string(key).value_or(fallback) : fallback;
}

std::optional<std::size_t> ObjectFields::choice(const char* key, const std::vector<std::string>& allowed) const
{
    const json* v = find(key);
    if (!v) {
        error(key, msg::io::missing(msg::io::oneOf(allowed)));
        return std::nullopt;
    }
    if (v->is_string()) {
        const auto it = std::find(allowed.begin(), allowed.end(), v->get_ref<const std::string&>());
        if (it != allowed.end()) return static_cast<std::size_t>(it - allowed.begin());
    }
    error(key, msg::io::notOneOf(allowed, *v));
    return std::nullopt;
}

std::optional<Point2> ObjectFields::point(const json& v, const std::string& field) const
{
    if (!v.is_array() || v.size() != 2) {
        error(field, msg::io::notAPoint(v));
        return std::nullopt;
    }
    const auto x = numberValue(v[0], field + "[0]");
    const auto y = numberValue(v[1], field + "[1]");
    if (!x || !y) return std::nullopt;
    return Point2{*x, *y};
}

std::optional<Point2> ObjectFields::point(const char* key) const
{
    return required<Point2>(*this, key, TAIWA_TRANSLATE_NOOP("taiwa::msg", "a point [x, y]"), &ObjectFields::point);
}

std::map<std::string, int> ObjectFields::wholeMap(const char* key) const
{
    std::map<std::string, int> out;
    const json* v = find(key);
    if (!v) return out;
    if (!v->is_object()) {
        error(key, msg::io::wrongType(TAIWA_TRANSLATE_NOOP("taiwa::msg", "an object"), *v));
        return out;
    }
    for (const auto& [name, value] : v->items()) {
        if (const auto id = wholeValue(value, std::string(key) + "." + msg::io::fieldKey(name))) out[name] = *id;
    }
    return out;
}

void ObjectFields::rejectUnknown(const std::string& owner, const std::vector<std::string>& known) const
{
    for (const auto& [key, value] : object_.items()) {
        if (std::find(known.begin(), known.end(), key) == known.end()) error(msg::io::fieldKey(key), msg::io::unknownField(owner, known));
    }
}

}  // namespace taiwa::io
