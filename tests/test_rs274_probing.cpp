// The `linuxcnc` probing cycle (post/probe_program.h) judged by LinuxCNC's
// own interpreter, run against simulated workpieces: round bosses and bores,
// rectangular blocks and pockets of known centre, size and top face. The
// standalone interpreter's probe never trips (its G38 ends at the target
// with #5070 = 0), so the simulation answers each touch in turn: the
// program is run, its next STRAIGHT_PROBE found, the point where the stylus
// ball meets the workpiece along that move computed, and the touch's
// target moved there and its #5070 test answered "found" in a copy of the
// program; then the next touch. The last run must pass with no error, and
// the work offset it writes (G10 L20, SET_G5X_OFFSET) must be the true
// centre and top face within 1 µm; the size it prints, the true size.
// The untouched program stops at its first touch with its message.
#include "job/job_file.h"
#include "pipeline/pipeline.h"
#include "post/probe_program.h"
#include "tools/tool_library.h"
#include "support/rs274.h"
#include "support/support.h"

#include <QDir>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <functional>
#include <optional>

using namespace taiwa;
using namespace taiwa::test;

namespace {

constexpr double kBall = 2.0;
// tests/data/rs274/params.var: G54 is active, its offset (0, 0, -100 mm);
// the tool starts at machine zero, at (0, 0, 100) in G54, where the
// canonical calls are.
const Point3 kG54{0, 0, -100};

// A workpiece in the interpreter's canonical coordinates.
struct Part {
    bool round = true, inside = false;
    Point2 centre;
    double sizeX = 0, sizeY = 0;  // diameter, or width and length
    double top = 0;
    // Signed distance of a point in the plane to the part's outline,
    // positive outside the material the ball may be in.
    double clearance(Point2 p) const
    {
        double d;
        if (round) {
            d = distance(p, centre) - sizeX / 2;
        } else {
            const double qx = std::abs(p.x - centre.x) - sizeX / 2, qy = std::abs(p.y - centre.y) - sizeY / 2;
            d = std::hypot(std::max(qx, 0.0), std::max(qy, 0.0)) + std::min(std::max(qx, qy), 0.0);
        }
        return inside ? -d : d;
    }
};

struct Probe {
    Point3 from, to;
};

std::vector<double> numbers(const QString& args)
{
    std::vector<double> v;
    for (const auto& a : args.split(',')) v.push_back(a.trimmed().toDouble());
    return v;
}

// The probing moves of a run, each with where it started.
std::vector<Probe> probes(const Rs274Result& r)
{
    static const QRegularExpression call(R"(^\s*\d+\s+N[.0-9]+\s+([A-Z_0-9]+)\((.*)\)\s*$)");
    std::vector<Probe> out;
    std::optional<Point3> at = Point3{-kG54.x, -kG54.y, -kG54.z};
    for (const QString& line : r.canon) {
        const auto m = call.match(line);
        if (!m.hasMatch()) continue;
        const QString name = m.captured(1);
        if (name == "STRAIGHT_TRAVERSE" || name == "STRAIGHT_FEED" || name == "STRAIGHT_PROBE") {
            const auto v = numbers(m.captured(2));
            const Point3 to{v[0], v[1], v[2]};
            if (name == "STRAIGHT_PROBE") out.push_back({at.value_or(to), to});
            at = to;
        }
    }
    return out;
}

// Where along the move the ball first meets the part (the ball's lowest
// point meets the top face; its side meets the outline).
Point3 contact(const Part& part, const Probe& p)
{
    if (std::abs(p.to.x - p.from.x) < 1e-9 && std::abs(p.to.y - p.from.y) < 1e-9) return {p.from.x, p.from.y, part.top};
    const auto gap = [&](double t) {
        const Point2 q{p.from.x + t * (p.to.x - p.from.x), p.from.y + t * (p.to.y - p.from.y)};
        return part.clearance(q) - kBall;
    };
    double lo = 0, hi = 1;
    if (gap(0) <= 0) qFatal("the touch starts in contact");
    for (int k = 1; k <= 1000; ++k)  // the first bracket
        if (gap(k / 1000.0) <= 0) {
            lo = (k - 1) / 1000.0, hi = k / 1000.0;
            break;
        } else if (k == 1000) {
            qFatal("the touch misses the part");
        }
    for (int it = 0; it < 100; ++it) (gap(0.5 * (lo + hi)) > 0 ? lo : hi) = 0.5 * (lo + hi);
    return {p.from.x + hi * (p.to.x - p.from.x), p.from.y + hi * (p.to.y - p.from.y), p.from.z + hi * (p.to.z - p.from.z)};
}

struct Simulated {
    Rs274Result last;
    std::string program;
    int touches = 0;
};

// Answers the touches one by one (see the file comment). `place` puts the
// part given where the first touch starts.
Simulated simulate(std::string program, const std::function<Part(Point3)>& place)
{
    Simulated s;
    std::optional<Part> part;
    for (int k = 0;; ++k) {
        s.last = runRs274(program);
        const auto ps = probes(s.last);
        if (static_cast<int>(ps.size()) <= k) break;  // no further touch: done
        if (!part) part = place(ps[0].from);
        const Point3 hit = contact(*part, ps[static_cast<std::size_t>(k)]);
        // The k-th G38.3 line: its target moved onto the contact (the move
        // keeps its direction: the shift is along it) and its test answered.
        std::size_t at = 0;
        for (int n = 0; n <= k; ++n) at = program.find("G38.3 ", n ? at + 1 : 0);
        const std::size_t end = program.find('\n', at);
        const std::string line = program.substr(at, end - at);
        const char axis = line[6];
        const double shift = axis == 'X' ? hit.x - ps[k].to.x : axis == 'Y' ? hit.y - ps[k].to.y : hit.z - ps[k].to.z;
        const std::string moved = line.substr(0, 7) + "[" + line.substr(7) + " + [" + std::to_string(shift) + "]]";
        program.replace(at, end - at, moved);
        const std::string test = "[#5070 EQ 0]";
        const std::size_t t = program.find(test, at);
        program.replace(t, test.size(), "[1 EQ 0]");
        s.touches = k + 1;
    }
    s.program = program;
    return s;
}

// The last offset of coordinate system `index` (1 = G54) the run set, in
// machine coordinates.
std::optional<std::vector<double>> offsetWritten(const Rs274Result& r, int index)
{
    std::optional<std::vector<double>> last;
    for (const QString& line : r.canon)
        if (line.contains("SET_G5X_OFFSET(" + QString::number(index) + ",")) {
            const QString args = line.section('(', 1).section(')', 0, 0);
            auto v = numbers(args);
            v.erase(v.begin());
            last = v;
        }
    return last;
}

WorkSetup setup(bool round, bool inside, double sizeX, double sizeY)
{
    WorkSetup w;
    w.round = round;
    w.inside = inside;
    w.tool = 90;
    w.ballRadius = kBall;
    w.sizeX = sizeX;
    w.sizeY = sizeY;
    w.touchDepth = 5;
    w.clearance = 5;
    w.search = 10;
    w.feed = 100;
    return w;
}

}  // namespace

class TestRs274Probing : public QObject {
    Q_OBJECT
private slots:
    void cycleFindsTheTrueCentre_data()
    {
        QTest::addColumn<bool>("round");
        QTest::addColumn<bool>("inside");
        QTest::addColumn<double>("trueX");
        QTest::addColumn<double>("trueY");
        QTest::addColumn<QString>("offset");
        QTest::addColumn<int>("index");
        // Nominal 80 (x 60); the parts are 0.06 larger or smaller and stand
        // off the start by (1.217, -0.934).
        QTest::newRow("boss") << true << false << 80.06 << 80.06 << "G54" << 1;
        QTest::newRow("bore") << true << true << 79.97 << 79.97 << "G55" << 2;
        QTest::newRow("block") << false << false << 80.05 << 59.96 << "G59.3" << 9;
        QTest::newRow("pocket") << false << true << 79.93 << 60.04 << "G57" << 4;
    }
    void cycleFindsTheTrueCentre()
    {
        QFETCH(bool, round);
        QFETCH(bool, inside);
        QFETCH(double, trueX);
        QFETCH(double, trueY);
        QFETCH(QString, offset);
        QFETCH(int, index);
        PostOptions o;
        o.dialect = "linuxcnc";
        o.workOffset = offset.toStdString();
        o.programName = "probing test";
        const std::string program = probingProgram(setup(round, inside, 80, 60), o);
        Part part;
        const auto place = [&](Point3 start) {
            part.round = round;
            part.inside = inside;
            part.sizeX = trueX;
            part.sizeY = trueY;
            // The first touch (the top face) starts above the centre, or
            // (bores and pockets) beside the opening, 45 mm left of it.
            const double besideX = inside ? 45.0 : 0.0;
            part.centre = {start.x + besideX + 1.217, start.y - 0.934};
            part.top = start.z - 2.5;
            return part;
        };
        const Simulated s = simulate(program, place);
        QVERIFY2(s.last.ok, qPrintable(s.last.errors + "\n" + QString::fromStdString(s.program)));
        QCOMPARE(s.touches, 5);
        const auto written = offsetWritten(s.last, index);
        QVERIFY2(written, qPrintable(s.last.canon.join('\n')));
        // In machine coordinates: the part's place in G54 plus G54's offset.
        const Point3 truth{part.centre.x + kG54.x, part.centre.y + kG54.y, part.top + kG54.z};
        QVERIFY2(std::abs((*written)[0] - truth.x) < 1e-3 && std::abs((*written)[1] - truth.y) < 1e-3,
                 qPrintable(QString("offset %1 %2, true centre %3 %4").arg((*written)[0]).arg((*written)[1]).arg(truth.x).arg(truth.y)));
        QVERIFY2(std::abs((*written)[2] - truth.z) < 1e-3, qPrintable(QString("Z %1, top %2").arg((*written)[2]).arg(truth.z)));
        // The size it prints, ball accounted for.
        const QString said = s.last.out.section("centre found;", 1).section('\n', 0, 0);
        const QRegularExpression number(R"(-?\d+\.\d+)");
        std::vector<double> sizes;
        for (auto it = number.globalMatch(said); it.hasNext();) sizes.push_back(it.next().captured().toDouble());
        QVERIFY2(sizes.size() >= 2, qPrintable(said));
        if (round)  // "diameter D (through the centre, along Y), across X c (a chord off the centre)"
            QVERIFY2(std::abs(sizes[0] - trueX) < 1e-3 && sizes[1] < sizes[0] && sizes[1] > sizes[0] - 0.1, qPrintable(said));
        else
            QVERIFY2(std::abs(sizes[0] - trueX) < 1e-3 && std::abs(sizes[1] - trueY) < 1e-3, qPrintable(said));
    }

    // Every probing sample's linuxcnc programs as exported: the setting
    // program passes and sets the centre the touches measured (its offsets
    // are in machine coordinates, as G10 L2 takes them); the cycle passes
    // against its nominal part.
    void samplePrograms()
    {
        const auto files = QDir(sourcePath("resources/samples")).entryInfoList({"probe-*.taiwa"}, QDir::Files, QDir::Name);
        QVERIFY(files.size() >= 3);
        for (const QFileInfo& f : files) {
            QTemporaryDir out;
            const auto r = runTaiwa({"export", f.absoluteFilePath(), "--out", out.path(), "--dialect", "linuxcnc"});
            QVERIFY2(r.exitCode == 0, qPrintable(r.err));
            const auto job = readJobFile(f.absoluteFilePath().toStdString());
            const Plan plan = planJob(*job.job, TechnologyTable::builtIn(), defaultToolLibrary());
            QCOMPARE(plan.setups.size(), std::size_t(1));
            const WorkSetup& w = plan.setups.front();
            const QString stem = QDir(out.path()).filePath(f.completeBaseName() + ".u" + QString::number(w.unit + 1));
            if (w.measured) {
                const Rs274Result set = runRs274(readFile(stem + ".setting.nc"));
                QVERIFY2(set.ok, qPrintable(f.fileName() + ": " + set.errors));
                const int index = plan.job.workOffset == "G55" ? 2 : 1;
                const auto written = offsetWritten(set, index);
                QVERIFY(written);
                QVERIFY(std::abs((*written)[0] - w.measured->centre.x) < 1e-3 && std::abs((*written)[1] - w.measured->centre.y) < 1e-3);
                if (w.measured->top) QVERIFY(std::abs((*written)[2] - *w.measured->top) < 1e-3);
            }
            const Simulated s = simulate(readFile(stem + ".probe.nc"), [&](Point3 start) {
                Part part;
                part.round = w.round;
                part.inside = w.inside;
                part.sizeX = w.sizeX;
                part.sizeY = w.sizeY;
                const double beside = w.inside ? w.sizeX / 2 + w.clearance : 0.0;
                part.centre = {start.x + beside + 0.4, start.y - 0.3};
                part.top = start.z - 1.0;
                return part;
            });
            QVERIFY2(s.last.ok, qPrintable(f.fileName() + ": " + s.last.errors));
            QCOMPARE(s.touches, 5);
        }
    }

    // Untouched, the standalone interpreter's probe never trips: the cycle
    // stops at its first touch with its message.
    void touchNotFoundStopsWithItsMessage()
    {
        PostOptions o;
        o.dialect = "linuxcnc";
        const Rs274Result r = runRs274(probingProgram(setup(true, false, 50, 50), o));
        QVERIFY(!r.ok);
        QVERIFY2((r.out + r.err).contains("touch 1: no top face within 15 mm below the start"), qPrintable(r.out + r.err));
        // Nothing set after the touch (the interpreter states G54's offset at its start).
        const QString afterTouch = r.out.section("STRAIGHT_PROBE", 1);
        QVERIFY(!afterTouch.isEmpty() && !afterTouch.contains("SET_G5X_OFFSET"));
    }
};

QTEST_GUILESS_MAIN(TestRs274Probing)
#include "test_rs274_probing.moc"
