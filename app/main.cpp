// Entry point of `taiwa`: the command line of docs/command-line.md, or the station
// window when called with no command.
#include "app/cli.h"

int main(int argc, char** argv) { return taiwa::app::run(argc, argv); }
