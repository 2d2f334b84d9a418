// The reader of the ISO and SINUMERIK tapes (readTape, tape_reader.h): the
// tape split into lines, each line's comments taken out and its words read
// strictly (tape_reader_iso.h's IsoReader), or the reading stopped at its
// line. What each block's words do is in tape_reader_iso_block.cpp, the
// Klartext reader in tape_reader_klartext.cpp, the drilling cycles in
// tape_reader_cycles.cpp.
#include "verify/tape_reader_iso.h"

#include <string_view>

namespace taiwa::verify {

TapeReading readKlartext(const std::string& text);  // tape_reader_klartext.cpp

namespace tape {

IsoReader::IsoReader(const post::Dialect& d)
    : sinumerik_(d.syntax == post::Syntax::Sinumerik),
      numbered_(!sinumerik_ && !d.programNumberLine.empty()),
      points_(!sinumerik_ && d.decimalPointAlways),
      offsetNeeded_(!d.lengthOffset.empty()),
      dwellWord_(sinumerik_ ? 'F' : d.dwellWord),
      tapSynchronised_(d.tap == "G33.1")
{
    m_.framed = !sinumerik_ && d.percentFraming;
}

TapeReading IsoReader::read(const std::string& text)
{
    return m_.readLines(
        text, [&](const std::string& raw) { line(raw); }, [&](const std::vector<std::string>& lines) { m_.endOfTape(lines); });
}

IsoReader::Block IsoReader::words(const std::vector<std::string>& tokens)
{
    Block b;
    for (std::size_t k = 0; k < tokens.size(); ++k) {
        const std::string& t = tokens[k];
        if (sinumerik_ && t == "SUPA") {
            b.supa = true;
            continue;
        }
        if (sinumerik_ && t == "MCALL") {
            b.mcall = true;
            continue;
        }
        if (sinumerik_ && t.starts_with("CYCLE")) {
            if (!b.cycle.empty()) refuse("two cycles in one block");
            b.cycle = t;
            continue;
        }
        if (sinumerik_ && t.starts_with("ADIS=")) {
            b.adis = decimal(std::string_view(t).substr(5), false);
            if (!b.adis) refuse("'" + t + "' is not understood");
            continue;
        }
        if (codeWord(t, k, b.g, b.m)) continue;  // N, M, G (G59.1, G33.1, G54.1: in tenths)
        if (!letterWord(t, sinumerik_ ? "XYZIJFSTD" : "XYZIJKRFPQSTH", "STDH", b)) continue;
        const char letter = t[0];
        // A FANUC or a Haas reads a number without a point in least
        // increments (X10 = 0.01 mm); their tapes always write the point.
        if (points_ && letter != 'P' && !b.point[letter])
            refuse("'" + t + "' without a decimal point (this control reads it in least increments)");
    }
    return b;
}

void IsoReader::line(const std::string& raw)
{
    if (raw.find_first_of("\r\t") != std::string::npos) refuse("a carriage return or tab");
    const std::string s = trim(m_.withoutComments(raw, sinumerik_));
    if (s.empty() || m_.framingLine(s)) return;
    const auto tokens = splitWords(s);
    if (numbered_ && tokens.size() == 1 && tokens[0][0] == 'O') {
        if (!whole(std::string_view(tokens[0]).substr(1)) || programNumber_) refuse("'" + tokens[0] + "' is not understood");
        programNumber_ = true;
        return;
    }
    block(words(tokens));
}

}  // namespace tape

TapeReading readTape(const std::string& text, const post::Dialect& dialect)
{
    if (dialect.syntax == post::Syntax::Klartext) return readKlartext(text);
    return tape::IsoReader(dialect).read(text);
}

}  // namespace taiwa::verify
