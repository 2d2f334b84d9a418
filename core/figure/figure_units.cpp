// Figure text converted between length units (figure_units.h).
#include "figure/figure_units.h"

#include "figure/figure_text.h"

#include <vector>

namespace taiwa::figure {

std::string convertFigureLengths(std::string_view text, const std::function<double(double)>& f)
{
    ParseResult parsed = parseFigure(text);
    if (!parsed.ok()) return std::string(text);
    std::vector<std::string> lines;
    for (std::size_t from = 0;;) {
        const std::size_t to = text.find('\n', from);
        lines.emplace_back(text.substr(from, to == std::string_view::npos ? std::string_view::npos : to - from));
        if (to == std::string_view::npos) break;
        from = to + 1;
    }
    for (Definition& d : parsed.definitions) {
        if (d.method != Method::LineAtAngle)  // its one number is an angle; every other number is a length
            for (double& v : d.numbers) v = f(v);
        for (ContourStep& st : d.contour.steps)
            if (st.corner != CornerKind::None) st.value = f(st.value);
        if (d.line < 1 || d.line > static_cast<int>(lines.size())) continue;
        std::string& line = lines[static_cast<std::size_t>(d.line - 1)];
        const std::size_t comment = line.find("$$");
        const std::string indent = line.substr(0, line.find_first_not_of(" \t"));
        line = indent + writeDefinition(d) + (comment == std::string::npos ? "" : " " + line.substr(comment));
    }
    std::string out;
    for (std::size_t i = 0; i < lines.size(); ++i) out += lines[i] + (i + 1 < lines.size() ? "\n" : "");
    return out;
}

}  // namespace taiwa::figure
