// The tape image list (pipeline stage 5): every block with its listing line
// number, then the block count, the characters punched (end-of-block
// included) and the length of paper tape at 10 characters per inch.
#include "post/tape_image.h"

#include <fmt/format.h>

#include <sstream>

namespace taiwa::post {

std::string tapeImage(const std::string& nc, const std::string& programName, const std::string& dialect)
{
    std::string out = fmt::format("TAPE IMAGE LIST   program {}   dialect {}\n", programName, dialect);
    out += std::string(72, '-') + "\n";
    std::istringstream in(nc);
    std::string block;
    int line = 0, blocks = 0;
    std::size_t characters = 0;
    while (std::getline(in, block)) {
        ++line;
        characters += block.size() + 1;  // EOB
        if (!block.empty() && block != "%" && block.front() != '(') ++blocks;
        out += fmt::format("{:6d}  {}\n", line, block);
    }
    out += std::string(72, '-') + "\n";
    const double metres = static_cast<double>(characters) / 10.0 * 0.0254;
    out += fmt::format("blocks {}   lines {}   characters {}   tape length {:.1f} m\n", blocks, line, characters, metres);
    return out;
}

}  // namespace taiwa::post
