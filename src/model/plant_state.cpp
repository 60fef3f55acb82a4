// The Plant's state as a whole: where a run starts, the full state at an operating point, the
// states' magnitudes and the sampled output columns. Every block of StateLayout is filled or
// read here, so a new block is added in the Plant alone (docs/architecture.md).
#include "pneumachaos/model/plant.hpp"

namespace pneumachaos {

std::vector<double> Plant::initial_state() const {
  std::vector<double> x(layout_.size, 0.0);
  x[layout_.P1] = ambient_Pa_;
  x[layout_.P2] = supply_Pa_;
  if (layout_.has_temperatures()) x[layout_.T1] = x[layout_.T2] = T_supply_;
  if (layout_.has_supply_line()) x[layout_.P0] = supply_Pa_;  // charged while S1 was shut
  if (layout_.has_valve_opening()) x[layout_.S1_open] = 0.0;  // S1 starts to open at t = 0
  // The seal (and guide) rested before the valve switched.
  if (layout_.seal_z_count > 0)
    seal_->rest_state(std::span<double>(x).subspan(layout_.seal_z, layout_.seal_z_count));
  if (layout_.guide_z_count > 0)
    guide_->rest_state(std::span<double>(x).subspan(layout_.guide_z, layout_.guide_z_count));
  return x;
}

void Plant::settle_internal_states(const FrictionModel& f, const FrictionInput& in,
                                   std::span<double> z) {
  if (in.v_m_per_s == 0.0) {
    f.rest_state(z);
  } else {
    f.steady_state(in, z);
  }
}

std::vector<double> Plant::state_at(const OperatingPoint& op) const {
  const StateLayout& L = layout_;
  std::vector<double> s(L.size, 0.0);
  const std::span<double> all(s);
  const double x0 = op.position_m;
  const double v = op.velocity_m_per_s;
  s[L.x] = x0;
  s[L.v] = v;
  s[L.P1] = op.P1_Pa;
  s[L.P2] = op.P2_Pa;
  if (L.has_temperatures()) s[L.T1] = s[L.T2] = T_supply_;
  if (L.has_supply_line()) s[L.P0] = supply_Pa_;
  if (L.has_valve_opening()) s[L.S1_open] = 1.0;  // a motion under way: S1 has opened
  const FrictionInput seal_in{v, op.P1_Pa + op.P2_Pa - 2.0 * ambient_Pa_, x0};
  if (L.seal_z_count > 0)
    settle_internal_states(*seal_, seal_in, all.subspan(L.seal_z, L.seal_z_count));
  if (L.has_load_body()) {
    // The load rides with the piston, its spring deflected by what holds it back: the guide's
    // steady friction at this velocity (none at rest) and the external force.
    const FrictionInput guide_in{v, 0.0, x0};
    const double F_guide = v != 0.0 ? guide_->steady_force_N(guide_in) : 0.0;
    s[L.load_x] = x0 - (F_guide + load_.external_force_N) / load_.coupling_stiffness_N_per_m;
    s[L.load_v] = v;
    if (L.guide_z_count > 0)
      settle_internal_states(*guide_, guide_in, all.subspan(L.guide_z, L.guide_z_count));
  }
  return s;
}

std::vector<double> Plant::state_scales() const {
  std::vector<double> s;
  s.reserve(layout_.size);
  for (const StateLayout::Entry& e : layout_.entries) s.push_back(e.scale);
  return s;
}

std::vector<OutputChannel> Plant::build_channels() const {
  using Source = OutputChannel::Source;
  std::vector<OutputChannel> out;
  const auto states = [&](StateBlock block) {
    for (std::size_t i = 0; i < layout_.size; ++i) {
      const StateLayout::Entry& e = layout_.entries[i];
      if (e.block == block) out.push_back({e.name, e.unit, Source::kState, i});
    }
  };
  states(StateBlock::kPiston);
  states(StateBlock::kChambers);
  out.push_back({"F_friction", "N", Source::kSealFriction, 0});
  states(StateBlock::kSealFriction);
  if (layout_.has_load_body()) {
    states(StateBlock::kLoadBody);
    out.push_back({"F_guide", "N", Source::kGuideFriction, 0});
    states(StateBlock::kGuideFriction);
  }
  states(StateBlock::kTemperatures);
  states(StateBlock::kSupplyLine);
  states(StateBlock::kValveOpening);
  out.push_back({"stuck", "-", Source::kStuck, 0});
  return out;
}

void Plant::sample(const Mode& mode, std::span<const double> x, std::vector<double>& row) const {
  using Source = OutputChannel::Source;
  const PlantOutputs out = outputs(mode, x);
  row.clear();
  for (const OutputChannel& c : channels_) {
    switch (c.source) {
      case Source::kState: row.push_back(x[c.state]); break;
      case Source::kSealFriction: row.push_back(out.seal_friction_N); break;
      case Source::kGuideFriction: row.push_back(out.guide_friction_N); break;
      case Source::kStuck: row.push_back(out.piston_stuck ? 1.0 : 0.0); break;
    }
  }
}

}  // namespace pneumachaos
