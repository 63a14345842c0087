#include "cli/commands.hpp"

int main(int argc, char** argv) { return bookspin::cli::run_cli(argc, argv); }
