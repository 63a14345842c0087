#pragma once
// One subcommand of the bookspin program. src/cli/NAME_command.cpp holds all of it: its
// options, their CLI11 names, help texts and validators, and what runs with them, joined by its
// `Subcommand add_NAME(CLI::App& cli)`; cli.cpp lists every NAME once (BOOKSPIN_SUBCOMMANDS).
// What several subcommands' options share is here.
#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

namespace bookspin::cli {

/// A subcommand added to the program: its CLI11 app (whether it was chosen, after parsing)
/// and what runs it with the options parsed into it, returning the process exit status
/// (called inside run_guarded()).
struct Subcommand {
  CLI::App* app = nullptr;
  std::function<int()> run;
};

/// The help text of --set, the option of every command that reads a scene.
inline constexpr const char* kSetHelp =
    "Override a scene key, value in TOML syntax (repeatable), e.g. --set time.dt=0.01 "
    "--set model.kind='\"rigid-matrix\"' --set book.size=[1,2,0.5]";

/// --force and --verify of the commands that skip up-to-date outputs; `manifest` is the
/// manifest file their help names.
void add_freshness_flags(CLI::App* cmd, bool& force, bool& verify, const std::string& manifest);

/// `-o,--out DIR` into `out_dir`, whose value when added is the default the help shows. An
/// empty name is bad input (exit 2), worded as npx words it: "--out: expected a directory, got
/// an empty name (leave it out for DEFAULT)", never a failed write to "".
CLI::Option* add_out_option(CLI::App* cmd, std::string& out_dir, const std::string& help);

/// A validator that refuses an empty name for an output that is not -o (gallery's OUT_DIR,
/// simulate's --csv): bad input (exit 2) "NAME: expected WHAT, got an empty name (HINT)", as
/// add_out_option words it, never a failed write to "" or a write into the current folder.
CLI::Validator no_empty_output(const std::string& what, const std::string& hint);

/// Flushes the standard output; an OutputError naming it where anything printed could not be
/// written (`bookspin fit … > /dev/full`: exit 1, not 0 with every line lost). Called after
/// every command (cli.cpp), and by info before it asks for the GL set-up.
void flush_standard_output();

/// `--frames N` is `--set time.frames=N`, after the user's own --set (so it wins); N = 0: not
/// given, nothing appended.
void frames_as_override(int frames, std::vector<std::string>& overrides);

}  // namespace bookspin::cli
