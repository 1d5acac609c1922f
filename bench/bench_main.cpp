#include "bench_main.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace ballbench::bench {
namespace {

double budget = 30;

// Takes --budget_s=S out of argv (Google Benchmark has taken its own flags out already).
bool read_budget(int& argc, char** argv) {
  constexpr const char* kFlag = "--budget_s=";
  int kept = 1;
  for (int k = 1; k < argc; ++k) {
    if (std::strncmp(argv[k], kFlag, std::strlen(kFlag)) != 0) {
      argv[kept++] = argv[k];
      continue;
    }
    const char* text = argv[k] + std::strlen(kFlag);
    char* end = nullptr;
    budget = std::strtod(text, &end);
    if (end == text || *end != '\0' || !(budget > 0)) {
      std::fprintf(stderr, "--budget_s: must be a number of seconds > 0, got '%s'\n", text);
      return false;
    }
  }
  argc = kept;
  return true;
}

}  // namespace

double budget_seconds() { return budget; }

}  // namespace ballbench::bench

int main(int argc, char** argv) {
  // 0.2 s a benchmark unless --benchmark_min_time says otherwise (the report's suites do): a
  // benchmark's own MinTime would override the flag.
  std::vector<char*> args(argv, argv + argc);
  char default_min_time[] = "--benchmark_min_time=0.2";
  if (std::none_of(args.begin(), args.end(), [](const char* a) { return std::strncmp(a, "--benchmark_min_time", 20) == 0; }))
    args.insert(args.begin() + 1, default_min_time);
  args.push_back(nullptr);
  argc = int(args.size()) - 1;
  argv = args.data();
  benchmark::Initialize(&argc, argv);
  if (!ballbench::bench::read_budget(argc, argv)) return 1;
  // In the JSON's context, for the report to state the budget its figures ran under.
  char budget_text[32];
  std::snprintf(budget_text, sizeof budget_text, "%g", ballbench::bench::budget_seconds());
  benchmark::AddCustomContext("budget_s", budget_text);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  ballbench::bench::register_benchmarks();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
