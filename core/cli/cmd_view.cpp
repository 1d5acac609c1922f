// `ballbench view`: the trajectory viewer page (reports/viewer_page.h) for a run file written by
// `ballbench run --frames N --json FILE`.
#include <filesystem>
#include <memory>

#include <fmt/format.h>

#include "commands.h"
#include "progress.h"
#include "data_file.h"
#include "input_error.h"
#include "interrupt.h"
#include "validators.h"
#include "viewer_page.h"

namespace ballbench::cli {
namespace {

struct ViewArgs {
  std::string results, out;
};

void view(const ViewArgs& a) {
  install_interrupt_handlers();
  const std::string out =
      a.out.empty() ? std::filesystem::path(a.results).replace_extension(".html").string() : a.out;
  {
    std::vector<PathUse> uses = noted_input_files();
    uses.push_back({"RESULTS", a.results, false});
    uses.push_back({"--out", out, true});
    check_path_clashes(uses);
  }
  const std::vector<Result> runs = read_results_file(a.results);
  if (runs.empty()) throw InputError(fmt::format("{}: no runs in it", a.results));
  std::vector<const Result*> shown;
  size_t frames = 0;
  for (const Result& r : runs) {
    shown.push_back(&r);
    frames = std::max(frames, r.series.frames.size());
  }
  if (frames == 0)
    throw InputError(fmt::format("{}: no frames to show (run with `ballbench run --frames N --json FILE`; scenes of "
                                 "at most 1000 balls)",
                                 a.results));
  std::string page;
  try {
    page = viewer_page(shown);
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: {}", a.results, e.what()));
  }
  // Asked to stop while reading: nothing is written. A page being written is written whole.
  exit_if_interrupted(fmt::format("{} not written", out));
  write_file_atomically(out, page, "the viewer page");
  exit_if_interrupted(fmt::format("{} was written whole", out));
  fmt::print("wrote {} ({} runs of {}, {} frames, {:.2f} MB)\n", out, runs.size(), runs.front().scene, frames,
             static_cast<double>(page.size()) / 1e6);
}

}  // namespace

void add_view(CLI::App& app) {
  auto a = std::make_shared<ViewArgs>();
  auto* cmd = app.add_subcommand("view", "write the trajectory viewer page (HTML) for a run file of `run --frames N --json`");
  cmd->add_option("RESULTS", a->results, "a JSON file written by `ballbench run --frames N --json FILE`")->required();
  cmd->add_option("--out", a->out, "the page to write (default: RESULTS with .html for .json)")->check(kOutputFile);
  add_quiet(cmd, Progress::quiet);
  cmd->callback([a] { view(*a); });
}

}  // namespace ballbench::cli
