// What `taiwa` says about itself (about_commands.h): the usage text of
// `taiwa --help`, and `--list-machines` and `--list-dialects`.
#include "app/about_commands.h"

#include "app/exit_codes.h"
#include "machine/machine.h"
#include "post/dialect.h"

#include <iostream>
#include <string>

namespace taiwa::app {

namespace {

const char* const kHelp = R"(taiwa - conversational NC programming station

Usage:
  taiwa [JOB]                      open the station window (with JOB loaded)
  taiwa check JOB                  input processing only; one line per error:
                                   JOB: unit N (MODULE) field: message
  taiwa export JOB --out DIR [--dialect NAME] [--units mm|inch] [--no-pictures]
                                   the whole pipeline; writes STEM.nc (.mpf for
                                   sinumerik, .h for heidenhain), STEM.tape.txt,
                                   STEM.sheet.html, STEM.sheet.pdf and
                                   STEM.steps.json into DIR (and each probing
                                   unit's programs, and a linuxcnc lathe tape's
                                   tool table STEM.tbl); the dialect (--list-dialects):
                                   --dialect, else the job's, else linuxcnc;
                                   verifies first (--resolution) and writes
                                   nothing when a gouge, collision or travel
                                   limit is found (exit 3), unless --force,
                                   which writes them into the sheet in red;
                                   the sheet shows each step's stock in a
                                   picture (drawn on the processor: no display)
  taiwa export --from-store NAME --out DIR [...]
                                   the same for the newest version of job NAME
                                   of the shop server's store (TAIWA_TOOL_DB)
  taiwa verify JOB [--resolution MM] [--json]
                                   cuts every step into the stock on a grid of
                                   MM (default 0.05) and prints each gouge,
                                   collision, rapid into stock, travel limit
                                   and material left, with its step, move and
                                   tape line; exit 3 when a gouge, collision
                                   or travel limit is found
  taiwa render JOB --out PNG [--step K|all] [--stock] [--size WxH]
               [--view iso|top|front|profile]
                                   the 3-D preview of step K (1-based, in
                                   machining order) or all steps, to a PNG; a
                                   lathe job: the part revolved, or with
                                   --view profile its profile views
  taiwa import STEP --out JOB [--material ID]
                                   a lathe job from a STEP solid of revolution:
                                   its outer profile (and bore) as turned-profile
                                   units, a bar that holds it; JOB must not exist
  taiwa figure-from-dxf FILE.dxf [--layers A,B] [--gap MM] [--units mm|inch]
                                   the contours of a DXF drawing (on the
                                   layers given; ends within MM, default 0.01,
                                   joined; lengths in the unit given, else the
                                   file's) as figure elements on stdout; what
                                   was read, gaps, branches and contours left
                                   out on stderr; exit 2 when the file is
                                   refused, has gaps or a contour is left out
  taiwa import-tools FILE.sqlite
                                   the shop server's tool library (TAIWA_TOOL_DB
                                   or --tools, a postgresql:// setting) replaced
                                   by that of an SQLite library of any version;
                                   the file is left as it was
  taiwa store list | taiwa store history NAME
                                   the shop server's job store (TAIWA_TOOL_DB
                                   or --tools): each job with its newest
                                   version, who saved it from which station
                                   and when, and who has it open; or every
                                   version of job NAME; tab-separated lines
  taiwa store locks | taiwa store unlock NAME [--force]
                                   the jobs some station has open (its lock),
                                   with who and since when and whether that
                                   station is connected now; or job NAME's
                                   lock released, saying whose it was: refused
                                   while its station is connected, unless
                                   --force
  taiwa --list-machines | --list-dialects
                                   the machines and dialects this program knows
                                   (shipped, and the shop's own in
                                   ~/.config/taiwa/machines|dialects/*.json),
                                   with where each comes from
  taiwa --version | --help

Common options:
  --tools DB    the tool library (SQLite); default $TAIWA_TOOL_DB or
                ~/.local/share/taiwa/tools.sqlite, created on first use
  --no-cache    verify, export: verify afresh; otherwise a report stored by
                an earlier verify or export of the same job, plan, library
                tools, machine and resolution is reused
                ($XDG_CACHE_HOME/taiwa/verification, or $TAIWA_CACHE_DIR)

Exit status: 0 ok, 2 input errors (the job's, the options' or the tool
library's; nothing written), 3 the verification found
a gouge, a collision or a travel limit, 1 internal failure.
)";

}  // namespace

const char* helpText()
{
    return kHelp;
}

int listMachines()
{
    for (const Machine& m : machineLibrary())
        std::cout << m.id << '\t' << toKey(m.kind) << '\t' << m.name << '\t' << m.source << '\n';
    for (const std::string& p : machineLibraryProblems()) std::cerr << "taiwa: " << p << '\n';
    return kOk;
}

int listDialects()
{
    for (const post::Dialect& d : post::dialectLibrary())
        std::cout << d.name << '\t' << d.description << '\t' << d.source << '\n';
    for (const std::string& p : post::dialectLibraryProblems()) std::cerr << "taiwa: " << p << '\n';
    return kOk;
}

}  // namespace taiwa::app
