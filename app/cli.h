// The command line of docs/command-line.md: check, export, render, --version, --help.
#pragma once
namespace taiwa::app {
// Exit codes: 0 ok, 2 input errors, 1 internal failure.
int run(int argc, char** argv);
}
