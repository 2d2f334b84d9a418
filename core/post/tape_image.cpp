// The tape image list (pipeline stage 5, see tape_image.h).
#include "post/tape_image.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <string_view>

namespace taiwa::post {

namespace {

// Not blocks: the '%' leader and trailer, comments of their own line in
// parentheses or after ';' (a HEIDENHAIN comment is a numbered block), and
// the continuation lines of a HEIDENHAIN cycle definition (indented).
bool isBlock(std::string_view line)
{
    return !line.empty() && line != "%" && line.front() != '(' && line.front() != ';' && line.front() != ' ';
}

// The length of a block's number at the start of `line`, with the letter
// before it: "N120 G0 ..." (G-code) or "12 L X+5 ..." (Klartext); 0 when
// the line has none. `digits` gets where its digits start.
std::size_t blockNumber(std::string_view line, std::size_t& digits)
{
    digits = line.size() > 1 && line[0] == 'N' && std::isdigit(static_cast<unsigned char>(line[1])) ? 1 : 0;
    if (digits == 0 && (line.empty() || !std::isdigit(static_cast<unsigned char>(line[0])))) return 0;
    std::size_t end = digits;
    while (end < line.size() && std::isdigit(static_cast<unsigned char>(line[end]))) ++end;
    return end;
}

// Calls f(line) for every line of the tape, without its end-of-block.
template <class F>
void forEachLine(const std::string& nc, F f)
{
    std::size_t from = 0;
    while (from < nc.size()) {
        std::size_t eob = nc.find('\n', from);
        if (eob == std::string::npos) eob = nc.size();
        f(std::string_view(nc).substr(from, eob - from));
        from = eob + 1;
    }
}

}  // namespace

TapeLength measureTape(const std::string& nc)
{
    TapeLength t;
    forEachLine(nc, [&](std::string_view line) {
        ++t.lines;
        t.characters += line.size() + 1;
        if (isBlock(line)) ++t.blocks;
    });
    return t;
}

std::string tapeImage(const std::string& nc, const std::string& programName, const std::string& dialect,
                      const std::string& machine)
{
    const std::string rule(72, '-');
    // A printable listing: control characters of the job's name are not printed.
    std::string name;
    for (const char c : programName) name += (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) ? ' ' : c;
    std::string out = fmt::format("TAPE IMAGE LIST   program {}   machine {}   dialect {}\n{}\n{:>7}  {:>6}  BLOCK\n{}\n", name,
                                  machine.empty() ? "-" : machine, dialect, rule, "LINE", "N", rule);
    out.reserve(out.size() + nc.size() + nc.size() / 2);
    // Right-aligned in `width` columns (the line numbers and N words are
    // never wider): appended by hand, fmt per line took most of the time.
    const auto column = [&out](std::string_view text, std::size_t width) {
        if (text.size() < width) out.append(width - text.size(), ' ');
        out += text;
    };
    std::size_t lineNumber = 0;
    forEachLine(nc, [&](std::string_view line) {
        ++lineNumber;
        // The N column: the block's sequence number, its text without it.
        std::string_view n, rest = line;
        std::size_t first = 0;
        if (const std::size_t end = blockNumber(line, first); end > 0) {
            n = line.substr(first, end - first);
            rest = line.substr(std::min(line.size(), end + 1));
        }
        char digits[24];
        const auto [end, ec] = std::to_chars(digits, digits + sizeof digits, lineNumber);
        column({digits, static_cast<std::size_t>(end - digits)}, 7);
        out += "  ";
        column(n, 6);
        out += "  ";
        out += rest;
        out += '\n';
    });
    const TapeLength t = measureTape(nc);
    out += rule + "\n";
    out += fmt::format("blocks {}   lines {}   characters {} (EOB included)   tape length {:.2f} m at 10 characters per inch\n",
                       t.blocks, t.lines, t.characters, t.metres());
    return out;
}

}  // namespace taiwa::post
