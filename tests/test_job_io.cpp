// Job files (interfaces.md "Job files"), the files that are jobs: every
// sample reads, passes input processing, validates against the shipped JSON
// Schema (which refuses every bad job) and writes back byte for byte;
// hand-built jobs survive writeJob/readJob; canonical text and defaults.
// Refusals are in test_job_refusals.cpp. TAIWA_UPDATE_GOLDEN=1 rewrites the
// samples canonically (review the diff before committing).
#include "modules/m2d/m2d.h"
#include "modules/area/area.h"
#include "modules/cp/cp.h"
#include "modules/face/face.h"
#include "modules/holes/holes.h"
#include "modules/m4/m4.h"
#include "modules/probe/probe.h"
#include "modules/side/side.h"
#include "modules/surface/surface.h"
#include "modules/turn/turn.h"
#include "job/job_check.h"
#include "job/job_file.h"
#include "pipeline/pipeline.h"
#include "support/support.h"
#include "tools/tool_library.h"

#include <QDir>
#include <QFileInfo>
#include <QProcess>
#include <QtTest>

#include <set>


using namespace taiwa;
using namespace taiwa::test;

namespace {


QStringList filesIn(const QString& dir, const QString& pattern)
{
    QStringList out;
    for (const auto& f : QDir(dir).entryInfoList({pattern}, QDir::Files, QDir::Name)) out << f.absoluteFilePath();
    return out;
}

QStringList samples() { return filesIn(sourcePath("resources/samples"), "*.taiwa"); }

std::string diagnosticLines(const QString& fileName, const Diagnostics& ds)
{
    std::string out;
    for (const auto& d : ds) out += format(fileName.toStdString(), d) + "\n";
    return out;
}

M4Pocket pocket()
{
    M4Pocket p;
    p.corners = {{{20, 20}, {120.5, 20}, {120.5, 80.25}, {20, 80.25}}};
    p.cornerRadius = 8;
    p.depth = 12.7;
    return p;
}

Job handBuilt()
{
    Job j;
    j.name = "Hand built \"quoted\" ジョブ";
    j.material = "steel-s45c";
    j.machine = "vmc-2";
    j.workOffset = "G55";
    j.stock = {-10.5, 0.1, 200, 150.125, 40};
    M4Pocket a = pocket();
    a.taper = 2.5;
    a.toolUse = 7;
    a.wallFinish = 3;
    a.pilotHole = 9;
    a.tools = {{"wall", 21}, {"floor", 12}};
    M2DPocket b;
    b.corner = {1.0 / 3.0, 1e-7};
    b.lengthX = 123456.789;
    b.lengthY = 60;
    b.depth = 20;
    b.theta1 = 10;
    b.cornerRadius = 6;
    b.scallop = 0.002;
    M2DPocket c = b;
    c.theta2 = 0.0;  // given, even though equal to the default angle of 0
    c.toolUse = 9;
    j.units = {{"A", a}, {"", b}, {"C", c}};
    return j;
}

// Runs python3 with jsonschema: validates `files` against the shipped
// schema, prints one line "OK name", "BAD name" or "UNJUDGED name" per file.
std::optional<QString> validate(const QStringList& files)
{
    const char* script = R"(
import json, sys
import jsonschema
schema = json.load(open(sys.argv[1]))
cls = jsonschema.validators.validator_for(schema)
cls.check_schema(schema)
v = cls(schema)
for f in sys.argv[2:]:
    def no_repeats(pairs):
        keys = [k for k, _ in pairs]
        if len(keys) != len(set(keys)): raise ValueError('repeated key')
        return dict(pairs)
    try:
        doc = json.load(open(f, encoding='utf-8'), object_pairs_hook=no_repeats)
    except Exception:
        print('UNJUDGED', f); continue  # not JSON, or what a schema cannot see (repeated keys)
    errors = list(v.iter_errors(doc))
    print(('BAD ' if errors else 'OK ') + f)
    for e in errors[:3]: print('   ', list(e.absolute_path), e.message[:200])
)";
    QProcess p;
    p.start("/usr/bin/python3", QStringList{"-c", script, sourcePath("resources/schema/taiwa-job.schema.json")} + files);
    if (!p.waitForFinished(60000)) return std::nullopt;
    const QString err = QString::fromUtf8(p.readAllStandardError());
    if (err.contains("No module named")) return std::nullopt;
    return QString::fromUtf8(p.readAllStandardOutput()) + err;
}

}  // namespace

class TestJobIo : public QObject {
    Q_OBJECT
private slots:
    void everySampleReadsAndWritesBackByteForByte()
    {
        const QStringList files = samples();
        QVERIFY2(files.size() >= 15, "the samples are missing");
        for (const auto& f : files) {
            const std::string text = readFile(f);
            const JobReadResult r = readJob(text);
            QVERIFY2(r.job && r.diagnostics.empty(), qPrintable(f + ": " + QString::fromStdString(diagnosticLines(f, r.diagnostics))));
            if (rewroteGolden(f, writeJob(*r.job))) continue;
            QCOMPARE(writeJob(*r.job), text);
            QVERIFY(readJobFile(f.toStdString()).job == r.job);
        }
    }

    void everySamplePassesInputProcessing()
    {
        for (const auto& f : samples()) {
            const JobReadResult r = readJobFile(f.toStdString());
            QVERIFY(r.job);
            const Diagnostics ds = checkJob(*r.job, TechnologyTable::builtIn(), defaultToolLibrary());
            // Nothing but the report of what drawn passes leave unswept (a warning, shown on purpose).
            const bool onlyUnswept = std::all_of(ds.begin(), ds.end(), [](const Diagnostic& d) {
                return d.severity == Severity::Warning && d.module == "AREA" && d.field == "points";
            });
            QVERIFY2(onlyUnswept, qPrintable(QString::fromStdString(diagnosticLines(QFileInfo(f).fileName(), ds))));
            QVERIFY2(TechnologyTable::builtIn().find(r.job->material), qPrintable(f));
        }
    }

    void samplesCoverEveryCode()
    {
        std::set<std::string> seen;  // "M4 U1 F2 H9 taper", "M2D U9 H9", ...
        bool inch = false;
        for (const auto& f : samples()) {
            const Job job = *readJobFile(f.toStdString()).job;
            inch = inch || job.lengthUnit == LengthUnit::Inch;
            for (const auto& u : job.units) {
                if (const auto* m = (u.module).getIf<M4Pocket>()) {
                    seen.insert("M4 U" + std::to_string(m->toolUse));
                    seen.insert("M4 F" + std::to_string(m->wallFinish));
                    seen.insert("M4 H" + std::to_string(m->pilotHole));
                    if (m->taper > 0) seen.insert("M4 taper F" + std::to_string(m->wallFinish));
                } else if (const auto* p = (u.module).getIf<ProbeUnit>()) {
                    seen.insert("PROBE shape" + std::to_string(p->shape) + " where" + std::to_string(p->where));
                    seen.insert(p->x[1] ? "PROBE touches" : "PROBE cycle only");
                } else if (const auto* t = (u.module).getIf<TurnUnit>()) {
                    seen.insert(t->profile.side == turning::ProfileSide::Inner ? "TURN inner" : "TURN outer");
                } else if (const auto* c = (u.module).getIf<ContourPocket>()) {
                    seen.insert("CP U" + std::to_string(c->toolUse));
                    if (!c->contours.islands.empty()) seen.insert("CP islands");
                } else if (const auto* a = (u.module).getIf<AreaClearing>()) {
                    seen.insert(a->area.islands.empty() ? "AREA" : "AREA islands");
                } else if (const auto* h = (u.module).getIf<HolePattern>()) {
                    seen.insert("HOLES " + h->pattern);
                    seen.insert("HOLES " + h->hole);
                } else if (const auto* fa = (u.module).getIf<FaceUnit>()) {
                    seen.insert("FACE pattern" + std::to_string(fa->pattern));
                    if (fa->margin > 0) seen.insert("FACE margin");
                    if (fa->tools.count("face")) seen.insert("FACE pinned");
                } else if (const auto* sm = (u.module).getIf<SideMill>()) {
                    seen.insert(std::string("SIDE ") + (sm->side == 1 ? "left" : "right") + (sm->direction == 1 ? " climb" : " conventional") + " F" + std::to_string(sm->wallFinish));
                } else if ((u.module).getIf<SurfaceUnit>()) {
                    seen.insert("SURFACE");
                } else {
                    const auto& d = (u.module).as<M2DPocket>();
                    seen.insert("M2D U" + std::to_string(d.toolUse) + " H" + std::to_string(d.pilotHole));
                    if (d.theta2) seen.insert("M2D theta2");
                }
            }
        }
        QVERIFY(inch);
        for (const char* want : {"M4 U1", "M4 U6", "M4 U7", "M4 U8", "M4 U9", "M4 F1", "M4 F2", "M4 F3", "M4 H0", "M4 H9",
                                 "M4 taper F1", "M4 taper F3", "M2D U1 H0", "M2D U9 H9", "M2D theta2", "PROBE shape1 where1",
                                 "PROBE shape1 where2", "PROBE shape2 where1", "PROBE touches", "PROBE cycle only", "TURN outer", "TURN inner",
                                 "CP U1", "CP islands", "HOLES single", "HOLES grid", "HOLES bolt circle", "HOLES drilled",
                                 "HOLES tapped", "HOLES reamed", "HOLES bored", "AREA islands", "FACE pattern1", "FACE pattern2",
                                 "FACE margin", "FACE pinned",
                                 "SIDE left climb F1", "SIDE right conventional F2", "SURFACE"})
            QVERIFY2(seen.count(want), want);
    }

    // The lathe samples show every case of seed 001 once planned: each
    // neighbour rule, each groove kind typed and identified, the adjustment
    // typed and taken from the tool's nose radius.
    void latheSamplesCoverEveryCaseOfTheGrindingAllowance()
    {
        std::set<std::string> seen;
        for (const auto& f : samples()) {
            const Job job = *readJobFile(f.toStdString()).job;
            if (!job.bar) continue;
            const Plan plan = planJob(job, TechnologyTable::builtIn(), defaultToolLibrary());
            QVERIFY2(plan.ok(), qPrintable(f));
            for (const auto& part : plan.turned)
                for (const auto& row : part.deformed.rows)
                    for (const auto* end : {&row.start, &row.end}) {
                        seen.insert(std::string("joint ") + turning::toKey(end->joint));
                        if (end->groove)
                            seen.insert(std::string("groove ") + turning::toKey(end->groove->kind) +
                                        (end->groove->identified ? " identified" : " typed"));
                        if (end->joint == turning::Joint::Tangent)
                            seen.insert(end->adjustmentFrom == "typed" ? "adjustment typed" : "adjustment from tool");
                    }
        }
        for (const char* want : {"joint free end", "joint 0-90", "joint 90-180", "joint 180", "joint above 180",
                                 "joint both ground", "groove lateral identified", "groove longitudinal identified", "groove ring identified",
                                 "groove lateral typed", "adjustment typed", "adjustment from tool"})
            QVERIFY2(seen.count(want), want);
    }

    // Version 2 only when the job names its dialect: a job without one is
    // still written as version 1 (a program of version 1 reads it).
    void theDialectIsVersionTwo()
    {
        Job j = handBuilt();
        QVERIFY(writeJob(j).find("\"version\": 1,") != std::string::npos);
        j.dialect = "fanuc";
        const std::string text = writeJob(j);
        QVERIFY(text.find("\"version\": 2,") != std::string::npos);
        QVERIFY(text.find("\"dialect\": \"fanuc\"") != std::string::npos);
        const JobReadResult back = readJob(text);
        QVERIFY(back.job && *back.job == j);
    }

    // Version 3 only for lathe jobs: every milling sample is still version 1
    // or 2 on disk and when written, so older programs read them as before,
    // but for one that gives its clamping (version 4: plate.taiwa).
    void latheJobsAreVersionThreeAndOnlyThey()
    {
        int lathe = 0, milling = 0;
        for (const auto& f : samples()) {
            const std::string text = readFile(f);
            const Job job = *readJob(text).job;
            const bool isLathe = job.bar.has_value();
            (isLathe ? lathe : milling)++;
            const bool three = text.find("\"version\": 3,") != std::string::npos;
            QVERIFY2(three == isLathe, qPrintable(f));
            // Figure elements and the contour, hole and face units are version 5.
            const bool five = !job.figure.empty() || std::any_of(job.units.begin(), job.units.end(), [](const MachiningUnit& u) {
                const std::string name = u.module.name();
                return name == "CP" || name == "HOLES" || name == "FACE" || name == "AREA" || name == "SIDE" || name == "SURFACE";
            });
            QCOMPARE(formatVersionFor(job), five ? 5 : job.clamping ? 4 : isLathe ? 3 : (job.dialect.empty() ? 1 : 2));
            QVERIFY2(five == (text.find("\"version\": 5,") != std::string::npos), qPrintable(f));
            QVERIFY2(job.clamping.has_value() == (text.find("\"version\": 4,") != std::string::npos), qPrintable(f));
        }
        QVERIFY(lathe >= 5 && milling >= 15);
    }

    // The block's clamping: version 4, written after the stock, read back
    // the same, converted with the job's lengths; a bad value refused
    // naming its field.
    void theClampingIsVersionFourAndRoundTrips()
    {
        Job j = handBuilt();
        j.clamping = Clamping{Clamping::Grip::X, 12.5};
        const std::string text = writeJob(j);
        QVERIFY(text.find("\"version\": 4,") != std::string::npos);
        QVERIFY2(text.find("  \"clamping\": {\n    \"fixture\": \"vice\",\n    \"grip\": \"x\",\n    \"height\": 12.5\n  },\n") !=
                     std::string::npos,
                 text.c_str());
        QVERIFY(text.find("\"stock\"") < text.find("\"clamping\""));
        const JobReadResult back = readJob(text);
        QVERIFY2(back.job, qPrintable(QString::fromStdString(diagnosticLines("job", back.diagnostics))));
        QVERIFY(*back.job == j);
        QCOMPARE(writeJob(*back.job), text);
        j.clamping->grip = Clamping::Grip::Y;
        QCOMPARE(readJob(writeJob(j)).job->clamping->grip, Clamping::Grip::Y);
        j.lengthUnit = LengthUnit::Inch;
        QCOMPARE(toMillimetres(j).clamping->height, 12.5 * 25.4);
        j.clamping.reset();
        QVERIFY(writeJob(j).find("clamping") == std::string::npos);

        const std::string good = "\"clamping\": {\"fixture\": \"vice\", \"grip\": \"x\", \"height\": 12.5}";
        const std::pair<std::string, std::string> bad[] = {
            {"\"clamping\": {\"fixture\": \"vice\", \"grip\": \"z\", \"height\": 12.5}", "job clamping.grip: "},
            {"\"clamping\": {\"fixture\": \"vice\", \"grip\": \"x\", \"height\": \"12\"}", "job clamping.height: must be a number"},
            {"\"clamping\": {\"fixture\": \"vice\", \"grip\": \"x\"}", "job clamping.height: "},
            {"\"clamping\": {\"fixture\": \"clamp\", \"grip\": \"x\", \"height\": 12.5}", "job clamping.fixture: "},
            {"\"clamping\": {\"fixture\": \"vice\", \"grip\": \"x\", \"height\": 12.5, \"depth\": 5}", "job clamping.depth: "},
            {"\"clamping\": true", "job clamping: must be an object"},
        };
        const std::string base = writeJob(*back.job);
        const std::size_t at = base.find("\"clamping\"");
        const std::size_t end = base.find("},\n", at) + 1;
        QVERIFY(readJob(std::string(base).replace(at, end - at, good)).job);
        for (const auto& [clamping, expected] : bad) {
            const JobReadResult r = readJob(std::string(base).replace(at, end - at, clamping));
            const std::string lines = diagnosticLines("j", r.diagnostics);
            QVERIFY2(!r.job && lines.starts_with("j: " + expected), lines.c_str());
        }
    }

    void handBuiltJobsRoundTrip()
    {
        Job inch = handBuilt();
        inch.lengthUnit = LengthUnit::Inch;
        inch.technology.alpha2 = 0.012;
        inch.technology.gamma = 0.45;
        inch.technology.alpha1 = 0.04;
        Job empty;
        empty.name = "";
        Job overrides = handBuilt();
        overrides.technology = {0.5, 0.25, 0.05, 0.1, 1.25, 0.3};
        for (const Job& j : {handBuilt(), inch, empty, overrides}) {
            const std::string text = writeJob(j);
            const JobReadResult r = readJob(text);
            QVERIFY2(r.job, qPrintable(QString::fromStdString(diagnosticLines("job", r.diagnostics))));
            QVERIFY(*r.job == j);
            QCOMPARE(writeJob(*r.job), text);
        }
    }

    void canonicalTextIsFixed()
    {
        Job j;
        j.name = "x";
        M2DPocket d;
        d.corner = {0.1, 2};
        d.lengthX = 1e21;
        d.theta2 = 30;
        j.units = {{"", d}};
        const std::string text = writeJob(j);
        // Key order of the format, whole numbers without ".0", points on one line.
        QVERIFY(text.starts_with("{\n  \"format\": \"taiwa-job\",\n  \"version\": 1,\n  \"name\": \"x\",\n  \"lengthUnit\": \"mm\","));
        QVERIFY(text.find("\"stock\": {\n    \"shape\": \"block\",\n    \"x\": 0,\n") != std::string::npos);
        QVERIFY(text.find("\"corner\": [0.1, 2],\n      \"L1\": 1e+21,\n      \"L2\": 0,") != std::string::npos);
        QVERIFY(text.find("\"theta1\": 0,\n      \"theta2\": 30,\n      \"cornerRadius\": 0,") != std::string::npos);
        QVERIFY(text.find("technology") == std::string::npos);  // no overrides: not written
        QVERIFY(text.find("tools") == std::string::npos);       // no pins: not written
        QVERIFY(text.ends_with("}\n"));
    }

    void optionalFieldsTakeTheirDefaults()
    {
        const JobReadResult r = readJob(R"({"format": "taiwa-job", "version": 1, "lengthUnit": "mm",
            "material": "pom", "stock": {"shape": "block", "width": 100, "length": 80, "height": 20},
            "units": [{"module": "M4", "corners": [[10,10],[60,10],[60,50],[10,50]], "cornerRadius": 5, "depth": 5, "U": 1},
                      {"module": "M2D", "corner": [70,10], "L1": 25, "L2": 60, "depth": 4, "theta1": 10,
                       "cornerRadius": 4, "U": 9}]})");
        QVERIFY(r.job);
        const Job& j = *r.job;
        QCOMPARE(j.name, std::string());
        QCOMPARE(j.machine, std::string("vmc"));
        QCOMPARE(j.workOffset, std::string("G54"));
        QCOMPARE(j.stock.x, 0.0);
        QVERIFY(j.technology.empty());
        const auto& m = (j.units[0].module).as<M4Pocket>();
        QCOMPARE(m.taper, 0.0);
        QCOMPARE(m.wallFinish, 1);
        QCOMPARE(m.pilotHole, 0);
        QVERIFY(m.tools.empty());
        const auto& d = (j.units[1].module).as<M2DPocket>();
        QVERIFY(!d.theta2);
        QCOMPARE(d.scallop, 0.01);
        QCOMPARE(d.pilotHole, 0);
    }

    void codesAreKeptAsTyped()
    {
        // Out-of-table codes are input processing's business: the reader keeps them.
        std::string text = writeJob(handBuilt());
        text.replace(text.find("\"U\": 7"), 6, "\"U\": 4");
        text.replace(text.find("\"F\": 3"), 6, "\"F\": 7.0");
        const JobReadResult r = readJob(text);
        QVERIFY(r.job);
        QCOMPARE((r.job->units[0].module).as<M4Pocket>().toolUse, 4);
        QCOMPARE((r.job->units[0].module).as<M4Pocket>().wallFinish, 7);
    }

    void hugeNumbersAreKeptOrRefusedNeverCrash()
    {
        std::string text = writeJob(handBuilt());
        text.replace(text.find("\"depth\": 12.7"), 13, "\"depth\": 1.7976931348623157e308");
        const JobReadResult big = readJob(text);
        QVERIFY(big.job);
        QCOMPARE((big.job->units[0].module).as<M4Pocket>().depth, 1.7976931348623157e308);
        QCOMPARE(readJob(writeJob(*big.job)).job, big.job);
        text.replace(text.find("1.7976931348623157e308"), 22, "-1e999");
        const JobReadResult over = readJob(text);
        QVERIFY(!over.job);
        // Named at its unit and field (it once said only "not a job file").
        QCOMPARE(diagnosticLines("j", over.diagnostics),
                 std::string("j: unit 1 (M4) depth: the number \"-1e999\" is too large for any dimension\n"));
    }

    void schemaAcceptsSamplesRefusesBadJobs()
    {
        const auto out = validate(samples() + filesIn(dataPath("bad-jobs"), "*.taiwa"));
        if (!out) QSKIP("python3 with jsonschema is not installed");
        for (const auto& f : samples()) QVERIFY2(out->contains("OK " + f + "\n"), qPrintable(*out));
        for (const auto& f : filesIn(dataPath("bad-jobs"), "*.taiwa")) {
            const bool judged = !out->contains("UNJUDGED " + f + "\n");
            QVERIFY2(!judged || out->contains("BAD " + f + "\n"), qPrintable(f + " passes the schema:\n" + *out));
        }
    }
};

QTEST_APPLESS_MAIN(TestJobIo)
#include "test_job_io.moc"
