// The holder's nose from its name: collet chucks by their ER size (the
// clamping nut, DIN 6499 / ISO 15488), shrink-fit chucks and Weldon side-lock
// holders by the shank diameter they take (DIN 69882-8 form A, DIN 1835 B
// holders of common makers), shell mill arbors and probe bodies by their
// body. Rounded up to the next millimetre.
#include "tools/holder_shape.h"

#include <algorithm>
#include <cctype>
#include <string>
#include <utility>

namespace taiwa::tools {

namespace {

std::string lower(std::string s)
{
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

// The first row whose shank is at least `d`, else the last row's.
double byShank(double d, std::initializer_list<std::pair<double, double>> rows)
{
    double nose = 0.0;
    for (const auto& [shank, n] : rows) {
        nose = n;
        if (d <= shank + 1e-9) break;
    }
    return nose;
}

}  // namespace

HolderShape holderShape(const Tool& tool)
{
    HolderShape h;
    const double d = tool.diameter;
    h.shankDiameter = d;
    if (tool.holderDiameter > 0) {  // the library's own measure first
        h.noseDiameter = tool.holderDiameter;
        h.noseLength = tool.holderLength > 0 ? tool.holderLength : 50;
        h.known = true;
        return h;
    }
    const std::string name = lower(tool.holder);
    constexpr std::pair<const char*, double> kColletNuts[] = {{"er11", 19}, {"er16", 28}, {"er20", 34},
                                                               {"er25", 42}, {"er32", 50}, {"er40", 63}};
    for (const auto& [size, nut] : kColletNuts) {
        if (name.find(size) != std::string::npos) {
            h.noseDiameter = nut;
            h.noseLength = 30;
            h.known = true;
            return h;
        }
    }
    if (name.find("shrink") != std::string::npos) {
        h.noseDiameter = byShank(d, {{6, 21}, {8, 21}, {12, 24}, {16, 27}, {20, 33}, {25, 44}, {32, 44}});
        h.noseLength = 50;
        h.known = true;
    } else if (name.find("weldon") != std::string::npos || name.find("side lock") != std::string::npos) {
        h.noseDiameter = byShank(d, {{6, 25}, {8, 28}, {10, 35}, {12, 42}, {16, 48}, {20, 52}, {25, 65}, {32, 72}});
        h.noseLength = 50;
        h.known = true;
    } else if (name.find("shell mill") != std::string::npos || name.find("arbor") != std::string::npos) {
        h.noseDiameter = std::max(40.0, 0.8 * d);
        h.noseLength = 40;
        h.known = true;
    } else if (name.find("probe") != std::string::npos) {
        h.noseDiameter = 40;
        h.noseLength = 60;
        h.known = true;
    } else {
        h.noseDiameter = std::max(63.0, d + 30.0);  // the widest nose of the rules above
        h.noseLength = 60;
    }
    return h;
}

}  // namespace taiwa::tools
