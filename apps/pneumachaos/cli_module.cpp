// The module libpneumachaos_cli.so: the command line with every command, for the command
// lines the program does not run itself (main.cpp).

#include <array>

#include "cli_main.hpp"

namespace {

using namespace pneumachaos::cli;

constexpr std::array<AddCommand, 10> kAllCommands{
    add_simulate, add_scenario,  add_stability, add_analyze, add_sweep,
    add_lyapunov, add_reproduce, add_friction,  add_fit,     add_calibrate};

}  // namespace

extern "C" __attribute__((visibility("default"))) int pneumachaos_cli_main(int argc,
                                                                          char** argv) {
  return cli_main(argc, argv, kAllCommands);
}
