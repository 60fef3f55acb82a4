#include "pneumachaos/simulate/measured_channels.hpp"

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "pneumachaos/model/variation.hpp"
#include "simulate/transducer_stages.hpp"

namespace pneumachaos {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// One channel's transducer in the channel's own units (absolute for pressures); a full scale
// of +-infinity is no range.
struct ChannelChain {
  double noise_sd = 0.0;
  double bandwidth_Hz = 0.0;
  int bits = 0;
  double lo = -kInf;
  double hi = kInf;
  NoiseStream stream = NoiseStream::kVelocity;
};

ChannelChain velocity_chain(const VelocityTransducer& t) {
  ChannelChain c;
  c.noise_sd = t.noise_m_per_s;
  c.bandwidth_Hz = t.bandwidth_Hz;
  c.bits = t.bits;
  if (t.range_m_per_s > 0.0) {
    c.lo = -t.range_m_per_s;
    c.hi = t.range_m_per_s;
  }
  return c;
}

ChannelChain pressure_chain(const PressureTransducer& t, double ambient_Pa, NoiseStream stream) {
  ChannelChain c;
  c.noise_sd = t.noise_Pa;
  c.bandwidth_Hz = t.bandwidth_Hz;
  c.bits = t.bits;
  if (t.range_Pa > 0.0) {
    c.lo = ambient_Pa;
    c.hi = ambient_Pa + t.range_Pa;
  }
  c.stream = stream;
  return c;
}

// The order of docs/model.md, "The transducer": lag, noise, converter. The noise is the
// electronics' and the converter's, after the lag, so its sd is the sd in the record.
std::vector<double> record(const std::vector<double>& signal, const ChannelChain& c, double rate_Hz,
                           std::uint64_t seed) {
  std::vector<double> y = first_order_lag(signal, rate_Hz, c.bandwidth_Hz);
  if (c.noise_sd > 0.0) {
    const std::vector<double> noise = sensor_noise(seed, c.stream, y.size(), c.noise_sd);
    for (std::size_t i = 0; i < y.size(); ++i) y[i] += noise[i];
  }
  quantise(y, c.bits, c.lo, c.hi);
  return y;
}

void add_record(TimeSeries& series, const std::string& name, const ChannelChain& c,
                std::uint64_t seed) {
  const Channel& signal = series.channel(name);
  std::string unit = signal.unit;  // add_channel may move the channels
  std::vector<double> measured = record(signal.values, c, series.rate_Hz(), seed);
  series.add_channel(name + "_measured", std::move(unit), std::move(measured));
}

}  // namespace

void add_measured_channels(TimeSeries& series, const TransducerParams& transducer,
                           double ambient_pressure_Pa, std::uint64_t seed) {
  const PressureTransducer& p = transducer.pressure;
  add_record(series, "v", velocity_chain(transducer.velocity), seed);
  add_record(series, "P1", pressure_chain(p, ambient_pressure_Pa, NoiseStream::kPressure1), seed);
  add_record(series, "P2", pressure_chain(p, ambient_pressure_Pa, NoiseStream::kPressure2), seed);
}

void add_scenario_measured_channels(TimeSeries& series, const Scenario& scenario,
                                    std::uint64_t seed) {
  if (scenario.transducer.ideal()) return;
  add_measured_channels(series, scenario.transducer, scenario.ambient_pressure_Pa, seed);
}

}  // namespace pneumachaos
