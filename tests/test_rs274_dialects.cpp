// Outside check of the haas, sinumerik and heidenhain tapes: every milling
// sample (no lathe job, no probing unit) is exported through the real command
// line in linuxcnc and in each of the three dialects; the linuxcnc tape, its
// machine-coordinate retracts (G53) taken out, runs through LinuxCNC's rs274
// (support/rs274.h), the dialect's tape is read back by the strict readers of
// support/dialect_reader.h into the same canonical moves, and the two lists
// must agree move by move from the first move after the first tool change,
// lines that go nowhere left out: the kind, the end point and the arc centre
// to 1.5 units of the tape's last decimal, the arc's turn, the feed rate (to
// half a unit of the F word and a hair), the tool, and the dwells.
// Hand-written tapes cover what the samples do not write yet (G2 and DR-, a
// whole-turn helix, a dwell, a modal cycle at two holes); an altered tape
// must be caught and the readers must refuse what they do not know.
#include "support/dialect_reader.h"
#include "support/rs274.h"
#include "support/support.h"

#include <QDir>
#include <QFileInfo>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

using namespace taiwa;
using namespace taiwa::test;

namespace {

const QStringList kDialects{"haas", "sinumerik", "heidenhain"};

struct Tape {
    std::string text;
    QString error;  // why there is no tape
};

// `units` empty: the job's own.
Tape exportTape(const QString& job, const QString& dialect, const QString& units)
{
    QTemporaryDir out;
    // The tape is what is judged here: the verification on a coarse grid and
    // no step pictures (both have tests of their own, and at the default
    // 0.05 mm the contour samples take seconds each).
    QStringList args{"export", job, "--out", out.path(), "--dialect", dialect, "--resolution", "0.25", "--no-pictures"};
    if (!units.isEmpty()) args << "--units" << units;
    const RunResult r = runTaiwa(args);
    if (r.exitCode != 0) return {{}, "taiwa " + args.join(' ') + " failed: " + r.err};
    const QString ext = dialect == "sinumerik" ? "mpf" : dialect == "heidenhain" ? "h" : "nc";
    const QString file = QDir(out.path()).filePath(QFileInfo(job).completeBaseName() + "." + ext);
    if (!QFileInfo::exists(file)) return {{}, file + " was not written"};
    return {readFile(file), {}};
}

// The linuxcnc tape without its machine-coordinate moves ("G53 G0 Z0"),
// which the other dialects write their own way and the readers take as no
// move at all.
std::string withoutMachineMoves(const std::string& ngc)
{
    std::string out;
    for (const auto& line : QString::fromStdString(ngc).split('\n', Qt::SkipEmptyParts))
        if (!line.trimmed().startsWith("G53")) out += line.toStdString() + "\n";
    return out;
}

DialectMoves readTape(const QString& dialect, const std::string& text)
{
    return dialect == "heidenhain" ? readKlartext(text) : readIsoTape(text, dialect == "sinumerik");
}

// rs274's reading of a job's linuxcnc tape, once per job and units.
const Rs274Result& reference(const QString& job, const QString& units, QString* error)
{
    static std::map<QString, Rs274Result> done;
    const QString key = job + "|" + units;
    if (const auto it = done.find(key); it != done.end()) return it->second;
    Rs274Result r;
    const Tape t = exportTape(job, "linuxcnc", units);
    if (!t.error.isEmpty()) {
        r.errors = t.error;
    } else {
        const std::string ngc = withoutMachineMoves(t.text);
        if (ngc.size() == t.text.size()) r.errors = "the linuxcnc tape has no G53 retract (has its form changed?)";
        else r = runRs274(ngc);
    }
    if (!r.ok && error) *error = "linuxcnc tape: " + r.errors;
    return done[key] = r;
}

struct Listed {
    CanonMove move;
    int line = 0;  // of the dialect's tape; 0 for rs274's moves
};

bool same(const Point3& a, const Point3& b)
{
    return std::abs(a.x - b.x) <= 1e-9 && std::abs(a.y - b.y) <= 1e-9 && std::abs(a.z - b.z) <= 1e-9;
}

// From the first move after the first tool change on, without the straight
// moves that go nowhere (arcs stay: a whole circle ends where it began).
std::vector<Listed> comparable(const std::vector<CanonMove>& moves, const std::vector<int>& lines)
{
    std::vector<Listed> out;
    for (std::size_t i = 0; i < moves.size(); ++i) {
        const CanonMove& m = moves[i];
        if (m.tool == 0 || (m.kind != CanonMove::Arc && same(m.start, m.end))) continue;
        out.push_back({m, i < lines.size() ? lines[i] : 0});
    }
    return out;
}

QString describe(const CanonMove& m)
{
    static const char* const kinds[] = {"traverse", "feed", "arc"};
    QString s = QString("%1 to X%2 Y%3 Z%4").arg(kinds[m.kind]).arg(m.end.x, 0, 'f', 4).arg(m.end.y, 0, 'f', 4).arg(m.end.z, 0, 'f', 4);
    if (m.kind == CanonMove::Arc)
        s += QString(" centre X%1 Y%2 turn %3").arg(m.centre.x, 0, 'f', 4).arg(m.centre.y, 0, 'f', 4).arg(m.rotation);
    if (m.kind != CanonMove::Traverse) s += QString(" F%1").arg(m.feed, 0, 'f', 2);
    return s + QString(" (T%1, step %2)").arg(m.tool).arg(m.step);
}

// The first difference between rs274's reading of the linuxcnc tape and the
// reader's of the dialect's tape (`tapeText`); nothing when they agree.
std::optional<QString> firstMismatch(const Rs274Result& ref, const DialectMoves& tape, const std::string& tapeText)
{
    if (!tape.error.empty()) return "the reader refuses the tape: " + QString::fromStdString(tape.error);
    if (tape.inches != ref.inches)
        return QString("units: rs274 %1, the tape %2").arg(ref.inches ? "inch" : "mm", tape.inches ? "inch" : "mm");
    // 1.5 units of the last decimal written (3 in mm, 4 in inch); feeds to
    // half a unit of F (1 decimal in mm, 2 in inch) and a hair.
    const double tol = ref.inches ? 1.5e-4 : 1.5e-3;
    const double feedTol = ref.inches ? 0.0051 : 0.051;
    const auto a = comparable(ref.moves, {});
    const auto b = comparable(tape.moves, tape.lines);
    const QStringList tapeLines = QString::fromStdString(tapeText).split('\n');
    const auto report = [&](std::size_t k, const QString& why) {
        QString s = QString("move %1 (of %2 from rs274, %3 from the tape): %4").arg(k).arg(a.size()).arg(b.size()).arg(why);
        if (k < a.size()) s += "\n  rs274 (linuxcnc tape): " + describe(a[k].move);
        if (k < b.size()) {
            s += "\n  dialect tape:          " + describe(b[k].move);
            const int l = b[k].line;
            if (l > 0 && l <= tapeLines.size()) s += QString("\n  tape line %1: %2").arg(l).arg(tapeLines[l - 1]);
        }
        return s;
    };
    if (a.empty()) return QString("rs274 reports no move after the first tool change");
    for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k) {
        const CanonMove& x = a[k].move;
        const CanonMove& y = b[k].move;
        if (x.kind != y.kind) return report(k, "the kind of move differs");
        if (x.tool != y.tool) return report(k, "the tool differs");
        const double ex[] = {x.end.x, x.end.y, x.end.z}, ey[] = {y.end.x, y.end.y, y.end.z};
        for (int i = 0; i < 3; ++i) {
            if (std::isnan(ey[i])) {
                // Only the first move may start from where the tape has not said.
                if (k != 0) return report(k, "the reader does not know where this move ends");
                continue;
            }
            if (!(std::abs(ex[i] - ey[i]) <= tol))
                return report(k, QString("%1 of the end differs by %2").arg("XYZ"[i]).arg(ey[i] - ex[i], 0, 'g', 4));
        }
        if (x.kind == CanonMove::Arc) {
            if (!(std::abs(x.centre.x - y.centre.x) <= tol && std::abs(x.centre.y - y.centre.y) <= tol))
                return report(k, "the arc's centre differs");
            if (x.rotation != y.rotation) return report(k, "the arc's turn differs");
        }
        if (x.kind != CanonMove::Traverse && !(std::abs(x.feed - y.feed) <= feedTol))
            return report(k, QString("the feed rate differs by %1").arg(y.feed - x.feed));
    }
    if (a.size() != b.size()) return report(std::min(a.size(), b.size()), "the number of moves differs");
    if (ref.dwells != tape.dwells) return QString("dwells: rs274 %1, the tape %2").arg(ref.dwells).arg(tape.dwells);
    return std::nullopt;
}

// Hand-written: the same motion in the four languages. G2/DR- and a helix of
// one whole turn (rs274: turn ±1, the end at the start), a flat full circle,
// a dwell, G81 at two holes, then a feed move: G81's F is modal in LinuxCNC,
// so its tape says F150 again; cycle 200's Q206 is not, so the Klartext L
// block needs no F to go on at 150.
const char* const kHandLinuxcnc = R"(G17 G21 G40 G49 G54 G80 G90 G94
G53 G0 Z0
T1 M6
G43 H1
S1000 M3
G0 X10 Y0
Z5
G1 Z0 F100
G2 X0 Y-10 I-10 J0 F200
G3 X10 Y0 Z-1 I0 J10
G2 X10 Y0 Z-2 I-10 J0
G3 X10 Y0 I-10 J0
G1 X20 F150
G4 P0.5
G0 Z5
G98 G81 X30 Y30 Z-4 R1 F80
X40
G80
G1 X50 F150
G0 Z10
M5
G53 G0 Z0
M30
)";

const char* const kHandHaas = R"(%
O01000 (HAND)
N10 G17 G21 G40 G49 G80 G90 G94
(STEP 1: HAND)
N20 G28 G91 Z0.
N30 G90
N40 T1 M06
N50 S1000 M3
N60 G0 G54 X10. Y0.
N70 G43 H1 Z5.
N80 G1 Z0. F100.
N90 G2 X0. Y-10. I-10. J0. F200.
N100 G3 X10. Y0. Z-1. I0. J10.
N110 G2 X10. Y0. Z-2. I-10. J0.
N120 G3 X10. Y0. I-10. J0.
N130 G1 X20. F150.
N140 G4 P0.5
N150 G0 Z5.
N160 G98 G81 X30. Y30. Z-4. R1. F80.
N170 X40.
N180 G80
N185 G1 X50. F150.
N190 G0 Z10.
N200 M5
N210 G28 G91 Z0.
N220 G90
N230 M30
%
)";

const char* const kHandSinumerik = R"(; HAND
N10 G17 G710 G40 G90 G94
N20 G641 ADIS=0.01
; STEP 1: hand
N30 G0 SUPA Z0
N40 T1 M6
N50 D1
N60 S1000 M3
N70 G0 G54 X10 Y0
N80 Z5
N90 G1 Z0 F100
N100 G2 X0 Y-10 I-10 J0 F200
N110 G3 X10 Y0 Z-1 I0 J10
N120 G2 X10 Y0 Z-2 I-10 J0
N130 G3 X10 Y0 I-10 J0
N140 G1 X20 F150
N150 G4 F0.5
N160 G0 Z5
N170 F80
N180 MCALL CYCLE81(5,1,0,-4)
N190 X30 Y30
N200 X40
N210 MCALL
N215 G1 X50 F150
N220 G0 Z10
N230 M5
N240 G0 SUPA Z0 D0
N250 M30
)";

const char* const kHandKlartext = R"(0 BEGIN PGM HAND MM
1 ; STEP 1: hand
2 L Z+0 R0 FMAX M91
3 TOOL CALL 1 Z S1000
4 L X+10 Y+0 R0 FMAX M3
5 L Z+5 R0 FMAX
6 L Z+0 F100
7 CC X+0 Y+0
8 C X+0 Y-10 DR- F200
9 CP IPA+90 IZ-1 DR+
10 CP IPA-360 IZ-1 DR-
11 CP IPA+360 DR+
12 L X+20 F150
13 CYCL DEF 9.0 DWELL TIME
14 CYCL DEF 9.1 DWELL 0.5
15 L Z+5 R0 FMAX
16 CYCL DEF 200 DRILLING ~
  Q200=+0 ;SET-UP CLEARANCE ~
  Q201=-5 ;DEPTH ~
  Q206=+80 ;FEED RATE FOR PLNGNG ~
  Q202=+5 ;PLUNGING DEPTH ~
  Q210=+0 ;DWELL TIME AT TOP ~
  Q203=+1 ;SURFACE COORDINATE ~
  Q204=+4 ;2ND SET-UP CLEARANCE ~
  Q211=+0 ;DWELL TIME AT DEPTH
17 L X+30 Y+30 R0 FMAX M99
18 L X+40 R0 FMAX M99
19 L X+50
20 L Z+10 R0 FMAX M5
21 L Z+0 R0 FMAX M91
22 M30
23 END PGM HAND MM
)";

const char* handTape(const QString& dialect)
{
    return dialect == "haas" ? kHandHaas : dialect == "sinumerik" ? kHandSinumerik : kHandKlartext;
}

// The 1-based line of `text` that holds `part`; 0 when none does.
int lineOf(const std::string& text, const std::string& part)
{
    const auto at = text.find(part);
    if (at == std::string::npos) return 0;
    return static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n')) + 1;
}

}  // namespace

class TestRs274Dialects : public QObject {
    Q_OBJECT
private slots:
    void handWrittenTapesReadAsRs274Does_data()
    {
        QTest::addColumn<QString>("dialect");
        for (const auto& d : kDialects) QTest::newRow(qPrintable(d)) << d;
    }
    void handWrittenTapesReadAsRs274Does()
    {
        QFETCH(QString, dialect);
        const Rs274Result ref = runRs274(withoutMachineMoves(kHandLinuxcnc));
        QVERIFY2(ref.ok, qPrintable(ref.errors));
        // rs274's own view of the whole-turn helix and the flat circle.
        const auto arcs = std::count_if(ref.moves.begin(), ref.moves.end(), [](const CanonMove& m) {
            return m.kind == CanonMove::Arc && std::abs(m.rotation) == 1 && std::abs(m.end.x - m.start.x) < 1e-9 &&
                   std::abs(m.end.y - m.start.y) < 1e-9;
        });
        QCOMPARE(static_cast<int>(arcs), 2);
        QCOMPARE(ref.dwells, 1);
        const std::string text = handTape(dialect);
        const DialectMoves tape = readTape(dialect, text);
        const auto mismatch = firstMismatch(ref, tape, text);
        QVERIFY2(!mismatch, qPrintable(mismatch.value_or(QString())));
        QCOMPARE(comparable(tape.moves, tape.lines).size(), std::size_t{19});
    }

    void readersRefuseWhatTheyDoNotKnow_data()
    {
        QTest::addColumn<QString>("dialect");
        QTest::addColumn<QString>("from");      // in the hand-written tape
        QTest::addColumn<QString>("to");        // what it becomes
        QTest::addColumn<QString>("complaint"); // part of the error
        const auto row = [](const char* name, const char* dialect, const char* from, const char* to, const char* complaint) {
            QTest::newRow(name) << QString(dialect) << QString(from) << QString(to) << QString(complaint);
        };
        row("haas unknown word", "haas", "G1 X20. F150.", "G1 X20. W3. F150.", "'W3.' is not understood");
        row("haas no decimal point", "haas", "N170 X40.", "N170 X40", "without a decimal point");
        row("haas G83 without Q", "haas", "G98 G81", "G98 G83", "G83 needs Q");
        row("haas G18", "haas", "N190 G0 Z10.", "N190 G18 G0 Z10.", "G18 is not understood");
        row("haas wrong H", "haas", "G43 H1 Z5.", "G43 H2 Z5.", "G43 H2 with T1");
        row("haas Z before G43", "haas", "N70 G43 H1 Z5.", "N70 Z5.", "length offset");
        row("haas M99", "haas", "N200 M5", "N200 M99", "M99 calls or leaves a subprogram, whose motion is not on the tape");
        row("sinumerik unknown word", "sinumerik",
            "N140 G1 X20 F150", "N140 G1 X20 F150 TRANS", "'TRANS' is not understood");
        row("haas Q without G83", "haas", "G98 G81 X30. Y30. Z-4. R1. F80.", "G98 G81 X30. Y30. Z-4. R1. Q2. F80.",
            "Q without G83");
        row("haas G76", "haas", "G98 G81", "G98 G76", "G76 is not understood");
        row("sinumerik CYCLE83 chip breaking", "sinumerik", "CYCLE81(5,1,0,-4)", "CYCLE83(5,1,0,-4,,-2,,2,0,0,1,0)", "CYCLE83 with VARI");
        row("sinumerik CYCLE84 left hand", "sinumerik", "CYCLE81(5,1,0,-4)", "CYCLE84(5,1,0,-4,,0,3,,-1.25,0,500,500)",
            "left-hand tapping is not supported");
        row("sinumerik CYCLE86 lift off", "sinumerik", "CYCLE81(5,1,0,-4)", "CYCLE86(5,1,0,-4,,0,3,0.1,0,0,0)", "RPA");
        row("sinumerik CYCLE87", "sinumerik", "CYCLE81(5,1,0,-4)", "CYCLE87(5,1,0,-4,,3)", "is not understood");
        row("sinumerik parenthesis comment", "sinumerik",
            "N150 G4 F0.5", "N150 G4 F0.5 (WAIT)", "'(WAIT)' is not understood");
        row("sinumerik G91", "sinumerik", "N220 G0 Z10", "N220 G91 G0 Z10", "G91 is not understood");
        // SUPA keeps the tool's length: without D0 the tool tip, not the
        // spindle, would go to machine Z0 (docs/post-processors.md).
        row("sinumerik SUPA with D1", "sinumerik", "N240 G0 SUPA Z0 D0", "N240 G0 SUPA Z0", "write D0 in the block");
        row("sinumerik Z after D0", "sinumerik", "N220 G0 Z10", "N220 G0 Z10 D0", "length offset");
        row("klartext unknown word", "heidenhain", "12 L X+20 F150", "12 L X+20 RL F150", "'RL' is not understood");
        row("klartext unknown block", "heidenhain", "1 ; STEP 1: hand", "1 LBL 1", "block not understood");
        row("klartext block number", "heidenhain", "15 L Z+5", "16 L Z+5", "block number 16, expected 15");
        row("klartext unsigned", "heidenhain", "20 L Z+10", "20 L Z10", "a signed number expected");
        row("klartext dwell at depth", "heidenhain", "Q211=+0 ;DWELL TIME AT DEPTH", "Q211=+1 ;DWELL TIME AT DEPTH",
            "dwells in cycle 200 are not supported");
        row("klartext no plunging depth", "heidenhain", "Q202=+5", "Q202=+0", "Q202 (plunging depth) must be positive");
        // A cycle parameter's rapid is MAX on a TNC; FMAX and FAUTO are not values.
        row("klartext FAUTO", "heidenhain", "Q206=+80", "Q206=FAUTO", "Q206=FAUTO is not a TNC's cycle parameter value");
        row("klartext FMAX", "heidenhain", "Q206=+80", "Q206=FMAX", "Q206=FMAX is not a TNC's cycle parameter value");
        row("klartext MAX plunge", "heidenhain", "Q206=+80", "Q206=MAX", "MAX is only a retraction feed");
        row("klartext cycle 203", "heidenhain", "16 CYCL DEF 200 DRILLING ~", "16 CYCL DEF 203 UNIVERSAL DRILLING ~",
            "continuation lines after a block");
        row("klartext continued comment", "heidenhain",
            "16 CYCL DEF 200 DRILLING ~", "16 ; no cycle ~", "continuation lines after a block");
        row("klartext M99 on an arc", "heidenhain",
            "8 C X+0 Y-10 DR- F200", "8 C X+0 Y-10 DR- F200 M99", "M99 is not understood here");
        row("klartext CP against DR", "heidenhain",
            "9 CP IPA+90 IZ-1 DR+", "9 CP IPA+90 IZ-1 DR-", "IPA and DR turn opposite ways");
    }
    // An M word that switches the machine (a program stop, mist coolant, a
    // shop's own) moves nothing: read as no motion, the moves unchanged.
    void aMachineSwitchIsNoMotion()
    {
        const std::string text = handTape("haas");
        for (const char* word : {"N200 M0", "N200 M7", "N200 M51"}) {
            std::string t = text;
            const auto at = t.find("N200 M5");
            QVERIFY(at != std::string::npos);
            t.replace(at, 7, word);
            const DialectMoves tape = readTape("haas", t);
            QVERIFY2(tape.error.empty(), tape.error.c_str());
            QCOMPARE(tape.moves.size(), readTape("haas", text).moves.size());
        }
    }

    void readersRefuseWhatTheyDoNotKnow()
    {
        QFETCH(QString, dialect);
        QFETCH(QString, from);
        QFETCH(QString, to);
        QFETCH(QString, complaint);
        std::string text = handTape(dialect);
        const auto at = text.find(from.toStdString());
        QVERIFY2(at != std::string::npos, qPrintable(from));
        text.replace(at, static_cast<std::size_t>(from.size()), to.toStdString());
        const DialectMoves tape = readTape(dialect, text);
        const QString error = QString::fromStdString(tape.error);
        QVERIFY2(error.contains(complaint), qPrintable("error: " + error));
        QVERIFY2(error.startsWith(QString("line %1:").arg(lineOf(text, to.toStdString()))), qPrintable("error: " + error));
    }

    void anAlteredTapeIsCaught_data()
    {
        QTest::addColumn<QString>("dialect");
        QTest::addColumn<bool>("feed");  // alter a feed rate rather than a coordinate
        for (const auto& d : kDialects) {
            QTest::newRow(qPrintable(d + " coordinate")) << d << false;
            QTest::newRow(qPrintable(d + " feed")) << d << true;
        }
    }
    void anAlteredTapeIsCaught()
    {
        QFETCH(QString, dialect);
        QFETCH(bool, feed);
        QString error;
        const Rs274Result& ref = reference(sourcePath("resources/samples/m4-standard.taiwa"), {}, &error);
        QVERIFY2(ref.ok, qPrintable(error));
        const Tape t = exportTape(sourcePath("resources/samples/m4-standard.taiwa"), dialect, {});
        QVERIFY2(t.error.isEmpty(), qPrintable(t.error));
        const auto agree = firstMismatch(ref, readTape(dialect, t.text), t.text);
        QVERIFY2(!agree, qPrintable(agree.value_or(QString())));

        // A lone X word of a straight feed move, or the first feed word of
        // one: 0.01 mm, 1 mm/min more.
        const QString number = feed ? R"([0-9.]+)" : dialect == "heidenhain" ? R"([-+][0-9.]+)" : R"(-?[0-9.]+)";
        const QString prefix = dialect == "heidenhain" ? R"(^\d+ L )" : R"(^N\d+ (?:G1 )?)";
        const QRegularExpression word(feed ? prefix + ".* F(" + number + ")$" : prefix + "X(" + number + ")$",
                                      QRegularExpression::MultilineOption);
        QString text = QString::fromStdString(t.text);
        const auto m = word.match(text);
        QVERIFY2(m.hasMatch(), "no line to alter");
        const double was = m.captured(1).toDouble();
        QString now = QString::number(was + (feed ? 1.0 : 0.01), 'f', feed ? 1 : 3);
        if (dialect == "heidenhain" && !feed && !now.startsWith('-')) now = "+" + now;
        if (dialect == "haas" && !now.contains('.')) now += '.';
        text.replace(m.capturedStart(1), m.capturedLength(1), now);
        const std::string altered = text.toStdString();
        const auto mismatch = firstMismatch(ref, readTape(dialect, altered), altered);
        QVERIFY2(mismatch, "the altered tape passes");
        const QString before = text.mid(m.capturedStart(), m.capturedLength() - m.capturedLength(1));  // up to the number
        const int line = lineOf(altered, (before + now).toStdString());
        QVERIFY2(mismatch->contains(QString("tape line %1:").arg(line)), qPrintable(*mismatch));
        QVERIFY2(mismatch->contains(feed ? "feed rate differs" : "X of the end differs"), qPrintable(*mismatch));
    }

    void samplesAgreeWithRs274_data()
    {
        QTest::addColumn<QString>("job");
        QTest::addColumn<QString>("units");  // "" the job's own
        QTest::addColumn<QString>("dialect");
        for (const auto& f : QDir(sourcePath("resources/samples")).entryInfoList({"*.taiwa"}, QDir::Files, QDir::Name)) {
            const std::string text = readFile(f.absoluteFilePath());
            if (text.find("\"shape\": \"bar\"") != std::string::npos) continue;  // lathe jobs
            if (text.find("PROBE") != std::string::npos) continue;               // probing units
            for (const auto& d : kDialects)
                QTest::newRow(qPrintable(f.completeBaseName() + " " + d)) << f.absoluteFilePath() << QString() << d;
        }
        for (const char* job : {"m4-standard", "plate"})
            for (const auto& d : kDialects)
                QTest::newRow(qPrintable(QString("%1 inch %2").arg(job, d)))
                    << sourcePath(QString("resources/samples/%1.taiwa").arg(job)) << QString("inch") << d;
    }
    void samplesAgreeWithRs274()
    {
        QFETCH(QString, job);
        QFETCH(QString, units);
        QFETCH(QString, dialect);
        QString error;
        const Rs274Result& ref = reference(job, units, &error);
        QVERIFY2(ref.ok, qPrintable(error));
        if (units == "inch" || job.endsWith("bracket-inch.taiwa")) QVERIFY(ref.inches);
        const Tape t = exportTape(job, dialect, units);
        QVERIFY2(t.error.isEmpty(), qPrintable(t.error));
        const DialectMoves tape = readTape(dialect, t.text);
        const auto mismatch = firstMismatch(ref, tape, t.text);
        QVERIFY2(!mismatch, qPrintable(mismatch.value_or(QString())));
    }
};

QTEST_APPLESS_MAIN(TestRs274Dialects)
#include "test_rs274_dialects.moc"
