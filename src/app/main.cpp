#include "app/commands.hpp"

int main(int argc, char** argv) { return bookspin::app::run_cli(argc, argv); }
