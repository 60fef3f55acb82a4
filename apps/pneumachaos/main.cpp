// pneumachaos: command-line entry point.

#include <fmt/format.h>

#include <iostream>
#include <map>

#include "commands.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/sweep/sweep_runner.hpp"

namespace {

int run(int argc, char** argv) {
  CLI::App app{"pneumachaos: stick-slip and chaotic oscillation of pneumatic cylinders"};
  app.set_version_flag("--version", std::string("pneumachaos ") + PNEUMACHAOS_VERSION +
                                        (pneumachaos::sweeps_support_mpi() ? " (MPI)" : ""));
  app.require_subcommand(1);
  std::map<CLI::App*, pneumachaos::cli::Action> actions;
  const auto add = [&](pneumachaos::cli::Action (*f)(CLI::App&)) {
    auto action = f(app);
    actions[app.get_subcommands({}).back()] = std::move(action);
  };
  add(pneumachaos::cli::add_simulate);
  add(pneumachaos::cli::add_scenario);
  add(pneumachaos::cli::add_stability);
  add(pneumachaos::cli::add_analyze);
  add(pneumachaos::cli::add_sweep);
  add(pneumachaos::cli::add_lyapunov);
  add(pneumachaos::cli::add_reproduce);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  for (auto* sub : app.get_subcommands()) return actions.at(sub)();
  return pneumachaos::cli::kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  // Every failure ends here with a message and an exit code, never as an uncaught exception.
  try {
    return run(argc, argv);
  } catch (const pneumachaos::Error& e) {
    fmt::print(stderr, "pneumachaos: error: {}\n", e.what());
    return pneumachaos::cli::kExitBadInput;
  } catch (const std::exception& e) {
    fmt::print(stderr, "pneumachaos: internal error: {}\n", e.what());
    return 70;  // EX_SOFTWARE
  } catch (...) {
    return 70;
  }
}
