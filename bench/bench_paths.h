// Where the benchmarks find their jobs: bench/ and the samples of the
// checkout they were built from. Only bench_paths.cpp is compiled with the
// checkout's path, so every other benchmark object is the same in any clone
// (and ccache serves it there).
#pragma once

#include <string>

namespace taiwa::bench {

// The bench/ folder of the checkout, e.g. dir() + "/fine-pocket.taiwa".
std::string dir();
// A bundled sample job, e.g. sample("plate") is resources/samples/plate.taiwa.
std::string sample(const std::string& stem);

}  // namespace taiwa::bench
