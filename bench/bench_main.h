#pragma once
// Every benchmark binary's main (bench_main.cpp): Google Benchmark's flags, then the binary's own
// register_benchmarks(), then the run.
namespace ballbench::bench {

// Defined once per binary: registers its benchmarks (benchmark::RegisterBenchmark).
void register_benchmarks();

}  // namespace ballbench::bench
