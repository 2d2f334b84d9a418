// ISO 1832 turning insert codes (insert_code.h).
#include "tools/insert_code.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <utility>
#include <vector>

namespace taiwa {

namespace {

struct Shape {
    char letter;
    double angle;
    // size digits -> inscribed circle [mm]
    std::vector<std::pair<std::string, double>> sizes;
};

const std::vector<Shape>& shapes()
{
    static const std::vector<Shape> s{
        {'C', 80, {{"06", 6.35}, {"09", 9.525}, {"12", 12.7}, {"16", 15.875}, {"19", 19.05}}},
        {'D', 55, {{"07", 6.35}, {"11", 9.525}, {"15", 12.7}, {"19", 15.875}}},
        {'K', 55, {{"09", 6.35}, {"16", 9.525}}},
        {'R', 0, {{"06", 6}, {"08", 8}, {"10", 10}, {"12", 12}, {"16", 16}, {"20", 20}, {"25", 25}}},
        {'S', 90, {{"09", 9.525}, {"12", 12.7}, {"15", 15.875}, {"19", 19.05}}},
        {'T', 60, {{"11", 6.35}, {"16", 9.525}, {"22", 12.7}, {"27", 15.875}}},
        {'V', 35, {{"11", 6.35}, {"16", 9.525}, {"22", 12.7}}},
        {'W', 80, {{"04", 6.35}, {"06", 9.525}, {"08", 12.7}}},
    };
    return s;
}

// Edge length of a polygonal insert from its inscribed circle.
double edgeLengthOf(const Shape& s, double ic, const std::string& digits)
{
    if (s.letter == 'R') return ic;
    return std::stod(digits);  // the size digits are the edge length in whole mm
}

const std::map<char, double> kClearance{{'A', 3}, {'B', 5}, {'C', 7}, {'D', 15}, {'E', 20},
                                        {'F', 25}, {'G', 30}, {'N', 0}, {'P', 11}, {'O', 0}};
const std::map<std::string, double> kThickness{{"01", 1.59}, {"T1", 1.98}, {"02", 2.38}, {"03", 3.18}, {"T3", 3.97},
                                               {"04", 4.76}, {"05", 5.56}, {"06", 6.35}, {"07", 7.94}, {"09", 9.52}};

}  // namespace

Result<InsertCode> parseInsertCode(const std::string& text)
{
    std::string s;
    for (const char c : text)
        if (!std::isspace(static_cast<unsigned char>(c))) s += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    const auto refuse = [&](const std::string& why) { return Failure{"'" + text + "': " + why}; };
    if (s.size() < 10) return refuse("an ISO insert code has four letters and six digits, as in CNMG 120408");
    std::string letters;
    for (const auto& sh : shapes()) letters += (letters.empty() ? "" : ", ") + std::string(1, sh.letter);
    const auto shape = std::find_if(shapes().begin(), shapes().end(), [&](const Shape& x) { return x.letter == s[0]; });
    if (shape == shapes().end())
        return refuse(std::string(1, s[0]) + " is not an ISO insert shape this program knows (" + letters + ")");
    InsertCode c;
    c.shape = s[0];
    c.tipAngle = shape->angle;
    c.clearance = s[1];
    const auto clearance = kClearance.find(s[1]);
    if (clearance == kClearance.end())
        return refuse(std::string(1, s[1]) + " is not an ISO clearance letter (N 0°, B 5°, C 7°, P 11°, …)");
    c.clearanceAngle = clearance->second;
    if (!std::isalpha(static_cast<unsigned char>(s[2])) || !std::isalpha(static_cast<unsigned char>(s[3])))
        return refuse("the third and fourth characters are the tolerance and type letters (as in CNMG)");
    c.tolerance = s[2];
    c.type = s[3];
    const std::string size = s.substr(4, 2), thick = s.substr(6, 2), nose = s.substr(8, 2);
    const auto ic = std::find_if(shape->sizes.begin(), shape->sizes.end(), [&](const auto& p) { return p.first == size; });
    if (ic == shape->sizes.end()) {
        std::string known;
        for (const auto& p : shape->sizes) known += (known.empty() ? "" : ", ") + p.first;
        return refuse("size " + size + " is not a " + std::string(1, c.shape) + " insert's (" + known + ")");
    }
    c.inscribedCircle = ic->second;
    c.edgeLength = edgeLengthOf(*shape, ic->second, size);
    const auto t = kThickness.find(thick);
    if (t == kThickness.end()) return refuse("thickness " + thick + " is not an ISO thickness code (02, 03, T3, 04, 06, …)");
    c.thickness = t->second;
    if (nose == "M0") {
        if (c.shape != 'R') return refuse("M0 (no corner) is for round inserts only");
        c.noseRadius = 0.0;
    } else if (std::isdigit(static_cast<unsigned char>(nose[0])) && std::isdigit(static_cast<unsigned char>(nose[1]))) {
        c.noseRadius = std::stoi(nose) / 10.0;
    } else {
        return refuse("the nose radius " + nose + " must be two digits in tenths of a mm (04 = 0.4 mm) or M0");
    }
    std::string rest = s.substr(10);
    if (!rest.empty() && rest.front() == '-') rest.erase(0, 1);
    if (!std::all_of(rest.begin(), rest.end(), [](char ch) { return std::isalnum(static_cast<unsigned char>(ch)); }))
        return refuse("the chip breaker '" + rest + "' must be letters and digits");
    c.chipBreaker = rest;
    c.code = s.substr(0, 4) + " " + s.substr(4, 6) + (rest.empty() ? "" : "-" + rest);
    return c;
}

}  // namespace taiwa
