// The sheet's pictures for an export, the same for `taiwa export` and the
// station's export: drawn by the core on the processor (core/picture, no
// display needed), encoded here as PNG with their labels painted in Qt's
// fonts (this library is where Qt Gui is allowed).
#pragma once

#include "export/export.h"
#include "picture/image.h"

#include <string>

namespace taiwa {

// At most this many step pictures: a very large job's sheet stays small and quick.
inline constexpr int kMaxSheetPictures = 200;

// PNG bytes of a picture, its labels painted on it (only where a
// QGuiApplication runs: without one, the picture without its words).
// Empty when it cannot be encoded.
std::string pngOf(const picture::Picture& p);

// The setup picture and one picture per step (the first `limit`) into
// `options`, with the note of any that are missing or left out. Returns
// why pictures are missing (empty: every picture was made; a job with
// more steps than `limit` is not a problem, its note says so).
std::string addSheetPictures(const Plan& plan, ExportOptions& options, int limit = kMaxSheetPictures);

}  // namespace taiwa
