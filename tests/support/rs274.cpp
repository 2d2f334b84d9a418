// Running LinuxCNC's rs274 on our G-code and reading its canonical calls
// (see rs274.h).
#include "support/rs274.h"
#include "support/support.h"

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>

#include <cmath>
#include <numbers>

namespace taiwa::test {

namespace {

std::vector<double> numbers(const QString& args)
{
    std::vector<double> v;
    for (const auto& part : args.split(QRegularExpression("[,\\s]+"), Qt::SkipEmptyParts)) v.push_back(part.toDouble());
    return v;
}

bool copyData(const QString& name, const QString& to)
{
    return QFile::copy(dataPath(QStringLiteral("rs274/") + name), to) &&
           QFile::setPermissions(to, QFile::ReadOwner | QFile::WriteOwner);
}

// rs274 prints "executing" on stderr for every run; anything else there is
// its complaint (which need not contain the word "error": "Radius to end of
// arc differs from radius to start: ...", "Nested comment found").
QString complaint(const QString& out, const QString& err)
{
    QStringList bad;
    for (const auto& l : err.split('\n', Qt::SkipEmptyParts))
        if (l.trimmed() != "executing") bad << l;
    for (const auto& l : out.split('\n', Qt::SkipEmptyParts))
        if (!l.contains("COMMENT(") && l.contains("error", Qt::CaseInsensitive)) bad << l;
    return bad.join('\n');
}

}  // namespace

Rs274Result runRs274(const std::string& ngc, const std::string& toolTable)
{
    Rs274Result r;
    QTemporaryDir dir;
    const QString tbl = dir.filePath("tools.tbl"), var = dir.filePath("params.var"), prog = dir.filePath("program.ngc");
    QFile program(prog);
    bool table = false;
    if (toolTable.empty()) {
        table = copyData("tools.tbl", tbl);
    } else {
        QFile f(tbl);
        table = f.open(QIODevice::WriteOnly) &&
                f.write(toolTable.data(), static_cast<qint64>(toolTable.size())) == static_cast<qint64>(toolTable.size());
    }
    if (!table || !copyData("params.var", var) || !program.open(QIODevice::WriteOnly)) {
        r.errors = "cannot prepare rs274's files in " + dir.path();
        return r;
    }
    program.write(ngc.data(), static_cast<qint64>(ngc.size()));
    program.close();

    QProcess p;
    p.setWorkingDirectory(dir.path());
    // rs274 maps its tool table through $HOME/.tool.mmap: two runs sharing
    // one (tests run in parallel) truncate each other's map and one dies of
    // SIGBUS. Each run gets its own home, the temporary folder.
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert("HOME", dir.path());
    p.setProcessEnvironment(env);
    p.start(QStringLiteral(TAIWA_RS274), {"-g", "-t", tbl, "-v", var, prog});
    p.closeWriteChannel();
    if (!p.waitForFinished(300000)) {
        p.kill();
        r.errors = "rs274 did not finish";
        return r;
    }
    r.out = QString::fromUtf8(p.readAllStandardOutput());
    r.err = QString::fromUtf8(p.readAllStandardError());
    r.exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
    r.errors = complaint(r.out, r.err);
    r.ok = r.exitCode == 0 && r.errors.isEmpty();
    if (!r.ok && r.errors.isEmpty()) r.errors = QString("rs274 exit code %1").arg(r.exitCode);

    static const QRegularExpression call(R"(^\s*\d+\s+N[.0-9]+\s+([A-Z_0-9]+)\((.*)\)\s*$)");
    static const QRegularExpression stepComment(R"(^STEP (\d+):)");
    // The tool starts at machine zero: in program coordinates, minus the work offset.
    Point3 at{};
    double feed = 0.0;
    double rpm = 0.0, syncPitch = 0.0;  // the spindle speed; G33.1's pitch (K)
    int step = 0, tool = 0, selected = 0, plane = 17;
    for (const auto& line : r.out.split('\n')) {
        const auto m = call.match(line);
        if (!m.hasMatch()) continue;
        r.canon << line.trimmed();
        const QString name = m.captured(1);
        const QString args = m.captured(2);
        if (name == "USE_LENGTH_UNITS") {
            const bool inches = args == "CANON_UNITS_INCHES";
            if (inches != r.inches) {
                const double k = inches ? 1 / 25.4 : 25.4;
                at = {at.x * k, at.y * k, at.z * k};
                feed *= k;
            }
            r.inches = inches;
        } else if (name == "SET_G5X_OFFSET" && r.moves.empty()) {
            const auto v = numbers(args);
            at = {-v.at(1), -v.at(2), -v.at(3)};
        } else if (name == "SELECT_PLANE") {
            plane = args == "CANON_PLANE_XZ" ? 18 : args == "CANON_PLANE_YZ" ? 19 : 17;
        } else if (name == "SET_FEED_RATE") {
            feed = args.toDouble();
        } else if (name == "COMMENT") {
            const auto s = stepComment.match(args.mid(1, args.size() - 2));
            if (s.hasMatch()) step = s.captured(1).toInt();
        } else if (name == "SELECT_TOOL") {
            selected = args.toInt();
        } else if (name == "CHANGE_TOOL") {
            tool = selected;
        } else if (name == "SET_SPINDLE_SPEED") {
            // SET_SPINDLE_SPEED(spindle, rpm)
            const auto v = numbers(args);
            rpm = v.empty() ? 0.0 : v.back();
        } else if (name == "START_SPEED_FEED_SYNC") {
            // START_SPEED_FEED_SYNC(pitch, velocity mode)
            syncPitch = numbers(args).at(0);
        } else if (name == "DWELL") {
            // G86's mandatory P0 is DWELL(0): no pause, no dwell.
            if (numbers(args).at(0) > 0) ++r.dwells;
        } else if (name == "RIGID_TAP") {
            // RIGID_TAP(x, y, z): G33.1 down to z at the spindle's pitch and
            // back up to where it began: two feeds, at the pitch x the
            // spindle speed (not the F word in force: G33.1 has none).
            const auto v = numbers(args);
            CanonMove down;
            down.kind = CanonMove::Feed;
            down.start = at;
            down.end = {v.at(0), v.at(1), v.at(2)};
            down.step = step;
            down.tool = tool;
            down.plane = plane;
            down.feed = syncPitch * rpm;
            CanonMove up = down;
            up.start = down.end;
            up.end = at;
            r.moves.push_back(down);
            r.moves.push_back(up);
        } else if (name == "STRAIGHT_TRAVERSE" || name == "STRAIGHT_FEED" || name == "ARC_FEED") {
            // STRAIGHT_*(x, y, z, a, b, c);
            // ARC_FEED(first_end, second_end, first_axis, second_axis, rotation, axis_end_point, a, b, c)
            const auto v = numbers(args);
            CanonMove c;
            c.start = at;
            c.step = step;
            c.tool = tool;
            c.plane = plane;
            if (name == "ARC_FEED") {
                c.kind = CanonMove::Arc;
                // XZ: first axis Z, second X, the axis end point Y.
                c.end = plane == 18 ? Point3{v.at(1), v.at(5), v.at(0)} : Point3{v.at(0), v.at(1), v.at(5)};
                c.centre = {v.at(2), v.at(3)};
                c.rotation = static_cast<int>(v.at(4));
            } else {
                c.kind = name == "STRAIGHT_FEED" ? CanonMove::Feed : CanonMove::Traverse;
                c.end = {v.at(0), v.at(1), v.at(2)};
            }
            if (c.kind != CanonMove::Traverse) c.feed = feed;
            r.moves.push_back(c);
            at = c.end;
        }
    }
    return r;
}

std::vector<Point3> sampleArc(const CanonMove& arc, double step)
{
    const bool xz = arc.plane == 18;
    // The plane's (first, second) coordinates of a point, and back.
    const auto inPlane = [&](const Point3& p) { return xz ? Point2{p.z, p.x} : Point2{p.x, p.y}; };
    const double axisStart = xz ? arc.start.y : arc.start.z, axisEnd = xz ? arc.end.y : arc.end.z;
    const Point2 a = inPlane(arc.start) - arc.centre;
    const Point2 b = inPlane(arc.end) - arc.centre;
    const double radius = length(a);
    double sweep = std::atan2(cross(a, b), dot(a, b));
    if (arc.rotation > 0 && sweep <= 1e-12) sweep += 2 * std::numbers::pi;
    if (arc.rotation < 0 && sweep >= -1e-12) sweep -= 2 * std::numbers::pi;
    // |rotation| > 1 adds full turns.
    const int turns = std::abs(arc.rotation) - 1;
    sweep += (sweep > 0 ? 1 : -1) * 2 * std::numbers::pi * turns;
    const int n = std::max(2, static_cast<int>(std::ceil(std::abs(sweep) * radius / step)));
    const double a0 = std::atan2(a.y, a.x);
    std::vector<Point3> pts;
    for (int i = 1; i <= n; ++i) {
        const double t = static_cast<double>(i) / n;
        const double ang = a0 + sweep * t;
        const Point2 q{arc.centre.x + radius * std::cos(ang), arc.centre.y + radius * std::sin(ang)};
        const double axis = axisStart + (axisEnd - axisStart) * t;
        pts.push_back(xz ? Point3{q.y, axis, q.x} : Point3{q.x, q.y, axis});
    }
    return pts;
}

}  // namespace taiwa::test
