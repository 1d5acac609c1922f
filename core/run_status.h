#pragma once
// How a run ended, as a closed set: the code compares these, and only results' JSON and the tables
// turn them into words (run_status_text, run_status_from_text).
#include <iosfwd>
#include <string_view>

namespace ballbench {

enum class RunStatus {
  ok,           // ran every step asked for
  diverged,     // a non-finite state, a ball out of the container or an energy blow-up (Result::diverged_step)
  failed,       // the engine threw, or its world could not be built (Result::error)
  unsupported,  // the scene needs what the engine lacks (Result::error)
  interrupted,  // SIGINT or SIGTERM ended it at a step boundary, or before it started
  crashed,      // its child process died (core/isolated_run.h; Result::error names the signal)
  timed_out,    // its child process gave no result within the time limit and was killed
  missed,       // stopped where a term of the spec it was asked to meet could no longer be met
                // (RunOptions::stop_on_miss; Result::error names the term, its figure and the time)
  over_cost,    // stopped where its engine time passed what it was allowed (RunOptions::cost_limit):
                // a configuration already found costs less, or the search's ceiling
};

// The text in results' JSON and in tables: the enumerator's name, except "timed out" (a space, as
// results files have always had it).
const char* run_status_text(RunStatus s);

// The status a text above names; throws InputError for any other.
RunStatus run_status_from_text(std::string_view text);

// The text, for test failure messages.
std::ostream& operator<<(std::ostream& os, RunStatus s);

}  // namespace ballbench
