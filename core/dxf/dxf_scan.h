// The guard in front of dxflib: one pass over the raw DXF text that checks it
// is an ASCII DXF, reads $INSUNITS and the layers, and hands on only the
// entities Taiwa reads, on the selected layers, with only the group codes
// they need, every number checked finite and every count (LWPOLYLINE 90,
// SPLINE 72/73/74) rewritten to what the entity really holds. dxflib
// allocates by those counts unchecked (a 157-byte file crashes it), reads
// "nan" as 0 and loops forever on a line over 1024 characters; none of that
// reaches it. Internal to core/dxf/.
#pragma once

#include "dxf/dxf_import.h"
#include "dxf/dxf_notes.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace taiwa::dxf::detail {

struct ScanResult {
    std::optional<std::string> error;
    // An ENTITIES section for dxflib. Each entity carries its DXF line as
    // its linetype (group 6, "@57 LINE"): dxflib passes it through untouched.
    std::string entities;
    int keptEntities = 0;
    std::vector<LayerInfo> layers;  // sorted by name
    std::optional<int> insunits;
    std::string version;  // $ACADVER
};

ScanResult scanDxf(std::string_view bytes, const std::vector<std::string>& selectedLayers, Notes& notes);

// DXF layer names are compared without regard to case.
bool sameLayerName(std::string_view a, std::string_view b);

}  // namespace taiwa::dxf::detail
