#pragma once
// A simulated run as its transducers record it (docs/model.md, "The transducer").

#include <cstdint>

#include "pneumachaos/core/time_series.hpp"
#include "pneumachaos/model/scenario.hpp"
#include "pneumachaos/model/transducer.hpp"

namespace pneumachaos {

/// Adds the channels v_measured [m/s], P1_measured [Pa] and P2_measured [Pa] (absolute): the
/// series' v, P1 and P2 through their transducers, each its first-order lag, then its white
/// noise, then its converter. ambient_pressure_Pa is the zero of the pressure transducers'
/// gauge full scale. The noise of each channel is drawn from its own stream of `seed` (the
/// run's), so the same seed gives the same records. With the transducers ideal, each
/// measured channel equals its signal exactly. Throws Error when v, P1 or P2 is missing or a
/// measured channel is already there.
void add_measured_channels(TimeSeries& series, const TransducerParams& transducer,
                           double ambient_pressure_Pa, std::uint64_t seed);

/// The record `simulate` gives (the command and the Python module alike): with any
/// transducer.* key set, the scenario's measured channels from `seed` are added; with ideal
/// transducers the series is left as simulated, so its columns do not double.
void add_scenario_measured_channels(TimeSeries& series, const Scenario& scenario,
                                    std::uint64_t seed);

}  // namespace pneumachaos
