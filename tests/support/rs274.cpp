// Running LinuxCNC's rs274 on our G-code and reading its canonical calls.
#include "support/rs274.h"

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
}  // namespace

Rs274Result runRs274(const std::string& ngc)
{
    Rs274Result r;
    QTemporaryDir dir;
    // A fresh tool table (rs274 reads it, diameters irrelevant without
    // cutter compensation) and an empty parameter file, which rs274 rewrites.
    QFile tbl(dir.filePath("tools.tbl"));
    tbl.open(QIODevice::WriteOnly);
    for (int t = 1; t <= 200; ++t) tbl.write(QStringLiteral("T%1 P%1 D0.25\n").arg(t).toUtf8());
    tbl.close();
    QFile var(dir.filePath("params.var"));
    var.open(QIODevice::WriteOnly);
    var.close();
    QFile prog(dir.filePath("program.ngc"));
    prog.open(QIODevice::WriteOnly);
    prog.write(ngc.data(), static_cast<qint64>(ngc.size()));
    prog.close();

    QProcess p;
    p.setWorkingDirectory(dir.path());
    p.start(QStringLiteral(TAIWA_RS274), {"-g", "-t", tbl.fileName(), "-v", var.fileName(), prog.fileName()});
    p.closeWriteChannel();
    if (!p.waitForFinished(300000)) {
        p.kill();
        r.errors = "rs274 did not finish";
        return r;
    }
    const QString out = QString::fromUtf8(p.readAllStandardOutput());
    const QString err = QString::fromUtf8(p.readAllStandardError());
    r.ok = p.exitStatus() == QProcess::NormalExit && p.exitCode() == 0 && !err.contains("error", Qt::CaseInsensitive);
    if (!r.ok) r.errors = err + out.right(2000);

    static const QRegularExpression call(R"(^\s*\d+\s+N\.+\s+([A-Z_]+)\((.*)\)\s*$)");
    static const QRegularExpression stepComment(R"(^STEP (\d+):)");
    Point3 at{};
    int step = 0, tool = 0, selected = 0;
    for (const auto& line : out.split('\n')) {
        const auto m = call.match(line);
        if (!m.hasMatch()) continue;
        r.canon << line.trimmed();
        const QString name = m.captured(1);
        const QString args = m.captured(2);
        if (name == "COMMENT") {
            const auto s = stepComment.match(args.mid(1, args.size() - 2));
            if (s.hasMatch()) step = s.captured(1).toInt();
        } else if (name == "SELECT_TOOL") {
            selected = args.toInt();
        } else if (name == "CHANGE_TOOL") {
            tool = selected;
        } else if (name == "STRAIGHT_TRAVERSE" || name == "STRAIGHT_FEED") {
            const auto v = numbers(args);
            CanonMove c;
            c.kind = name == "STRAIGHT_FEED" ? CanonMove::Feed : CanonMove::Traverse;
            c.start = at;
            c.end = {v.at(0), v.at(1), v.at(2)};
            c.step = step;
            c.tool = tool;
            r.moves.push_back(c);
            at = c.end;
        } else if (name == "ARC_FEED") {
            // ARC_FEED(first_end, second_end, first_axis, second_axis, rotation, axis_end_point, a, b, c)
            const auto v = numbers(args);
            CanonMove c;
            c.kind = CanonMove::Arc;
            c.start = at;
            c.end = {v.at(0), v.at(1), v.at(5)};
            c.centre = {v.at(2), v.at(3)};
            c.rotation = static_cast<int>(v.at(4));
            c.step = step;
            c.tool = tool;
            r.moves.push_back(c);
            at = c.end;
        }
    }
    return r;
}

std::vector<Point3> sampleArc(const CanonMove& arc, double step)
{
    const Point2 a{arc.start.x - arc.centre.x, arc.start.y - arc.centre.y};
    const Point2 b{arc.end.x - arc.centre.x, arc.end.y - arc.centre.y};
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
        pts.push_back({arc.centre.x + radius * std::cos(ang), arc.centre.y + radius * std::sin(ang),
                       arc.start.z + (arc.end.z - arc.start.z) * t});
    }
    return pts;
}

}  // namespace taiwa::test
