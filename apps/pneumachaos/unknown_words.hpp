#pragma once
// A mistyped command or option named as such, with the nearest known one: CLI11
// alone reads `simulate --duraton 5` as a scenario file "5" that does not exist and
// `simulat` as no command at all.

#include <CLI/CLI.hpp>

namespace pneumachaos::cli {

/// Throws Error ("unknown command ...; did you mean ...?" or "unknown option ...; did you
/// mean ...?") when argv[1] is not one of app's commands, or a "--long" argument of the
/// chosen command is none of its options; returns otherwise. Arguments after "--" and
/// values of options are not options.
void refuse_unknown_words(const CLI::App& app, int argc, char** argv);

}  // namespace pneumachaos::cli
