#pragma once
// Every benchmark binary's main (bench_main.cpp): Google Benchmark's flags, then ballbench's own
// (--budget_s), then the binary's own register_benchmarks(), then the run.
namespace ballbench::bench {

// Defined once per binary: registers its benchmarks (benchmark::RegisterBenchmark).
void register_benchmarks();

// Seconds a benchmark's steps may take before it stops, saying how far it got (--budget_s=S,
// default 30): a slow engine is reported, not waited for.
double budget_seconds();

}  // namespace ballbench::bench
