// The two-path lathe's tapes of an export (two_path_export.h): balance the
// job's first roughing step with the job's settings, post both programs,
// list both in the tape image, and the LinuxCNC tool table of each path.
#include "export/two_path_export.h"

#include "machine/machine.h"
#include "model/translate_noop.h"
#include "pipeline/pipeline.h"
#include "post/dialect.h"
#include "post/tool_table.h"
#include "post/two_path_post.h"
#include "turning/balanced_roughing.h"

#include <fmt/format.h>

#include <stdexcept>

namespace taiwa {

std::optional<Result<std::vector<ExportFile>>> twoPathTapes(const Plan& plan, const std::string& dialect,
                                                            std::optional<LengthUnit> units, int programNumber,
                                                            const std::string& stem)
{
    using Files = Result<std::vector<ExportFile>>;
    const Machine* machine = findMachine(plan.mmJob.machine);
    if (!plan.mmJob.bar || plan.steps.empty() || !machine || !machine->layout.multiPath) return std::nullopt;
    std::size_t index = plan.steps.size();
    for (std::size_t k = 0; k < plan.steps.size() && index == plan.steps.size(); ++k)
        if (plan.steps[k].machiningType == MachiningType::TurnRoughing && turnOf(plan.steps[k])) index = k;
    if (index == plan.steps.size())
        return Files{Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "machine: {} is a two-path lathe and the job has no "
                                                                      "roughing step to balance between its paths"),
                                   plan.mmJob.machine)}};
    const Step& rough = plan.steps[index];
    // Path 1 faces before and finishes after the balanced roughing: the paths meet at the ends.
    const turning::BalanceSettings set = turning::balanceSettings(plan.mmJob.twoPath, true);
    auto cut = turning::balanceRoughing(turnOf(rough)->path, turnOf(rough)->cutting, *machine, set);
    if (!cut) return Files{Failure{cut.error()}};
    std::vector<PostedProgram> programs;
    try {
        programs = postBalancedCut(*cut, plan.steps, index, *machine->layout.multiPath, plan.tools,
                                   postOptions(plan, dialect, units, programNumber, stem));
    } catch (const Refusal& e) {
        return Files{Failure{e.what()}};
    }
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
