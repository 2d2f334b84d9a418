// The checkout's bench/ folder, given to this one file by bench/CMakeLists.txt.
#include "bench_paths.h"

namespace taiwa::bench {

std::string dir() { return TAIWA_BENCH_DIR; }
std::string sample(const std::string& stem) { return dir() + "/../resources/samples/" + stem + ".taiwa"; }

}  // namespace taiwa::bench
