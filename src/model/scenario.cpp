#include "pneumachaos/model/scenario.hpp"

#include <fmt/format.h>

#include "pneumachaos/core/error.hpp"

namespace pneumachaos {
namespace {

// Default valve areas of the two circuits (MODEL.md): the meter-out pair is the paper's chaotic
// example (Fig. 7, S1 = 2.70 mm^2, S2 = 0.35 mm^2); meter-in throttles the supply with the
// same 0.35 mm^2 and exhausts freely through 20 mm^2 (a fully open 1/4" valve).
constexpr double kMeterOutS1 = 2.70e-6;
constexpr double kMeterOutS2 = 0.35e-6;
constexpr double kMeterInS1 = 0.35e-6;
constexpr double kMeterInS2 = 20e-6;

void check_friction(const FrictionParams& f, const std::string& prefix) {
  if (f.static_N < f.coulomb_N) {
    throw Error(prefix + "Fs_N",
                fmt::format("static friction Fs = {} N must be >= Coulomb friction "
                            "Fc = {} N ({}Fc_N)",
                            f.static_N, f.coulomb_N, prefix));
  }
  if (f.kind != FrictionKind::kClassic && f.static_gain_N_per_Pa < f.coulomb_gain_N_per_Pa) {
    throw Error(prefix + "Fs_gain_N_per_MPa",
                "must be >= " + prefix + "Fc_gain_N_per_MPa so that Fs >= Fc at every pressure");
  }
}

}  // namespace

double CircuitParams::S1() const {
  return S1_m2.value_or(kind == CircuitKind::kMeterOut ? kMeterOutS1 : kMeterInS1);
}
double CircuitParams::S2() const {
  return S2_m2.value_or(kind == CircuitKind::kMeterOut ? kMeterOutS2 : kMeterInS2);
}

void Scenario::validate() const {
  if (cylinder.rod_m >= cylinder.bore_m) {
    throw Error("cylinder.rod_mm", fmt::format("rod diameter {} mm must be smaller than the bore "
                                               "{} mm (cylinder.bore_mm)",
                                               cylinder.rod_m * 1e3, cylinder.bore_m * 1e3));
  }
  if (valve.law == FlowLaw::kIso6358 && valve.laminar_ratio <= valve.critical_ratio) {
    throw Error("valve.laminar_ratio",
                fmt::format("must lie above the critical ratio b = {} (valve.critical_ratio)",
                            valve.critical_ratio));
  }
  check_friction(friction, "friction.");
  if (load.coupling == LoadCoupling::kSpring)
    check_friction(load.guide_friction, "guide_friction.");
  if (run.sample_rate_Hz * run.duration_s > 5e8) {
    throw Error("run.rate_Hz", "rate x duration asks for more than 5e8 samples");
  }
}

Scenario default_scenario() { return Scenario{}; }

}  // namespace pneumachaos
