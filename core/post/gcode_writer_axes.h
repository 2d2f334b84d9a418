// The axes of the G-code writer's modal state (GCodeWriter::axis_ is
// indexed by them), shared by its two halves: gcode_writer.cpp (the
// moves and the blocks) and gcode_writer_cycles.cpp (the drilling
// cycles). Internal to core/post.
#pragma once

namespace taiwa::post::detail {

enum Axis { X, Y, Z };

}  // namespace taiwa::post::detail
