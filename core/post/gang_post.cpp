// The gang-tool lathe's tape (gang_post.h): the lathe post's program, each
// tool change and the end rewritten as the gang change: Z clear, the T
// word, X, then the approach.
#include "post/gang_post.h"

#include "post/dialect.h"
#include "post/lathe_post.h"
#include "post/number_format.h"
#include "post/tape_image.h"
#include "model/turn_path.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <regex>
#include <stdexcept>

namespace taiwa {

namespace {

// A line's sequence number ("N300 ", or none) and the rest.
std::pair<std::string, std::string> splitNumber(const std::string& line)
{
    if (line.size() > 2 && line[0] == 'N' && std::isdigit(static_cast<unsigned char>(line[1]))) {
        std::size_t i = 1;
        while (i < line.size() && std::isdigit(static_cast<unsigned char>(line[i]))) ++i;
        if (i < line.size() && line[i] == ' ') return {line.substr(0, i + 1), line.substr(i + 1)};
    }
    return {"", line};
}

// The value of a word (`X54.`) of a block, outside its comments; none when it has none.
std::optional<double> word(const std::string& body, char letter)
{
    const std::string code = body.substr(0, std::min(body.find('('), body.find(';')));
    for (std::size_t i = 0; i < code.size(); ++i)
        if (code[i] == letter && (i == 0 || code[i - 1] == ' ')) {
            std::size_t used = 0;
            try {
                const double v = std::stod(code.substr(i + 1), &used);
                if (used > 0) return v;
            } catch (const std::exception&) {
                return std::nullopt;
            }
        }
    return std::nullopt;
}

// A block that moves the tool to the X and Z it names: not a dwell, nor a
// cycle's or a spindle limit's words, nor a subroutine's line.
bool movesTo(const std::string& body)
{
    // Comments, tool calls, and a subroutine's lines (LinuxCNC's G71 contour: "o100 sub", its moves indented).
    if (body.empty() || body[0] == '(' || body[0] == ';' || body[0] == 'o' || body[0] == 'T' || body[0] == ' ') return false;
    for (const char* not_ : {"G4 ", "G04 ", "G71", "G70", "G72", "G76", "G50", "CYCLE"})
        if (body.find(not_) != std::string::npos) return false;
    return word(body, 'X') || word(body, 'Z');
}

bool isToolCall(const std::string& body) { return body.size() > 1 && body[0] == 'T' && std::isdigit(static_cast<unsigned char>(body[1])); }

// The turret station a tool call selects: FANUC's T0202 (station, then
// offset), LinuxCNC's T2 M6 G43, SINUMERIK's T2 D1.
int stationOf(const std::string& call)
{
    std::size_t digits = 1;
    while (digits < call.size() && std::isdigit(static_cast<unsigned char>(call[digits]))) ++digits;
    const std::string number = call.substr(1, digits - 1);
    return std::stoi(number.size() == 4 ? number.substr(0, 2) : number);
}

}  // namespace

PartEnvelope pathsEnvelope(const std::vector<Step>& steps)
{
    PartEnvelope e{-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(), 0.0};
    const auto take = [&](turning::ZR p) {
        e.zFront = std::max(e.zFront, p.z);
        e.zBack = std::min(e.zBack, p.z);
        e.radius = std::max(e.radius, std::abs(p.r));
    };
    for (const Step& s : steps)
        if (turnOf(s)) {
            take(turnOf(s)->path.start);
            for (const auto& m : turnOf(s)->path.moves) take(m.end);
        }
    if (e.zFront < e.zBack) e = {};
    return e;
}

PostedProgram postGangTool(const std::vector<Step>& steps, const std::vector<Tool>& library, const GangSlide& slide,
                           const PartEnvelope& part, const PostOptions& options)
{
    const post::Dialect* d = &post::dialectNamed(options.dialect);
    for (const Step& s : steps)
        if (s.tool && !slide.place(s.tool->toolId))
            throw Refusal(
                fmt::format("tools.T{0}: tool {0} has no mounting offset on the gang slide (gangSlide.tools)", s.tool->toolId));
    const PostedProgram posted = postLathe(steps, library, options);

    std::vector<std::string> lines;
    for (std::size_t from = 0; from < posted.nc.size();) {
        const std::size_t to = posted.nc.find('\n', from);
        lines.push_back(posted.nc.substr(from, to - from));
        from = to == std::string::npos ? posted.nc.size() : to + 1;
    }
    // The turret stations the post numbered (T01 …) by library tool, from its header.
    std::map<int, int> toolAt;
    const std::regex header(R"(T(\d+) = (?:library|LIBRARY) T(\d+))");
    for (const auto& l : lines)
        if (std::smatch m; std::regex_search(l, m, header)) toolAt[std::stoi(m[1])] = std::stoi(m[2]);

    // Every tip beyond the front by the clearance, and by the offsets'
    // spread in Z besides (a control moving the slide at the T word).
    double lowest = 0.0, highest = 0.0;
    for (std::size_t k = 0; k < slide.places.size(); ++k) {
        lowest = k ? std::min(lowest, slide.places[k].offset.z) : slide.places[k].offset.z;
        highest = k ? std::max(highest, slide.places[k].offset.z) : slide.places[k].offset.z;
    }
    // Up to the next whole millimetre beyond it (not on the boundary itself).
    const double clearSlide = std::ceil(part.zFront + slide.clearance + (highest - lowest) - lowest + 1e-3);
    const bool inch = options.units == LengthUnit::Inch;
    const auto num = [&](double mm) {
        return post::formatNumber(fromMm(mm, options.units), inch ? d->lengthDecimals.inch : d->lengthDecimals.mm, d->decimalPointAlways);
    };

    const GangPlace none{};       // at the program's start no tool offset is in force: the slide's reference
    const GangPlace* active = &none;
    std::optional<turning::ZR> tip;  // the programmed position (X as a radius) [mm]
    std::optional<turning::ZR> before;  // and before the last motion written (the change point's rapid, replaced)
    PostedProgram out;
    const auto emit = [&](const std::string& line, BlockSource from) {
        out.nc += line + '\n';
        out.lines.push_back(from);
    };
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const auto [n, body] = splitNumber(lines[i]);
        const BlockSource src = i < posted.lines.size() ? posted.lines[i] : BlockSource{};
        const bool end = body == d->programEnd;
        if ((isToolCall(body) || end) && !out.lines.empty()) {
            // The change point's rapid just before: Z clear instead, in the old tool's offset.
            const std::size_t last = out.nc.rfind('\n', out.nc.size() - 2) + 1;
            const auto [pn, pbody] = splitNumber(out.nc.substr(last, out.nc.size() - 1 - last));
            // Z out from where the tip was before the change point's rapid
            // (or stays, when already further): the slide's Z to keep.
            const bool replace = movesTo(pbody);
            const std::optional<turning::ZR> from = replace ? before : tip;
            const double slideZ = from ? std::max(from->z - active->offset.z, clearSlide) : clearSlide;
            const std::string clear = "G0 Z" + num(slideZ + active->offset.z);
            if (replace) {
                out.nc.resize(last);
                out.nc += pn + clear + '\n';
            } else {
                emit(clear, src);
            }
            if (end) {
                emit("G0 X" + num(options.latheChangeX), src);
                emit(lines[i], src);
                continue;
            }
            emit(lines[i], src);
            // The new tool's offset: X to the approach's, Z where the slide is.
            const int station = stationOf(body);
            const auto at = toolAt.find(station);
            const GangPlace* next = at == toolAt.end() ? nullptr : slide.place(at->second);
            if (!next) throw std::logic_error(fmt::format("gang post: no tool on the slide for station {}", station));
            double x = options.latheChangeX;
            for (std::size_t j = i + 1; j < lines.size(); ++j)
                if (const auto b = splitNumber(lines[j]).second; movesTo(b)) {
                    x = word(b, 'X') ? toMm(*word(b, 'X'), options.units) : x;
                    break;
                }
            active = next;
            tip = turning::ZR{slideZ + active->offset.z, x / 2.0};
            emit("G0 X" + num(x) + " Z" + num(tip->z), src);
            continue;
        }
        if (movesTo(body)) {
            turning::ZR p = tip.value_or(turning::ZR{clearSlide, options.latheChangeX / 2.0});
            if (const auto x = word(body, 'X')) p.r = toMm(*x, options.units) / 2.0;
            if (const auto z = word(body, 'Z')) p.z = toMm(*z, options.units);
            before = tip;
            tip = p;
        }
        emit(lines[i], src);
    }
    out.tapeImage = post::tapeImage(out.nc, options.programName, d->name, options.machine);
    return out;
}

}  // namespace taiwa
