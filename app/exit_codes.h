// The exit codes of every command of the command line
// (docs/command-line.md): 0 ok, 1 internal failure, 2 input errors (the
// job's, the options' or the tool library's), 3 verification faults.
#pragma once

namespace taiwa::app {

constexpr int kOk = 0, kInternal = 1, kInputErrors = 2, kFindings = 3;

}  // namespace taiwa::app
