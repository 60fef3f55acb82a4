// The command line linked plainly, without the module that pneumachaos opens on demand: every
// command in one program, or (PNEUMACHAOS_LINK_CALIBRATE 0) every command but calibrate. Only
// for weighing the module against a plain link (bench/startup_variants.sh;
// docs/notes/performance.md, "Start-up").
#include <array>

#include "cli_main.hpp"

namespace {
using namespace pneumachaos::cli;
#if PNEUMACHAOS_LINK_CALIBRATE
constexpr std::array<AddCommand, 10> kAllCommands{
    add_simulate, add_scenario,  add_stability, add_analyze, add_sweep,
    add_lyapunov, add_reproduce, add_friction,  add_fit,     add_calibrate};
#else
constexpr std::array<AddCommand, 9> kAllCommands{add_simulate, add_scenario,  add_stability,
                                                 add_analyze,  add_sweep,     add_lyapunov,
                                                 add_reproduce, add_friction, add_fit};
#endif
}  // namespace

int main(int argc, char** argv) { return cli_main(argc, argv, kAllCommands); }
