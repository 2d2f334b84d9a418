// What the tape read-back tests (test_tape_readback, _lathe) share: a
// sample planned with the default tools, the read-back's own findings in
// words, and a shop's dialect file made for a test with a sample job set to
// post in it (the shipped linuxcnc.json under a name of its own with one
// word changed, in a temporary home's config folder where `taiwa` finds
// shop dialects), for a word the dialect loader lets through. Header only,
// like hand_plan.h.
#pragma once

#include "job/job_file.h"
#include "pipeline/pipeline.h"
#include "support/support.h"
#include "tools/tool_library.h"
#include "verify/verify.h"

#include <QDir>
#include <QTemporaryDir>

#include <string>

namespace taiwa::test {

// A shipped sample, or a test's job ("gang/lathe-gang-shaft.taiwa": a gang-tool lathe's).
inline Plan planOf(const QString& sample)
{
    const QString path = sample.contains('/') ? dataPath(sample) : sourcePath("resources/samples/" + sample);
    const JobReadResult read = readJobFile(path.toStdString());
    if (!read.job) return {};
    return planJob(*read.job, TechnologyTable::builtIn(), defaultToolLibrary());
}

// The findings of the tape's own, in words.
inline QString tapeFindings(const verify::Report& r, const Plan& plan)
{
    QString s;
    for (const auto& f : r.findings)
        if (f.kind == verify::FindingKind::UnplannedMove || f.kind == verify::FindingKind::UnreadTape)
            s += QString::fromStdString(verify::describe(f, plan)) + "\n";
    return s;
}

struct ShopDialectJob {
    QString job;        // the sample's copy that names the dialect (empty: a text to replace was not found)
    QStringList env;    // XDG_CONFIG_HOME and TAIWA_CACHE_DIR in `home`
};

inline ShopDialectJob shopDialectJob(const QTemporaryDir& home, const std::string& name, const std::string& from,
                                     const std::string& to, const QString& sample)
{
    const QString folder = home.filePath("taiwa/dialects");
    std::string dialect = readFile(sourcePath("resources/dialects/linuxcnc.json"));
    std::string text = readFile(sourcePath("resources/samples/" + sample));
    const std::string shipped = "\"name\": \"linuxcnc\"";
    const auto named = dialect.find(shipped);
    const auto word = dialect.find(from);
    const auto offset = text.find("\"workOffset\": \"G54\",");
    if (!QDir().mkpath(folder) || named == std::string::npos || word == std::string::npos || offset == std::string::npos)
        return {};
    dialect.replace(word, from.size(), to);
    dialect.replace(dialect.find(shipped), shipped.size(), "\"name\": \"" + name + "\"");
    writeFile(folder + "/" + QString::fromStdString(name) + ".json", dialect);
    text.insert(offset, "\"dialect\": \"" + name + "\",\n  ");
    const QString job = home.filePath(QString::fromStdString(name) + ".taiwa");
    writeFile(job, text);
    return {job, {"XDG_CONFIG_HOME=" + home.path(), "TAIWA_CACHE_DIR=" + home.filePath("cache")}};
}

}  // namespace taiwa::test
