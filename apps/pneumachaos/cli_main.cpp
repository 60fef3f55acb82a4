// The command line's parse, dispatch and error handling (cli_main.hpp).

#include <fmt/format.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <system_error>
#include <map>

#include "cli_main.hpp"
#include "flag_names.hpp"
#include "unknown_words.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/sweep/sweep_runner.hpp"

namespace {

// Whether argv[1] is one of the registered commands' names.
bool names_a_command(const CLI::App& app, int argc, char** argv) {
  if (argc < 2) return false;
  for (const auto* sub : app.get_subcommands({})) {
    if (sub->get_name() == argv[1]) return true;
  }
  return false;
}

int run(int argc, char** argv, std::span<const pneumachaos::cli::AddCommand> commands,
        pneumachaos::cli::Elsewhere elsewhere) {
  CLI::App app{"pneumachaos: stick-slip and chaotic oscillation of pneumatic cylinders"};
  app.set_version_flag("--version", std::string("pneumachaos ") + PNEUMACHAOS_VERSION +
                                        (pneumachaos::sweeps_support_mpi() ? " (MPI)" : ""));
  app.require_subcommand(1);
  std::map<CLI::App*, pneumachaos::cli::Action> actions;
  for (const auto add : commands) {
    auto action = add(app);
    actions[app.get_subcommands({}).back()] = std::move(action);
  }
  if (elsewhere != nullptr && !names_a_command(app, argc, argv)) return elsewhere(argc, argv);
  pneumachaos::cli::refuse_unknown_words(app, argc, argv);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version print and succeed; every other parse error is a usage error (2),
    // not CLI11's own codes, so scripts can rely on the README's exit codes.
    const int code = app.exit(e);
    return code == 0 ? pneumachaos::cli::kExitOk : pneumachaos::cli::kExitBadInput;
  }
  for (auto* sub : app.get_subcommands()) return actions.at(sub)();
  return pneumachaos::cli::kExitOk;
}

// Output to a full disk or a closed descriptor must not end as success: stdout is flushed and
// checked before the exit code is decided.
int checked_stdout(int code) {
  std::cout.flush();
  const bool failed = std::fflush(stdout) != 0 || std::ferror(stdout) != 0 || !std::cout;
  if (!failed) return code;
  fmt::print(stderr, "pneumachaos: error: cannot write to standard output: {}\n",
             std::strerror(errno != 0 ? errno : EIO));
  return code == pneumachaos::cli::kExitOk ? pneumachaos::cli::kExitRunFailed : code;
}

}  // namespace

namespace pneumachaos::cli {

int cli_main(int argc, char** argv, std::span<const AddCommand> commands, Elsewhere elsewhere) {
  try {
    return checked_stdout(run(argc, argv, commands, elsewhere));
  } catch (const std::filesystem::filesystem_error& e) {
    fmt::print(stderr, "pneumachaos: error: {}\n", e.what());
    return pneumachaos::cli::kExitRunFailed;
  } catch (const std::system_error& e) {
    // fmt reports a failed write to standard output this way.
    fmt::print(stderr, "pneumachaos: error: cannot write output: {}\n", e.what());
    return pneumachaos::cli::kExitRunFailed;
  } catch (const pneumachaos::Error& e) {
    using namespace pneumachaos::cli;
    fmt::print(stderr, "pneumachaos: error: {}\n", message_as_typed(e, common_flag_names()));
    return dynamic_cast<const pneumachaos::RunError*>(&e) ? kExitRunFailed : kExitBadInput;
  } catch (const std::exception& e) {
    fmt::print(stderr, "pneumachaos: internal error: {}\n", e.what());
    return 70;  // EX_SOFTWARE
  } catch (...) {
    return 70;
  }
}

}  // namespace pneumachaos::cli
