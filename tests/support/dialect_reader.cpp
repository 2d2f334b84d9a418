// The shipped dialects' tapes read by the core's reader (verify/tape_reader.h)
// into rs274's canonical moves (dialect_reader.h).
#include "support/dialect_reader.h"

#include "post/dialect.h"
#include "verify/tape_reader.h"

namespace taiwa::test {

namespace {

DialectMoves read(const std::string& text, const char* dialect)
{
    const verify::TapeReading r = verify::readTape(text, post::dialectNamed(dialect));
    DialectMoves out;
    out.inches = r.inches;
    out.dwells = r.dwells;
    out.error = r.error;
    out.moves.reserve(r.motions.size());
    for (const verify::TapeMotion& m : r.motions) {
        CanonMove c;
        c.kind = m.kind == verify::TapeMotion::Traverse ? CanonMove::Traverse
                 : m.kind == verify::TapeMotion::Feed   ? CanonMove::Feed
                                                        : CanonMove::Arc;
        c.start = m.start;
        c.end = m.end;
        c.centre = m.centre;
        c.rotation = m.rotation;
        c.plane = 17;
        c.feed = m.feed;
        c.step = m.step;
        c.tool = m.tool;
        out.moves.push_back(c);
        out.lines.push_back(m.line);
    }
    return out;
}

}  // namespace

DialectMoves readIsoTape(const std::string& text, bool sinumerik) { return read(text, sinumerik ? "sinumerik" : "haas"); }

DialectMoves readKlartext(const std::string& text) { return read(text, "heidenhain"); }

}  // namespace taiwa::test
