// The two-path lathe's tapes of an export (two_path_export.h): both
// programs (the job's first roughing step balanced with the job's settings
// and posted, post/posted_job.h), both listed in the tape image, and the
// LinuxCNC tool table of each path.
#include "export/two_path_export.h"

#include "pipeline/pipeline.h"
#include "post/dialect.h"
#include "post/tool_table.h"

#include <fmt/format.h>

namespace taiwa {

std::optional<Result<std::vector<ExportFile>>> twoPathTapes(const Plan& plan, const std::string& dialect,
                                                            std::optional<LengthUnit> units, int programNumber,
                                                            const std::string& stem)
{
    return twoPathTapes(plan, postTwoPath(plan, postOptions(plan, dialect, units, programNumber, stem)), dialect, stem);
}

std::optional<Result<std::vector<ExportFile>>> twoPathTapes(const Plan& plan, const std::optional<Result<PostedTwoPath>>& posted,
                                                            const std::string& dialect, const std::string& stem)
{
    using Files = Result<std::vector<ExportFile>>;
    if (!posted) return std::nullopt;
    if (!*posted) return Files{Failure{posted->error()}};
    const std::vector<PostedProgram>& programs = (*posted)->programs;
    const Step& rough = plan.steps[(*posted)->roughing];
    const post::Dialect* d = post::findDialect(dialect);
    const std::string ext = d ? "." + d->fileExtension : ".nc";
    const bool linuxcnc = d && d->syntax == post::Syntax::Iso && d->macroSyntax != "fanuc";
    std::vector<ExportFile> files;
    std::string image;
    for (std::size_t p = 0; p < programs.size(); ++p) {
        const std::string path = fmt::format(".p{}", p + 1);
        files.emplace_back(path + ext, programs[p].nc);
        image += fmt::format("==== {}{}{} ====\n", stem, path, ext) + programs[p].tapeImage;
        if (!image.empty() && image.back() != '\n') image += '\n';
        if (linuxcnc) {
            // Path 1 runs the whole job; the other paths their blocks of the roughing alone.
            const std::vector<Step> alone{rough};
            files.emplace_back(path + ".tbl", linuxcncLatheToolTable(p == 0 ? plan.steps : alone, plan.tools, stem + path));
        }
    }
    files.emplace_back(".tape.txt", image);
    return Files{std::move(files)};
}

}  // namespace taiwa
