// Placeholder command line until the pipeline lands.
#include "app/cli.h"
#include <cstdio>
#include <cstring>
namespace taiwa::app {
int run(int argc, char** argv)
{
    if (argc > 1 && std::strcmp(argv[1], "--version") == 0) { std::puts("taiwa " TAIWA_VERSION); return 0; }
    return 1;
}
}
