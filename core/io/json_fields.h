// Typed access to the fields of a parsed job document for the reader: each
// accessor returns the value or, when the field is missing or of the wrong
// kind, records a diagnostic naming the field's path and returns nothing (or
// the documented default). Nothing here throws.
#pragma once

#include "model/diagnostic.h"
#include "model/geometry.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace taiwa::io {

// Where fields live: the unit (1-based, absent for the job) and its module,
// and the path of the enclosing object ("stock.", "technology.", "" in a unit).
struct Place {
    std::optional<int> unit;
    std::string module;
    std::string prefix;
};

// One JSON object of the document and the place it has in the job.
class ObjectFields {
public:
    ObjectFields(const nlohmann::json& object, Place place, DiagnosticSink& sink);

    const nlohmann::json* find(const char* key) const;
    void error(const std::string& field, const std::string& message) const;
    std::string path(const std::string& field) const { return place_.prefix + field; }
    DiagnosticSink& sink() const { return sink_; }
    // The fields of an object nested in this one ("rows[2]." + key).
    ObjectFields nested(const nlohmann::json& object, const std::string& prefix) const
    {
        return ObjectFields(object, Place{place_.unit, place_.module, place_.prefix + prefix}, sink_);
    }

    std::optional<double> number(const char* key) const;  // required
    double number(const char* key, double fallback) const;
    std::optional<double> optionalNumber(const char* key) const;
    std::optional<int> whole(const char* key) const;  // required
    int whole(const char* key, int fallback) const;
    std::optional<std::string> string(const char* key) const;  // required
    std::string string(const char* key, const std::string& fallback) const;
    // A string from a fixed list; index into `allowed`.
    std::optional<std::size_t> choice(const char* key, const std::vector<std::string>& allowed) const;
    std::optional<Point2> point(const char* key) const;
    std::optional<Point2> point(const nlohmann::json& value, const std::string& field) const;
    // An object of whole numbers (tool pins); empty when absent.
    std::map<std::string, int> wholeMap(const char* key) const;
    // Reports every key not in `known` as an unknown field of `owner`.
    void rejectUnknown(const std::string& owner, const std::vector<std::string>& known) const;

    // One value of an array (reported at `field`, "touches[2]").
    std::optional<double> numberValue(const nlohmann::json& v, const std::string& field) const;
    std::optional<int> wholeValue(const nlohmann::json& v, const std::string& field) const;

private:

    const nlohmann::json& object_;
    Place place_;
    DiagnosticSink& sink_;
};

}  // namespace taiwa::io
