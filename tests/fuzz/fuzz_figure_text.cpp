// libFuzzer target for the figure language (core/figure/): any bytes go to
// parseFigure, which must not crash and must either read definitions or
// refuse with a line and column inside the text and a one-line printable
// message. Definitions read are evaluated (no crash, refusals one line) and
// written; the written text must read back to the same definitions and
// write again to the same text. Every contour corner revised
// (reviseCorner) gives text that reads back to the same definitions but for
// that one value.
// Run: build-fuzz/tests/fuzz/fuzz_figure_text -dict=tests/fuzz/figure.dict -max_len=2048 CORPUS tests/fuzz/corpus/figure_text
#include "figure/figure_eval.h"
#include "figure/figure_text.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

namespace {
void fail(const char* what)
{
    std::fprintf(stderr, "fuzz_figure_text: %s\n", what);
    std::abort();
}

void checkMessage(const taiwa::figure::FigureError& e)
{
    if (e.line < 1 || e.column < 1) fail("a refusal without its line and column");
    for (const char c : e.message)
        if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f)
            fail("a refusal that is not one line of printable text");
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace taiwa::figure;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const ParseResult read = parseFigure(text);
    if (!read.ok()) {
        checkMessage(*read.error);
        if (!read.definitions.empty()) fail("definitions and a refusal at once");
        return 0;
    }
    const Evaluation ev = evaluate(read.definitions);
    for (const auto& e : ev.errors) checkMessage(e);
    if (ev.elements.size() + ev.contours.size() + ev.errors.size() > read.definitions.size())
        fail("more results than definitions");
    const std::string written = writeFigure(read.definitions);
    const ParseResult again = parseFigure(written);
    if (!again.ok()) fail("written text does not read back");
    if (!(again.definitions == read.definitions)) fail("written text reads back to other definitions");
    if (writeFigure(again.definitions) != written) fail("written text is not canonical");
    for (std::size_t i = 0; i < read.definitions.size(); ++i) {
        const Definition& d = read.definitions[i];
        if (d.method != Method::Contour) continue;
        int corner = 0;
        for (std::size_t k = 0; k < d.contour.steps.size(); ++k) {
            if (d.contour.steps[k].corner == CornerKind::None) continue;
            const auto revised = reviseCorner(text, d.name, corner++, 1.25);
            if (!revised) fail("a corner that cannot be revised");
            ParseResult r = parseFigure(*revised);
            if (!r.ok() || r.definitions.size() != read.definitions.size()) fail("a revised corner breaks the text");
            if (r.definitions[i].contour.steps[k].value != 1.25) fail("a revised corner has another value");
            r.definitions[i].contour.steps[k].value = d.contour.steps[k].value;
            if (!(r.definitions == read.definitions)) fail("a revised corner changes something else");
        }
    }
    return 0;
}
