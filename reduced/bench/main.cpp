// bench-reduced: Google Benchmark entry point; the benchmarks are in the other files here.
#include <benchmark/benchmark.h>

BENCHMARK_MAIN();
