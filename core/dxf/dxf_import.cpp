// DXF import (see dxf_import.h): the options checked, the guard (dxf_scan),
// dxflib's decoding (dxf_entities), the units, the pieces (dxf_geometry) and
// their chaining (dxf_chain), with every message collected in the result.
#include "dxf/dxf_import.h"

#include "model/translate_noop.h"

#include "dxf/dxf_chain.h"
#include "dxf/dxf_entities.h"
#include "dxf/dxf_geometry.h"
#include "dxf/dxf_scan.h"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>

namespace taiwa::dxf {

using detail::Notes;

namespace {

constexpr std::size_t kSegmentBudget = 2000000;

struct UnitInfo {
    double mmPerUnit;
    const char* name;
};

// $INSUNITS: the lengths sensible for a drawing to machine; the astronomical
// ones (17 to 20) are refused.
std::optional<UnitInfo> insunits(int code)
{
    switch (code) {
    case 1: return UnitInfo{25.4, TAIWA_TRANSLATE_NOOP("taiwa::msg", "inch")};
    case 2: return UnitInfo{304.8, TAIWA_TRANSLATE_NOOP("taiwa::msg", "foot")};
    case 3: return UnitInfo{1609344.0, TAIWA_TRANSLATE_NOOP("taiwa::msg", "mile")};
    case 4: return UnitInfo{1.0, "mm"};
    case 5: return UnitInfo{10.0, "cm"};
    case 6: return UnitInfo{1000.0, "m"};
    case 7: return UnitInfo{1e6, "km"};
    case 8: return UnitInfo{25.4e-6, TAIWA_TRANSLATE_NOOP("taiwa::msg", "microinch")};
    case 9: return UnitInfo{0.0254, TAIWA_TRANSLATE_NOOP("taiwa::msg", "mil")};
    case 10: return UnitInfo{914.4, TAIWA_TRANSLATE_NOOP("taiwa::msg", "yard")};
    case 11: return UnitInfo{1e-7, TAIWA_TRANSLATE_NOOP("taiwa::msg", "ångström")};
    case 12: return UnitInfo{1e-6, "nm"};
    case 13: return UnitInfo{1e-3, "µm"};
    case 14: return UnitInfo{100.0, "dm"};
    case 15: return UnitInfo{1e4, "dam"};
    case 16: return UnitInfo{1e5, "hm"};
    default: return std::nullopt;
    }
}

DxfReadResult failed(std::string message)
{
    DxfReadResult r;
    r.error = std::move(message);
    return r;
}

std::string layerList(const std::vector<LayerInfo>& layers)
{
    std::string s;
    for (const LayerInfo& l : layers) s += s.empty() ? fmt::format("{} ({})", l.name, l.entities)
                      : fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}, {}"), s, fmt::format("{} ({})", l.name, l.entities));
    return s.empty() ? TAIWA_TRANSLATE_NOOP("taiwa::msg", "none") : s;
}

Result<void> checkOptions(const DxfOptions& o)
{
    if (!(o.gapTolerance >= 1e-6 && o.gapTolerance <= 10.0))
        return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the gap tolerance {:g} mm is not between 0.000001 and 10 mm"), o.gapTolerance)};
    if (!(o.splineTolerance >= 1e-4 && o.splineTolerance <= 10.0))
        return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the spline tolerance {:g} mm is not between 0.0001 and 10 mm"), o.splineTolerance)};
    if (!(o.gapReportDistance >= 0.0 && o.gapReportDistance <= 1000.0))
        return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the gap report distance {:g} mm is not between 0 and 1000 mm"), o.gapReportDistance)};
    return {};
}

}  // namespace

std::string EntityRef::text() const
{
    return line > 0 ? fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} on layer {} (DXF line {})"), type, layer, line) : fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} on layer {}"), type, layer);
}

int DxfReadResult::closedCount() const
{
    return static_cast<int>(std::count_if(contours.begin(), contours.end(), [](const DxfContour& c) { return c.contour.closed; }));
}

int DxfReadResult::openCount() const { return static_cast<int>(contours.size()) - closedCount(); }

DxfReadResult readDxf(const std::filesystem::path& path, const DxfOptions& options)
{
    std::error_code ec;
    const auto size = std::filesystem::file_size(path, ec);
    if (ec) return failed(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "cannot read {}: {}"), path.string(), ec.message()));
    if (size > (std::size_t{256} << 20)) return failed(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} is larger than 256 MB"), path.string()));
    std::ifstream in(path, std::ios::binary);
    if (!in) return failed(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "cannot open {}: {}"), path.string(), std::strerror(errno)));
    std::string bytes(static_cast<std::size_t>(size), '\0');
    in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    bytes.resize(static_cast<std::size_t>(in.gcount()));  // a file cut shorter since its size was read
    if (in.bad()) return failed(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "cannot read {}"), path.string()));
    return readDxfBytes(bytes, options);
}

DxfReadResult readDxfBytes(std::string_view bytes, const DxfOptions& options)
{
    DxfReadResult r;
    if (auto checked = checkOptions(options); !checked) return failed(checked.error());
    Notes notes;
    detail::ScanResult scan = detail::scanDxf(bytes, options.layers, notes);
    r.layers = std::move(scan.layers);
    const auto fail = [&](std::string message) {
        DxfReadResult f;
        f.error = std::move(message);
        f.layers = std::move(r.layers);
        f.warnings = notes.take();
        return f;
    };
    if (scan.error) return fail(*scan.error);
    for (const std::string& wanted : options.layers)
        if (std::none_of(r.layers.begin(), r.layers.end(), [&](const LayerInfo& l) { return detail::sameLayerName(l.name, wanted); }))
            notes.add(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the drawing has no layer {}"), wanted));

    // Units.
    const std::optional<UnitInfo> fileUnits = scan.insunits && *scan.insunits != 0 ? insunits(*scan.insunits) : std::nullopt;
    if (options.units == Units::FromFile) {
        if (scan.insunits && *scan.insunits != 0 && !fileUnits)
            return fail(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the drawing's units ($INSUNITS {}) are not lengths to machine in"), *scan.insunits));
        if (!fileUnits) notes.add(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the drawing does not say its units ($INSUNITS unitless or absent): read as mm"));
        r.unitScale = fileUnits ? fileUnits->mmPerUnit : 1.0;
        r.units = fileUnits ? fileUnits->name : "mm";
    } else {
        const bool inch = options.units == Units::Inches;
        r.unitScale = inch ? 25.4 : 1.0;
        r.units = inch ? TAIWA_TRANSLATE_NOOP("taiwa::msg", "inch") : "mm";
        if (fileUnits && fileUnits->mmPerUnit != r.unitScale)
            notes.add(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the drawing says its units are {}; read as {} as set"), fileUnits->name, r.units));
    }

    if (scan.keptEntities == 0)
        return fail(options.layers.empty()
                        ? fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "no lines, arcs, circles, polylines, splines or ellipses on the drawing's layers; the drawing's layers: {}"),
                                      layerList(r.layers))
                        : fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "no lines, arcs, circles, polylines, splines or ellipses on the selected layers; the drawing's layers: {}"),
                                      layerList(r.layers)));
    const std::vector<detail::RawEntity> entities = detail::decodeEntities(scan.entities, static_cast<std::size_t>(scan.keptEntities));
    std::vector<detail::Piece> pieces;
    if (auto built = detail::buildPieces(entities, r.unitScale, options.splineTolerance, kSegmentBudget, pieces, notes); !built)
        return fail(built.error());
    if (pieces.empty()) return fail(TAIWA_TRANSLATE_NOOP("taiwa::msg", "none of the entities on the selected layers could be read (see the warnings)"));

    detail::ChainResult chain =
        detail::chainPieces(std::move(pieces), options.gapTolerance, std::max(options.gapReportDistance, 10 * options.gapTolerance));
    r.contours = std::move(chain.contours);
    r.gaps = std::move(chain.gaps);
    r.branches = std::move(chain.branches);
    r.smallGapsClosed = chain.joinsOverZero;
    r.largestGapClosed = chain.largestJoin;
    r.largestGapClosedAt = chain.largestJoinAt;
    if (r.smallGapsClosed > 0)
        notes.add(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} gaps up to {:.4g} mm closed (the largest at ({:.3f}, {:.3f})); the gap tolerance is {:.4g} mm"),
                              r.smallGapsClosed, r.largestGapClosed, r.largestGapClosedAt.x, r.largestGapClosedAt.y,
                              options.gapTolerance));
    r.warnings = notes.take();
    return r;
}

}  // namespace taiwa::dxf
