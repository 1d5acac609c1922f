#pragma once
// The subcommands of `ballbench`, one file each (cmd_*.cpp). Each adds itself to the app with a
// callback that runs when it is chosen; errors are thrown (InputError for the user's) and turned
// into one line by main.cpp.
#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

namespace ballbench {
struct Scene;
}

namespace ballbench::cli {

void add_list(CLI::App& app);
void add_run(CLI::App& app);
void add_report(CLI::App& app);
void add_regress(CLI::App& app);
void add_stress(CLI::App& app);
void add_sweep(CLI::App& app);
void add_match(CLI::App& app);
void add_merge(CLI::App& app);
void add_view(CLI::App& app);
void add_settle(CLI::App& app);
void add_conform(CLI::App& app);

// Every command's --quiet, declared here once: no progress on stderr (errors, and what a command
// skips or leaves out, are still said).
CLI::Option* add_quiet(CLI::App* cmd, bool& quiet);

// Every engine's settings, from the scene's [settings.NAME] tables and from `overrides` (--set,
// {"ENGINE": {"KEY": value}}), checked before anything runs, for the engines a command runs and the
// rest alike: a typo is an error even for an engine left out, found before the first run rather than
// as a failed row of each. Throws InputError "settings.ENGINE.KEY: why" (an unknown key names the
// engine's known settings), prefixed by FILE:LINE for the scene's own; "--set X.KEY: unknown engine".
void check_settings(const Scene& scene, const nlohmann::json& overrides);

// Renders OUT/REPORT.md and OUT/figures from OUT/results (`report`, and `merge` of report shards).
void render_report_folder(const std::string& out);

// Thrown by a subcommand that ran to the end but found what it checks failing (`regress`, having
// printed what differs): main exits with `status`, printing nothing more.
struct CheckFailed {
  int status = 1;
};

// After a command has written what it computed: if SIGINT or SIGTERM asked it to stop
// (interrupt.h), says so in one line with `kept` (what was written, and where) and ends the
// command with 128 + the signal's number, as a shell reports a process ended by it.
void exit_if_interrupted(const std::string& kept);

}  // namespace ballbench::cli
