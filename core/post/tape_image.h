// The tape image list: the NC tape as a printable listing with line
// numbers, and a footer with the block count and the tape's length.
#pragma once

#include <string>

namespace taiwa::post {

std::string tapeImage(const std::string& nc, const std::string& programName, const std::string& dialect);

}  // namespace taiwa::post
