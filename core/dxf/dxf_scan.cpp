// The guard in front of dxflib (see dxf_scan.h): reads the DXF group pairs
// itself, keeps the entities and group codes Taiwa reads, checks every number
// and rewrites every count.
#include "dxf/dxf_scan.h"

#include "model/translate_noop.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <set>

namespace taiwa::dxf::detail {

namespace {

constexpr std::size_t kMaxBytes = std::size_t{256} << 20;
constexpr double kMaxNumber = 1e12;      // drawing units; far beyond any machine
constexpr std::size_t kMaxValue = 1000;  // characters: dxflib's lines end at 1024

struct Pair {
    int code = 0;
    std::string_view value;
    int line = 0;  // of the value
};

std::string_view trim(std::string_view s)
{
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
    return s;
}

std::string shorten(std::string_view s)
{
    std::string out(s.substr(0, 40));
    for (char& c : out)
        if (static_cast<unsigned char>(c) < 32) c = '?';
    return s.size() > 40 ? out + "…" : out;
}

std::string upper(std::string_view s)
{
    std::string out(s);
    for (char& c : out)
        if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
    return out;
}

// The file's group pairs, one at a time.
class PairReader {
public:
    explicit PairReader(std::string_view text) : text_(text) {}
    // False at the end of the text or on a line that is no group code (then
    // `error` says so).
    bool next(Pair& p, std::optional<std::string>& error)
    {
        std::string_view codeLine, valueLine;
        if (!line(codeLine)) return false;
        const int codeLineNo = lineNo_;
        if (!line(valueLine)) {
            if (!trim(codeLine).empty()) truncated = true;
            return false;
        }
        const std::string_view c = trim(codeLine);
        int code = 0;
        const auto r = std::from_chars(c.data(), c.data() + c.size(), code);
        if (c.empty() || r.ec != std::errc{} || r.ptr != c.data() + c.size() || code < -5 || code > 1071) {
            error = fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "line {}: '{}' stands where a DXF group code belongs: not a DXF file, or a damaged one"),
                                codeLineNo, shorten(codeLine));
            return false;
        }
        p = {code, valueLine, lineNo_};
        return true;
    }
    bool truncated = false;

private:
    bool line(std::string_view& out)
    {
        if (pos_ >= text_.size()) return false;
        const std::size_t end = text_.find('\n', pos_);
        const std::size_t stop = end == std::string_view::npos ? text_.size() : end;
        out = text_.substr(pos_, stop - pos_);
        if (!out.empty() && out.back() == '\r') out.remove_suffix(1);
        pos_ = stop + 1;
        ++lineNo_;
        return true;
    }
    std::string_view text_;
    std::size_t pos_ = 0;
    int lineNo_ = 0;
};

bool isRealCode(int c) { return (c >= 10 && c <= 59) || (c >= 110 && c <= 149) || (c >= 210 && c <= 239); }

std::optional<double> parseReal(std::string_view v)
{
    v = trim(v);
    std::string s(v);
    if (s.find('.') == std::string::npos) std::replace(s.begin(), s.end(), ',', '.');  // dxflib reads ',' as '.'
    double d = 0;
    const auto r = std::from_chars(s.data(), s.data() + s.size(), d);
    if (s.empty() || r.ec != std::errc{} || r.ptr != s.data() + s.size() || !std::isfinite(d) || std::abs(d) > kMaxNumber)
        return std::nullopt;
    return d;
}

std::optional<int> parseInt(std::string_view v)
{
    v = trim(v);
    long long i = 0;
    const auto r = std::from_chars(v.data(), v.data() + v.size(), i);
    if (v.empty() || r.ec != std::errc{} || r.ptr != v.data() + v.size() || i < -1000000000LL || i > 1000000000LL)
        return std::nullopt;
    return static_cast<int>(i);
}

// The group codes dxflib is given for each entity Taiwa reads.
bool keeps(std::string_view type, int c)
{
    const bool extrusion = c == 210 || c == 220 || c == 230;
    if (type == "LINE") return c == 8 || c == 10 || c == 20 || c == 30 || c == 11 || c == 21 || c == 31 || extrusion;
    if (type == "ARC") return c == 8 || c == 10 || c == 20 || c == 30 || c == 40 || c == 50 || c == 51 || extrusion;
    if (type == "CIRCLE") return c == 8 || c == 10 || c == 20 || c == 30 || c == 40 || extrusion;
    if (type == "ELLIPSE")
        return c == 8 || c == 10 || c == 20 || c == 30 || c == 11 || c == 21 || c == 31 || c == 40 || c == 41 ||
               c == 42 || extrusion;
    if (type == "LWPOLYLINE") return c == 8 || c == 70 || c == 10 || c == 20 || c == 42 || extrusion;
    if (type == "POLYLINE") return c == 8 || c == 70 || extrusion;
    if (type == "VERTEX") return c == 10 || c == 20 || c == 30 || c == 42 || c == 70;
    if (type == "SPLINE")
        return c == 8 || c == 70 || c == 71 || c == 10 || c == 20 || c == 30 || c == 11 || c == 21 || c == 31 ||
               c == 40 || c == 41 || extrusion;
    return false;
}

bool isRead(std::string_view t)
{
    return t == "LINE" || t == "ARC" || t == "CIRCLE" || t == "ELLIPSE" || t == "LWPOLYLINE" || t == "POLYLINE" ||
           t == "SPLINE";
}

struct Entity {
    std::string_view type;
    int line = 0;  // of its "0 / TYPE" pair
    std::vector<Pair> pairs;

    std::string layer() const
    {
        for (const Pair& p : pairs)
            if (p.code == 8) return std::string(trim(p.value).substr(0, kMaxValue));
        return "0";
    }
    int intValue(int code, int fallback) const
    {
        for (const Pair& p : pairs)
            if (p.code == code) return parseInt(p.value).value_or(fallback);
        return fallback;
    }
};

// Takes the ENTITIES section's entities one by one and writes what dxflib
// is to read.
class Filter {
public:
    Filter(ScanResult& out, Notes& notes, const std::vector<std::string>& selected)
        : out_(out), notes_(notes), selected_(selected)
    {
    }

    void tableLayer(std::string_view name) { layer(std::string(trim(name).substr(0, kMaxValue))); }

    void entity(Entity e)
    {
        if (e.type == "VERTEX") {
            if (!polyline_.empty()) polyline_.push_back(std::move(e));
            return;
        }
        if (!polyline_.empty()) finishPolyline(e.type == "SEQEND");
        if (e.type == "SEQEND" || e.type == "ATTRIB") return;  // the end of an INSERT's attributes
        if (e.intValue(67, 0) == 1) {
            ++paperSpace_;
            return;
        }
        LayerInfo& l = layer(e.layer());
        ++l.entities;
        if (!l.selected) return;
        if (!isRead(e.type)) {
            ++ignored_[std::string(e.type.substr(0, 40))];
            return;
        }
        if (e.type == "POLYLINE") {
            polyline_.push_back(std::move(e));
            return;
        }
        std::string text;
        if (clean(e, text)) {
            out_.entities += text;
            ++out_.keptEntities;
        }
    }

    void finish()
    {
        if (!polyline_.empty()) finishPolyline(false);
        if (paperSpace_ > 0) notes_.add(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} entities in paper space not read"), paperSpace_));
        if (!ignored_.empty()) {
            std::string list;
            for (const auto& [type, n] : ignored_)
                list = list.empty() ? fmt::format("{} {}", n, type)
                                    : fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}, {}"), list, fmt::format("{} {}", n, type));
            notes_.add(ignored_.count("INSERT")
                           ? fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "not read (no contour geometry): {} — block references are not expanded: explode them in the CAD program"), list)
                           : fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "not read (no contour geometry): {}"), list));
        }
        for (auto& [key, info] : layers_) out_.layers.push_back(info);
    }

private:
    LayerInfo& layer(const std::string& name)
    {
        auto [it, added] = layers_.try_emplace(upper(name));
        if (added) {
            it->second.name = name;
            it->second.selected = selected_.empty() || std::any_of(selected_.begin(), selected_.end(), [&](const std::string& s) {
                                      return sameLayerName(s, name);
                                  });
        }
        return it->second;
    }

    void finishPolyline(bool sawSeqend)
    {
        const Entity& head = polyline_.front();
        const int flags = head.intValue(70, 0);
        if (!sawSeqend) notes_.add(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "line {}: POLYLINE without SEQEND, read up to its last VERTEX"), head.line));
        if (flags & (16 | 64)) {
            notes_.add(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "line {}: POLYLINE mesh or polyface (flags {}) is no contour: not read"), head.line, flags));
        } else {
            std::string text;
            bool ok = clean(head, text);
            for (std::size_t i = 1; ok && i < polyline_.size(); ++i) {
                if (polyline_[i].intValue(70, 0) & 16) continue;  // a spline frame's control point, not on the curve
                ok = clean(polyline_[i], text, false);
            }
            if (ok) {
                out_.entities += text + "0\nSEQEND\n";
                ++out_.keptEntities;
            }
        }
        polyline_.clear();
    }

    // The entity as dxflib is to read it; false (and a note) when it must be
    // left out.
    bool clean(const Entity& e, std::string& text, bool tagged = true)
    {
        std::string body;
        int n10 = 0, n11 = 0, n40 = 0, n41 = 0;
        char buf[64];
        for (const Pair& p : e.pairs) {
            if (!keeps(e.type, p.code)) continue;
            if (e.type == "LWPOLYLINE" && p.code != 10 && p.code != 8 && p.code != 70 && p.code < 200 && n10 == 0)
                continue;  // a vertex's 20/42 before any 10: dxflib would write before its array
            std::string_view value = trim(p.value);
            if (isRealCode(p.code)) {
                const auto d = parseReal(p.value);
                if (!d) {
                    notes_.add(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "line {}: {} not read: '{}' is not a finite number (within ±1e12)"), p.line,
                                           e.type, shorten(p.value)));
                    return false;
                }
                value = std::string_view(buf, static_cast<std::size_t>(std::to_chars(buf, buf + sizeof buf, *d).ptr - buf));
            } else if (p.code >= 60 && p.code <= 99) {
                if (!parseInt(p.value)) {
                    notes_.add(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "line {}: {} not read: '{}' is not an integer"), p.line, e.type, shorten(p.value)));
                    return false;
                }
            }
            n10 += p.code == 10;
            n11 += p.code == 11;
            n40 += p.code == 40;
            n41 += p.code == 41;
            body += fmt::format("{}\n{}\n", p.code, value.substr(0, kMaxValue));
        }
        std::string counts;
        if (e.type == "LWPOLYLINE") counts = fmt::format("90\n{}\n", n10);
        if (e.type == "SPLINE") {
            if (n41 != 0 && n41 != n10) {
                notes_.add(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "line {}: SPLINE not read: {} weights for {} control points"), e.line, n41, n10));
                return false;
            }
            counts = fmt::format("72\n{}\n73\n{}\n74\n{}\n", n40, n10, n11);
        }
        text += fmt::format("0\n{}\n", e.type);
        if (tagged) text += fmt::format("6\n@{} {}\n", e.line, e.type);
        text += counts + body;
        return true;
    }

    ScanResult& out_;
    Notes& notes_;
    const std::vector<std::string>& selected_;
    std::map<std::string, LayerInfo> layers_;  // by upper-case name
    std::map<std::string, int> ignored_;
    std::vector<Entity> polyline_;  // a POLYLINE and its VERTEXes
    int paperSpace_ = 0;
};

ScanResult failed(std::string message)
{
    ScanResult r;
    r.error = std::move(message);
    return r;
}

}  // namespace

bool sameLayerName(std::string_view a, std::string_view b) { return upper(trim(a)) == upper(trim(b)); }

ScanResult scanDxf(std::string_view bytes, const std::vector<std::string>& selectedLayers, Notes& notes)
{
    ScanResult out;
    if (bytes.empty()) return failed(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the file is empty"));
    if (bytes.size() > kMaxBytes) return failed(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the file is larger than {} MB"), kMaxBytes >> 20));
    if (bytes.substr(0, 18) == "AutoCAD Binary DXF")
        return failed(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a binary DXF: save the drawing as an ASCII DXF (R12 or later)"));
    if (bytes.find('\0') != std::string_view::npos) return failed(TAIWA_TRANSLATE_NOOP("taiwa::msg", "not a DXF file: it holds binary data"));

    PairReader reader(bytes);
    out.entities.reserve(bytes.size() + 64);  // what is kept, about as long as the file: written once
    out.entities = "0\nSECTION\n2\nENTITIES\n";
    Filter filter(out, notes, selectedLayers);
    Pair p;
    std::string section, headerVariable, tableEntry;
    bool expectSectionName = false, sawSection = false, sawEntities = false, sawEof = false, first = true;
    std::optional<Entity> entity;
    while (reader.next(p, out.error)) {
        if (first && p.code != 0 && p.code != 999)
            return failed(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "not a DXF file: it starts with '{}'"), shorten(p.value)));
        first = false;
        const std::string_view v = trim(p.value);
        if (expectSectionName) {
            expectSectionName = false;
            if (p.code == 2) {
                section = upper(v);
                sawEntities = sawEntities || section == "ENTITIES";
                continue;
            }
        }
        if (p.code == 0 && (v == "SECTION" || v == "ENDSEC" || v == "EOF")) {
            if (entity) filter.entity(std::move(*entity));
            entity.reset();
            section.clear();
            expectSectionName = v == "SECTION";
            sawSection = sawSection || expectSectionName;
            if (v == "EOF") {
                sawEof = true;
                break;
            }
            continue;
        }
        if (section == "HEADER") {
            if (p.code == 9) headerVariable = upper(v);
            else if (headerVariable == "$INSUNITS" && p.code == 70) out.insunits = parseInt(v);
            else if (headerVariable == "$ACADVER" && p.code == 1) out.version = std::string(v.substr(0, 20));
        } else if (section == "TABLES") {
            if (p.code == 0) tableEntry = upper(v);
            else if (tableEntry == "LAYER" && p.code == 2) filter.tableLayer(v);
        } else if (section == "ENTITIES") {
            if (p.code == 0) {
                if (entity) filter.entity(std::move(*entity));
                entity = Entity{v, p.line - 1, {}};
            } else if (entity) {
                entity->pairs.push_back(p);
            }
        }
    }
    if (out.error) return failed(*out.error);
    if (entity) filter.entity(std::move(*entity));
    filter.finish();
    if (!sawSection) return failed(TAIWA_TRANSLATE_NOOP("taiwa::msg", "not a DXF file: it has no SECTION"));
    if (!sawEntities) {
        ScanResult f = failed(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the DXF file has no ENTITIES section"));
        f.layers = std::move(out.layers);
        return f;
    }
    if (!sawEof) notes.add(reader.truncated ? TAIWA_TRANSLATE_NOOP("taiwa::msg", "the file ends in the middle of a group: it may be cut short")
                                            : TAIWA_TRANSLATE_NOOP("taiwa::msg", "the file ends without EOF: it may be cut short"));
    out.entities += "0\nENDSEC\n0\nEOF\n";
    return out;
}

}  // namespace taiwa::dxf::detail
