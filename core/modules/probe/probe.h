// Module PROBE: work-centre probing (spec "Work centre as machining origin",
// seed 004). A round (boss, bore) or rectangular (block, pocket) workpiece
// clamped anywhere: the operator's touch points give its centre, which
// becomes the job's work offset (a setting block), and a probing cycle
// program makes the touches on the machine by itself. No machining steps.
// Its input as the job keeps it; the fits are in probe_fit.h, the rest
// behind its door (probe_kind.cpp).
#pragma once

#include "model/geometry.h"
#include "model/module.h"
#include "modules/length_fields.h"

#include <array>
#include <optional>

namespace taiwa {

struct ProbeUnit {
    static constexpr const char* kName = "PROBE";
    static constexpr int kSinceFormatVersion = 1;  // the job format that brought it
    static constexpr std::size_t kMaxTouches = 8;
    int shape = 1;   // 1 round (boss or bore), 2 rectangular (block or pocket)
    int where = 1;   // 1 touched from outside (boss, block), 2 from inside (bore, pocket)
    // The touches as measured: the stylus ball's centre, relative to the
    // first touch (the measuring origin, always 0, 0). A touch is there when
    // both coordinates are; rectangles say which side each is on (1 -X,
    // 2 +X, 3 -Y, 4 +Y, in the part's own axes).
    std::array<std::optional<double>, kMaxTouches> x{}, y{};
    std::array<int, kMaxTouches> side{};
    Point2 origin;               // machine X, Y of the first touch
    std::optional<double> top;   // machine Z of a touch on the top face (tool length to the ball's bottom)
    int tool = 0;                // the probe (tool library type "probe"); 0: the library's only probe
    double tolerance = 0.01;     // largest residual of a touch accepted
    // The probing cycle: nominal size, where the touches are made.
    double sizeX = 50.0;         // diameter (round) or width along X
    double sizeY = 0.0;          // length along Y (rectangular)
    double touchDepth = 5.0;     // below the top face
    double clearance = 5.0;      // beyond the nominal outline (inside it for bores and pockets)
    double search = 10.0;        // how far past the nominal outline a touch looks
    double feed = 100.0;         // mm/min

    void convertLengths(const LengthMap& f)
    {
        convertEach(f, x, y, origin, top, tolerance, sizeX, sizeY, touchDepth, clearance, search, feed);
    }
    friend bool operator==(const ProbeUnit&, const ProbeUnit&) = default;
};

}  // namespace taiwa
