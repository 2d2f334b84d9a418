// What `taiwa` says about itself (app/about_commands.cpp): the text of
// `taiwa --help`, and the machines and dialects it knows with where each
// was read from (`--list-machines`, `--list-dialects`).
#pragma once

namespace taiwa::app {

// The usage text `taiwa --help` prints (docs/command-line.md).
const char* helpText();

// One line per machine: id, kind, name and where it was read from; the
// user's files left out on standard error. Exit 0.
int listMachines();

// One line per dialect: name, description and where it was read from; the
// user's files left out on standard error. Exit 0.
int listDialects();

}  // namespace taiwa::app
