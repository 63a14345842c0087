#pragma once
// The bookspin program: run_cli() parses the command line and runs the chosen subcommand
// (each one file, src/cli/NAME_command.cpp, listed once in cli.cpp), and what several
// subcommands share. Each subcommand returns the process exit status.
#include <string>

#include "cli/run_guarded.hpp"

namespace bookspin::cli {

/// Every product's on_remake: tells the user on stderr why the existing manifest of the output
/// called `name` did not match ("bookspin: note: NAME: making it again: REASON").
void remake_note(const std::string& name, const std::string& reason);

/// Parses argv and runs the chosen subcommand.
int run_cli(int argc, char** argv);

}  // namespace bookspin::cli
