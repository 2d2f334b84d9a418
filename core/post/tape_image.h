// The tape image list: the NC tape as a printable listing (line, sequence
// number, block) with a footer giving the block count and the tape's length
// in characters (end-of-block included) and in metres of paper tape at 10
// characters per inch.
#pragma once

#include <cstddef>
#include <string>

namespace taiwa::post {

struct TapeLength {
    std::size_t lines = 0;
    std::size_t blocks = 0;       // lines that are neither comments nor '%'
    std::size_t characters = 0;   // every character punched, one EOB per line
    double metres() const { return static_cast<double>(characters) / 10.0 * 0.0254; }
};

TapeLength measureTape(const std::string& nc);
// The listing's header names the program, the machine and the dialect; the
// N column holds each block's number (N words, or HEIDENHAIN's leading one).
std::string tapeImage(const std::string& nc, const std::string& programName, const std::string& dialect,
                      const std::string& machine = {});

}  // namespace taiwa::post
