#pragma once
// The command line as one function over a set of commands: the program itself runs it with
// the commands that need neither Ceres nor the report, the module libpneumachaos_cli.so with
// every command (main.cpp says which runs when).

#include <span>

#include "commands.hpp"

namespace pneumachaos::cli {

using AddCommand = Action (*)(CLI::App&);
/// Runs a command line that names none of the registered commands; returns the exit code.
using Elsewhere = int (*)(int argc, char** argv);

/// Parses argv with `commands` registered, runs the chosen one and returns the exit code;
/// every failure ends here with a message, never as an uncaught exception. With `elsewhere`,
/// a command line whose first argument is not one of `commands` (another command, --help,
/// --version, nothing) goes to it instead, unparsed.
int cli_main(int argc, char** argv, std::span<const AddCommand> commands,
             Elsewhere elsewhere = nullptr);

}  // namespace pneumachaos::cli
