// pneumachaos: command-line entry point.
//
// The commands that need neither Ceres (friction, fit) nor the report (reproduce) run in this
// program. Every other command line, the overall --help and --version included, goes to the
// module libpneumachaos_cli.so, which holds every command: loading pagmo, Ceres and their
// libraries costs each start 12-14 ms of CPU, a third of an `analyze` of 1e4 samples
// (docs/notes/performance.md, "Start-up", where it is weighed; docs/architecture.md).

#include <fmt/format.h>

#include <array>
#include <cstdio>

#include "cli_main.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/core/module_loader.hpp"

namespace {

using namespace pneumachaos::cli;

constexpr std::array<AddCommand, 6> kCommandsHere{add_simulate, add_scenario, add_stability,
                                                  add_analyze,  add_sweep,    add_lyapunov};

int in_module(int argc, char** argv) {
  using Main = int (*)(int, char**);
  Main full = nullptr;
  try {
    full = reinterpret_cast<Main>(pneumachaos::module_symbol("libpneumachaos_cli.so",
                                                             "pneumachaos_cli_main"));
  } catch (const pneumachaos::Error& e) {
    fmt::print(stderr, "pneumachaos: error: {}\n", e.what());
    return kExitRunFailed;
  }
  return full(argc, argv);
}

}  // namespace

int main(int argc, char** argv) { return cli_main(argc, argv, kCommandsHere, in_module); }
