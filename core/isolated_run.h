#pragma once
// One engine run in a child process with a time limit: a segfault, abort or hang in an engine
// becomes that run's result ("crashed" naming the signal, "timed out" naming the limit) and the
// rest of a comparison goes on. POSIX only (fork, pipe, poll, waitpid).
#include <string>

#include "engine.h"
#include "result.h"
#include "runner.h"
#include "scene.h"

namespace ballbench {

struct IsolationOptions {
  // Wall-clock limit for the whole run, building the world included (s). Generous by default: the
  // slowest engine on the largest built-in scene takes minutes, a hang takes forever.
  double timeout_s = 600;
  // If not empty, the child writes the run's trajectory CSV (header included, core/trajectory_csv.h)
  // to this file. A run that crashes or times out leaves no file.
  std::string trajectory_path;
  // Where the child's failure to write that file is said (why: "File too large"), if not null: the
  // run's result stands, its rows are lost.
  std::string* trajectory_error = nullptr;
  // An engine in a process of its own runs in a forked child all the same, which starts a process
  // of its own for it: a timing repeat in a fresh process. (A Node engine's speed differs from one
  // process to the next: box2d3's pile window read 9 200 ns in one and 16 500 in another.)
  bool fresh_process = false;
  // The core the child runs on (core_affinity.h), and the process it starts for an engine of its
  // own; -1: wherever the system puts it.
  int core = -1;
};

// run_engine() in a forked child, which sends the Result back through a pipe (as JSON) and exits;
// for an engine in a process of its own (EngineInfo::own_process), in this process, its steps
// bounded as the child would be (RunOptions::stuck). The same contract as run_engine: throws InputError for bad settings (found by the child), never
// for what the engine does. `options.trajectory` must be null (use isolation.trajectory_path);
// `options.progress` is called in this process, as the child reports progress.
Result run_engine_isolated(const Scene& scene, const EngineEntry& entry, const RunOptions& options,
                           const IsolationOptions& isolation);

// An engine process's group started (live) or ended, called by whatever starts engine processes.
// In a run's child process it is told to the parent, which ends the groups still live when the
// child dies without ending them (killed at the time limit, crashed): an engine dies with the
// child (PR_SET_PDEATHSIG), a helper in its group would not. Elsewhere it does nothing.
void note_engine_group(int group, bool live);

// In a process just forked (and not exec'd): closes every file it inherited but stdin, stdout, stderr
// and `keep` (-1: none). A run forked beside it from another thread has its pipe open until its fork
// returns, and that run's parent reads the pipe to its end, which a copy of its write end here would
// hold off until this process exits (a run of 40 steps beside a hung one read as hung; a try of a
// second beside one of a minute, as a minute).
void close_inherited_files(int keep);

// "SIGSEGV (segmentation fault)": the signal's name and what it means.
std::string signal_description(int sig);

}  // namespace ballbench
