// Files on disk for the job reader and every export: reading a text file
// with its size checked before it is read into memory, and writing any text
// atomically (temporary file in the same folder, fsync, rename).
#pragma once

#include "model/diagnostic.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace taiwa {

namespace io {

struct TextReadResult {
    std::optional<std::string> text;  // present when the file was read whole
    Diagnostics diagnostics;          // why not: one diagnostic about the file as a whole
};

// A regular file of at most maxBytes, read whole; anything else refused.
TextReadResult readTextFile(const std::string& path, std::size_t maxBytes);

}  // namespace io

// Writes text to path atomically: a temporary file in the same folder, then
// rename. Returns an error message, or nothing on success.
std::optional<std::string> writeFileAtomically(const std::string& path, std::string_view text);

}  // namespace taiwa
