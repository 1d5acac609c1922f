// `ballbench settle`: a scene run to its end by one engine, its final state written as a scene
// file (core/scene_writer.h), so that a settled pile is data: searched over a short window instead
// of being poured again by every engine at every step size.
#include <filesystem>
#include <memory>

#include <fmt/format.h>

#include "commands.h"
#include "data_file.h"
#include "input_error.h"
#include "interrupt.h"
#include "progress.h"
#include "registry.h"
#include "run_engines.h"
#include "scene_loader.h"
#include "scene_writer.h"
#include "spec_verdict.h"
#include "validators.h"

namespace ballbench::cli {
namespace {

struct SettleArgs {
  std::string scene, engine = "home", profile, out, name;
  double duration = 1.0;
  std::vector<std::string> sets;
  bool quiet = false;
};

void settle(const SettleArgs& a) {
  install_interrupt_handlers();
  Progress::quiet = a.quiet;
  const Scene scene = load_scene(a.scene);
  std::vector<PathUse> uses = noted_input_files();
  if (!scene.source.empty() && std::filesystem::exists(scene.source)) uses.push_back({"--scene", scene.source, false});
  uses.push_back({"--out", a.out, true});
  check_path_clashes(uses);
  check_writable(a.out, "the settled scene", true);
  const EngineEntry& e = find_engine(a.engine);
  check_profile({&e}, a.profile.empty() ? e.info.profiles.front() : a.profile);
  RunOptions options;
  options.profile = a.profile;
  nlohmann::json sets = nlohmann::json::object();
  for (const auto& item : a.sets) add_setting(sets, item);
  for (const auto& [engine, table] : sets.items())
    if (engine != a.engine)
      throw InputError(fmt::format("--set {}.KEY: the scene is settled by {}, not {}", engine, a.engine, engine));
  options.overrides = sets.value(a.engine, nlohmann::json::object());
  options.series_points = 0;
  State last;
  options.last_state = &last;
  Progress progress(fmt::format("settle {} with {}", scene.name, run_label(e.info.name, a.profile)));
  options.progress = [&](long done, long total) { progress.update(double(done) / double(total)); };
  const Result r = run_engine(scene, e, options);
  if (r.status != RunStatus::ok)
    throw InputError(fmt::format("settle: {} on {} ended {} ({}): nothing written", run_label(r), scene.name,
                                 run_status_text(r.status), r.error));
  const std::string name = a.name.empty() ? scene.name + "-settled" : a.name;
  const SceneSnapshot snap = scene_at_state(scene, last, name, a.duration);
  // The file must read back as a scene: a name the loader refuses is found here, not by its user.
  parse_scene(snap.text, a.out);
  write_file_atomically(a.out, "# Made by: " + run_context().value("command", std::string("ballbench settle")) + "\n" + snap.text,
                        "the settled scene");
  const SpecVerdict v = judge(scene_spec(scene), r);
  fmt::print("{}: {} balls of {} at t = {:g} s by {} (its spec {}: {}), {:g} s to run; wrote {}\n", name, scene.n(),
             scene.name, last.t, run_label(r), scene_spec(scene).text(), v.met ? "met" : "not met: " + v.why_not,
             a.duration, a.out);
  if (snap.pushed_in > 0)
    fmt::print("{} balls had sunk into a wall and start touching it instead (moved by at most {:.3g} of a radius)\n",
               snap.pushed_in, snap.pushed_by);
}

}  // namespace

void add_settle(CLI::App& app) {
  auto a = std::make_shared<SettleArgs>();
  auto* cmd = app.add_subcommand("settle", "run a scene to its end and write its final state as a scene file");
  cmd->add_option("--scene", a->scene, "built-in scene name or path to a .toml scene file")->required();
  cmd->add_option("--out", a->out, "the scene file to write (TOML)")->required();
  cmd->add_option("--engine", a->engine, "the engine that settles it (default home)");
  cmd->add_option("--profile", a->profile, "its profile (default: its first)");
  cmd->add_option("--duration", a->duration, "the written scene's duration (s, default 1): a window to search over")
      ->check(kPositiveNumber);
  cmd->add_option("--name", a->name, "the written scene's name (default: SCENE-settled)");
  cmd->add_option("--set", a->sets, "an engine setting, ENGINE.KEY=VALUE (repeatable)");
  add_quiet(cmd, a->quiet);
  cmd->callback([a] { settle(*a); });
}

}  // namespace ballbench::cli
