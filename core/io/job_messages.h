// Every message of the job-file reader, in one place (like check/messages.h
// for input processing): sentences naming what was expected and what the file
// holds, quoting at most a short, printable excerpt of anything it contains.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace taiwa::msg::io {

// What a JSON value is, in words: "a string", "a number", "an array", "null", ...
std::string kindOf(const nlohmann::json& v);
// A string of the file, quoted, cut to a readable length, control bytes escaped.
std::string excerpt(std::string_view s);
// A key of the file as part of a field path: as it is when it is a plain
// name, else quoted like excerpt().
std::string fieldKey(std::string_view key);
// "one of \"mm\", \"inch\""
std::string oneOf(const std::vector<std::string>& allowed);

// The file as a whole.
std::string fileEmpty();
std::string fileTooLarge(std::size_t bytes, std::size_t limit);
std::string fileCannotOpen(const std::string& reason);
std::string fileUnreadable(const std::string& reason);
std::string notAFile();
// Positions: byte 1-based as nlohmann counts, line and column 1-based.
std::string notJson(std::size_t byte, std::size_t line, std::size_t column, const std::string& what);
std::string nestedTooDeep(std::size_t byte, std::size_t line, std::size_t column, std::size_t limit);
std::string numberTooLarge(const std::string& token);
std::string notAnObject(const nlohmann::json& root);
std::string formatMissing();
std::string formatWrong(const nlohmann::json& value);
std::string versionNewer(long long version, int supported);
std::string versionUnknown(long long version, int supported);

// Fields.
std::string missing(const std::string& expected);
std::string wrongType(const std::string& expected, const nlohmann::json& found);
std::string notWhole(const nlohmann::json& found);
std::string wholeOutOfRange(const nlohmann::json& found);
std::string unknownField(const std::string& owner, const std::vector<std::string>& known);
std::string notOneOf(const std::vector<std::string>& allowed, const nlohmann::json& found);
std::string unknownModule(const std::string& name, const std::vector<std::string>& known);
std::string unknownStockShape(const std::string& shape, const std::vector<std::string>& known);
std::string cornerCount(std::size_t found);
std::string notAPoint(const nlohmann::json& found);
std::string duplicateKey();

}  // namespace taiwa::msg::io
