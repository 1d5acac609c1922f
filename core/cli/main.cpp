// `ballbench`: the subcommands are in cmd_*.cpp. Every error the user can cause ends here as one
// line on stderr and exit status 2; a check that ran and failed (`regress`) exits with status 1;
// nothing deeper exits the process.
#include <csignal>
#include <cstdio>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "commands.h"
#include "data_file.h"
#include "input_error.h"
#include "interrupt.h"
#include "registry.h"
#include "run_engines.h"

namespace ballbench::cli {

void exit_if_interrupted(const std::string& kept) {
  const int sig = interrupt_signal();
  if (!sig) return;
  fmt::print(stderr, "ballbench: interrupted by {}: {}\n", interrupt_name(), kept);
  throw CheckFailed{128 + sig};
}

CLI::Option* add_quiet(CLI::App* cmd, bool& quiet) { return cmd->add_flag("--quiet", quiet, "no progress on stderr"); }

}  // namespace ballbench::cli

int main(int argc, char** argv) {
  // A file-size limit (ulimit -f, a quota) fails a write with EFBIG, which the writer reports naming
  // the file and keeps what it replaces, rather than SIGXFSZ killing the process mid-write.
  std::signal(SIGXFSZ, SIG_IGN);
  CLI::App app{"ballbench: compare 2D ball physics engines on identical scenes"};
  app.require_subcommand(1);
  // Options of the app are also taken after the subcommand's name (`ballbench run --engines F ...`).
  app.fallthrough();
  app.add_option_function<std::vector<std::string>>(
      "--engines",
      [](const std::vector<std::string>& files) {
        for (const auto& f : files) {
          ballbench::note_input_file("--engines", f);
          ballbench::use_engines_file(f);
        }
      },
      "an engines file (TOML, adapters/process/README.md) naming external engines to add to the project's "
      "engines.toml (repeatable)");
  ballbench::cli::set_command_line(argc, argv);
  ballbench::cli::add_list(app);
  ballbench::cli::add_run(app);
  ballbench::cli::add_report(app);
  ballbench::cli::add_regress(app);
  ballbench::cli::add_stress(app);
  ballbench::cli::add_sweep(app);
  ballbench::cli::add_match(app);
  ballbench::cli::add_merge(app);
  ballbench::cli::add_view(app);
  ballbench::cli::add_settle(app);
  ballbench::cli::add_conform(app);
  try {
    app.parse(argc, argv);  // runs the chosen subcommand's callback
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "ballbench: error: %s (see ballbench --help)\n", ballbench::printable(e.what()).c_str());
    return 2;
  } catch (const ballbench::cli::CheckFailed& e) {
    return e.status;
  } catch (const ballbench::Interrupted& e) {
    std::fprintf(stderr, "ballbench: interrupted by %s while %s: nothing was run\n", ballbench::interrupt_name(),
                 e.during.c_str());
    return 128 + ballbench::interrupt_signal();
  } catch (const ballbench::InputError& e) {
    std::fprintf(stderr, "ballbench: error: %s\n", ballbench::printable(e.what()).c_str());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ballbench: internal error: %s\n", ballbench::printable(e.what()).c_str());
    return 3;
  }
  return 0;
}
