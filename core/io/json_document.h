// Parsing the text of a job file into a JSON tree with nlohmann::json, and
// what nlohmann alone would not tell: keys given twice in one object (it
// keeps the last silently) and a broken document's position as a sentence.
#pragma once

#include <nlohmann/json.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace taiwa::io {

// A location in the document: object keys and array indices from the root,
// e.g. {"units", "[2]", "depth"}.
using JsonPath = std::vector<std::string>;
// "units[2].depth"
std::string joinPath(JsonPath::const_iterator begin, JsonPath::const_iterator end);

struct ParsedDocument {
    std::optional<nlohmann::json> root;  // absent when the text is not JSON
    std::string error;                   // why, as a sentence, when absent
    JsonPath errorPath;                  // where, when the text is JSON but a value cannot be held (1e400)
    std::string errorModule;             // the "module" of the unit errorPath is in, when it came before
    std::vector<JsonPath> repeatedKeys;  // every key given a second time in its object
};

// A job nests five deep (job, units, unit, corners, point); deeper documents
// are refused before parsing.
constexpr std::size_t kMaxNesting = 64;

// Never throws.
ParsedDocument parseDocument(std::string_view text);

}  // namespace taiwa::io
