// The command line: the program's own help, every subcommand added from the one list below,
// and the exit status of bad options (2) and of each command (run_guarded.hpp).
#include <CLI/CLI.hpp>
#include <iostream>
#include <string>

#include "cli/commands.hpp"
#include "cli/interrupt.hpp"
#include "cli/run_guarded.hpp"
#include "cli/subcommand.hpp"
#include "common/version.hpp"
#include "output/output_dir.hpp"
#include "scene/toml_reader.hpp"

// Every subcommand, once, in the order `bookspin --help` lists them. X(NAME) stands for
// src/cli/NAME_command.cpp, which defines `Subcommand add_NAME(CLI::App& cli)`: a new
// subcommand is its file and its X(NAME) here.
#define BOOKSPIN_SUBCOMMANDS(X) \
  X(simulate)                   \
  X(render)                     \
  X(export)                     \
  X(explore)                    \
  X(accuracy)                   \
  X(plot)                       \
  X(gallery)                    \
  X(inertia)                    \
  X(fit)                        \
  X(sweep)                      \
  X(flipcheck)                  \
  X(info)

namespace bookspin::cli {

#define BOOKSPIN_DECLARE_SUBCOMMAND(name) Subcommand add_##name(CLI::App& cli);
BOOKSPIN_SUBCOMMANDS(BOOKSPIN_DECLARE_SUBCOMMAND)
#undef BOOKSPIN_DECLARE_SUBCOMMAND

namespace {

using AddSubcommand = Subcommand (*)(CLI::App& cli);

#define BOOKSPIN_LIST_SUBCOMMAND(name) add_##name,
constexpr AddSubcommand kSubcommands[] = {BOOKSPIN_SUBCOMMANDS(BOOKSPIN_LIST_SUBCOMMAND)};
#undef BOOKSPIN_LIST_SUBCOMMAND

int report(const std::string& message, int code) {
  std::cerr << "bookspin: error: " << scene::escape_controls(message) << '\n';
  return code;
}

}  // namespace

int run_cli(int argc, char** argv) {
  install_interrupt_handlers();  // first, so an early Ctrl-C is handled the same way
  CLI::App cli{"bookspin: simulate and render the unstable rotation of a book", "bookspin"};
  // `bookspin --version`: the one version (VERSION, docs/flipcheck.md "Versions").
  cli.set_version_flag("--version", "bookspin " + version(), "Print bookspin's version and exit");
  cli.require_subcommand(1);
  std::vector<Subcommand> subcommands;
  for (AddSubcommand add : kSubcommands) subcommands.push_back(add(cli));
  try {
    cli.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return cli.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return cli.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return cli.exit(e);
  } catch (const CLI::ParseError& e) {
    return report(std::string(e.what()) + " (see bookspin --help)", kExitUsage);
  }
  const int status = run_guarded([&] {
    for (const Subcommand& subcommand : subcommands)
      if (cli.got_subcommand(subcommand.app)) {
        const int code = subcommand.run();
        // What it printed reached the standard output, or exit 1 naming it (`> /dev/full`).
        flush_standard_output();
        return code;
      }
    return static_cast<int>(kExitOk);
  });
  // A run that stops without its outputs (an interrupt, an error) takes back the folders it
  // made and left empty; their temporaries are gone already.
  if (status != kExitOk) output::remove_empty_made_directories();
  return status;
}

}  // namespace bookspin::cli
