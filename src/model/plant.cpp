#include "pneumachaos/model/plant.hpp"

#include "pneumachaos/core/error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "level_field.hpp"
#include "plant_equations.hpp"

namespace pneumachaos {
namespace {

using plant_detail::direction_of;
using plant_detail::kGuide;
using plant_detail::kSeal;
using plant_detail::mode_of;
using plant_detail::moving;
using plant_detail::quasi_static;

void set_mode(Mode& m, std::size_t contact, ContactMode c) {
  m.value[contact] = static_cast<std::int8_t>(c);
}

// The rate the quasi-static limit is switched on is c |v| / g: LuGre's bristle relaxes at
// sigma0 |v| / g, the slowest GMS element loads at 4 |v| / r_N (docs/model.md, "Friction").
double rate_per_speed_over_level(const FrictionParams& p) {
  if (p.kind == FrictionKind::kGms) return friction_law::gms_loading_rate_per_speed_over_level(p);
  return p.lugre.sigma0_N_per_m;
}

// An upper bound of that rate c |v| / g from a lower bound of g (its
// smaller level, the pressure term only where it lowers g, the texture at its deepest), with
// no exp or sin: the switching function checks it at every step of every run
// (docs/notes/performance.md).
double relaxation_rate_bound(const TabulatedFriction& p, const FrictionInput& in, int direction) {
  double texture_low = 1.0;
  for (const TextureMode& m : p.texture) texture_low -= std::abs(m.amplitude);
  if (p.level_table) texture_low += p.level_table->lowest();
  const double gauge = std::min(in.gauge_sum_Pa, 0.0);
  const double level_low = std::min(p.curve.coulomb_N + p.pressure_gain.coulomb_N_per_Pa * gauge,
                                    p.curve.static_N + p.pressure_gain.static_N_per_Pa * gauge);
  const double g_low = level_low * texture_low;
  if (!(g_low > 0.0)) return std::numeric_limits<double>::infinity();
  return rate_per_speed_over_level(p) * direction * in.v_m_per_s / g_low;
}

// A random level field deep enough to cancel the seal's friction somewhere along the bore
// would make it push instead of resist: refused, naming the key that draws the field.
void require_positive_level(const TabulatedFriction& p) {
  if (!p.level_table) return;
  double low = 1.0 + p.level_table->lowest();
  for (const TextureMode& m : p.texture) low -= std::abs(m.amplitude);
  if (!(low > 0.0))
    throw Error("variation.seal_noise_rel",
                "the random seal level (with the texture) reaches zero friction along the bore; "
                "use a smaller relative level");
}

}  // namespace

Plant::Plant(const Scenario& scenario)
    : geometry_(scenario.cylinder),
      load_(scenario.load),
      circuit_(scenario.circuit.kind),
      ambient_Pa_(scenario.ambient_pressure_Pa),
      supply_Pa_(scenario.supply_pressure_Pa()),
      polytropic_exponent_(scenario.polytropic_exponent),
      RT_(scenario.gas.R_J_per_kgK * scenario.temperature_K),
      thermal_(scenario.thermal),
      kappa_(scenario.gas.heat_capacity_ratio),
      R_(scenario.gas.R_J_per_kgK),
      T_supply_(scenario.temperature_K) {
  scenario.validate();
  A1_ = geometry_.area_head_m2();
  A2_ = geometry_.area_rod_m2();
  // The valves are sized for supply-temperature air upstream; with the energy equation the
  // chambers' own temperatures correct the flow out of them (plant_equations.hpp).
  valve1_.emplace(scenario.valve, scenario.gas, scenario.circuit.S1(), scenario.temperature_K);
  valve2_.emplace(scenario.valve, scenario.gas, scenario.circuit.S2(), scenario.temperature_K);
  if (scenario.valve_opening.lagged()) {
    valve1_time_constant_s_ = scenario.valve_opening.time_constant_s;
    layout_.S1_open = layout_.append("S1_open", "-", 1e-2, StateBlock::kValveOpening);
  }
  if (scenario.supply_line.enabled()) {
    line_.emplace(scenario.supply_line, scenario.valve, scenario.gas, supply_Pa_,
                  scenario.temperature_K);
    layout_.P0 = layout_.append("P0", "Pa", 1e4, StateBlock::kSupplyLine);
  }
  if (thermal_.chamber_model == ChamberModel::kEnergy) {
    layout_.T1 = layout_.append("T1", "K", 1.0, StateBlock::kTemperatures);
    layout_.T2 = layout_.append("T2", "K", 1.0, StateBlock::kTemperatures);
  }
  // The bore's texture is tabulated over the stroke and kBoreMargin_m either side; beyond it
  // the sines are evaluated. The seal's random level is tabulated over its period and repeats.
  const auto tabulated = [&](const FrictionParams& p) {
    return make_friction_model(
        p, tabulate_texture(p.texture, -kBoreMargin_m, geometry_.stroke_m + kBoreMargin_m),
        tabulate_level_field(p.level_field, -kBoreMargin_m));
  };
  seal_ = tabulated(scenario.friction);
  require_positive_level(seal_->params());
  if (seal_->state_count() > 0) {
    layout_.seal_z_count = seal_->state_count();
    layout_.seal_z = layout_.append(seal_->state_name(), seal_->state_unit(), seal_->state_scale(),
                                    StateBlock::kSealFriction, layout_.seal_z_count);
  }
  const bool spring = load_.coupling == LoadCoupling::kSpring;
  piston_mass_ = spring ? load_.piston_mass_kg : load_.mass_kg;
  if (spring) {
    contacts_ = 2;
    guide_ = tabulated(load_.guide_friction);
    layout_.load_x = layout_.append("x_load", "m", 1e-3, StateBlock::kLoadBody);
    layout_.load_v = layout_.append("v_load", "m/s", 1e-2, StateBlock::kLoadBody);
    if (guide_->state_count() > 0) {
      layout_.guide_z_count = guide_->state_count();
      layout_.guide_z =
          layout_.append(std::string(guide_->state_name()) + "_guide", guide_->state_unit(),
                         guide_->state_scale(), StateBlock::kGuideFriction, layout_.guide_z_count);
    }
  }
  channels_ = build_channels();
}

std::array<double, 2> Plant::mass_flows(double P1_Pa, double P2_Pa) const {
  return {valve1_->mass_flow(supply_Pa_, P1_Pa), valve2_->mass_flow(P2_Pa, ambient_Pa_)};
}

double Plant::holding_force(std::size_t contact, std::span<const double> x) const {
  const auto& L = layout_;
  const FrictionModel& f = contact == kSeal ? *seal_ : *guide_;
  const std::size_t z0 = contact == kSeal ? L.seal_z : L.guide_z;
  const std::size_t nz = contact == kSeal ? L.seal_z_count : L.guide_z_count;
  return f.holding_force_N(friction_input<double>(contact, x),
                           nz == 0 ? std::span<const double>{} : x.subspan(z0, nz));
}

// Dimensionless, so the two conditions of entry can share one function: the contact enters
// where both its rate has reached the threshold and its internal state has settled within
// kSettled: LuGre's bristle on its steady state, every GMS element on its share or above it
// (the force the limit drops on entry, sigma0 |z - z0| or k sum (r_i - m_i), is then below
// kSettled g: a state still catching up after a fast start keeps the full law).
double Plant::quasi_static_switch(std::size_t contact, const Mode& mode,
                                  std::span<const double> x) const {
  constexpr double kSettled = 1e-4;
  const ContactMode m = mode_of(mode, contact);
  const TabulatedFriction& p = friction_of(contact).params();
  const FrictionInput in = friction_input<double>(contact, x);
  const int d = direction_of(m);
  const double on = p.quasi_static_threshold();
  // Far from the threshold (most steps) the bound decides the sign alone; it is positive
  // there, as the exact function is, so the switch is located on the exact function.
  if (!quasi_static(m)) {
    const double bound = relaxation_rate_bound(p, in, d);
    if (bound < on) return 1.0 - bound / on;
  }
  const double g = friction_law::stribeck_level_N(p, in, d * in.v_m_per_s, true);
  const double ratio = rate_per_speed_over_level(p) * d * in.v_m_per_s / g / on;  // rate / threshold
  if (quasi_static(m)) return ratio - p.quasi_static_exit_fraction();
  const double* z = x.data() + (contact == kSeal ? layout_.seal_z : layout_.guide_z);
  if (p.kind == FrictionKind::kGms) {
    if (ratio < 1.0) return 1.0 - ratio;  // the limit's deflections need a derivative: skip
    std::array<double, kMaxGmsElements> on{};
    limit_deflections(contact, mode, x, on.data());
    return friction_law::gms_distance_from_limit(p, g, z, on.data()) / kSettled - 1.0;
  }
  const double z0 = d * g / p.lugre.sigma0_N_per_m;  // the steady state, g sgn v / sigma0
  return std::max(1.0 - ratio, std::abs(*z - z0) / (kSettled * std::abs(z0)) - 1.0);
}

// On the steady state the full LuGre force equals the quasi-static one (dz/dt = 0 there), so
// the force is continuous where the contact leaves the limit. GMS elements enter holding their
// shares (those above keep their deflection) and leave at the limit's deflections, computed in
// the limit's mode `quasi` before it is left.
void Plant::settle_bristle(std::size_t contact, const Mode& quasi, bool entering,
                           std::span<double> x) const {
  const TabulatedFriction& p = friction_of(contact).params();
  const std::size_t z0 = contact == kSeal ? layout_.seal_z : layout_.guide_z;
  const FrictionInput in = friction_input<double>(contact, std::span<const double>(x));
  if (p.kind != FrictionKind::kGms) {
    friction_of(contact).steady_state(in, x.subspan(z0, 1));
  } else if (entering) {
    const int d = direction_of(mode_of(quasi, contact));
    const double g = friction_law::stribeck_level_N(p, in, d * in.v_m_per_s, true);
    friction_law::gms_settle_on_shares(p, g, x.data() + z0, d);
  } else {
    std::array<double, kMaxGmsElements> on{};
    limit_deflections(contact, quasi, x, on.data());
    std::copy_n(on.begin(), p.gms.count, x.begin() + static_cast<std::ptrdiff_t>(z0));
  }
}

double Plant::head_pressure_rate(std::span<const double> x) const {
  if (!layout_.has_temperatures()) return head_chamber_rate(x);
  std::vector<double> rates(layout_.size);
  chamber_energy_rates(x, std::span<double>(rates));
  return rates[layout_.P1];
}
double Plant::rod_pressure_rate(std::span<const double> x) const {
  if (!layout_.has_temperatures()) return rod_chamber_rate(x);
  std::vector<double> rates(layout_.size);
  chamber_energy_rates(x, std::span<double>(rates));
  return rates[layout_.P2];
}

void Plant::derivative(const Mode& mode, std::span<const double> x, std::span<double> dxdt,
                       double /*t*/) const {
  evaluate(mode, x, dxdt);
}

Plant::EventList Plant::active_events(const Mode& mode) const {
  EventList list;
  const auto add = [&](EventType t, std::size_t c) {
    list.items[list.count++] = {t, static_cast<std::uint8_t>(c)};
  };
  for (std::size_t c = 0; c < contacts_; ++c) {
    const ContactMode m = mode_of(mode, c);
    // The quasi-static limit is left (at a fraction of its rate) before v can reach 0.
    if (quasi_static(m)) {
      add(EventType::kQuasiExit, c);
    } else if (direction_of(m) != 0) {
      add(EventType::kVelocityZero, c);
    }
    const TabulatedFriction& p = friction_of(c).params();
    if ((m == ContactMode::kSmoothPos || m == ContactMode::kSmoothNeg) &&
        p.quasi_static_threshold() > 0.0)
      add(EventType::kQuasiEnter, c);  // LuGre's and GMS's: other models have no such limit
    if (m == ContactMode::kStuck) add(EventType::kBreakaway, c);
    if (m == ContactMode::kAtStop) add(EventType::kStopRelease, c);
    if (c == kSeal && moving(m)) {
      if (m != ContactMode::kSlidePos) add(EventType::kStopHit, c);
      if (!geometry_.volumes_frozen()) add(EventType::kStrokeEnd, c);
    }
  }
  return list;
}

std::size_t Plant::event_count(const Mode& mode) const { return active_events(mode).count; }

void Plant::event_functions(const Mode& mode, std::span<const double> x, double /*t*/,
                            std::span<double> g) const {
  const auto& L = layout_;
  const EventList list = active_events(mode);
  for (std::size_t i = 0; i < list.count; ++i) {
    const std::size_t c = list.items[i].contact;
    const std::size_t iv = c == kSeal ? L.v : L.load_v;
    switch (list.items[i].type) {
      case EventType::kVelocityZero:
        g[i] = direction_of(mode_of(mode, c)) * x[iv];
        break;
      case EventType::kBreakaway:
        g[i] = holding_force(c, x) - std::abs(drive_force<double>(c, x));
        break;
      case EventType::kStopRelease:
        g[i] = holding_force(c, x) - drive_force<double>(c, x);
        break;
      case EventType::kStopHit:
        g[i] = x[L.x];
        break;
      case EventType::kStrokeEnd:
        g[i] = geometry_.stroke_m - x[L.x];
        break;
      case EventType::kQuasiEnter:
      case EventType::kQuasiExit:
        g[i] = quasi_static_switch(c, mode, x);
        break;
    }
  }
}

ContactMode Plant::rest_mode(std::size_t contact, std::span<const double> x, bool at_stop) const {
  const FrictionModel& f = contact == kSeal ? *seal_ : *guide_;
  const double drive = drive_force<double>(contact, x);
  const double hold = holding_force(contact, x);
  if (at_stop) {
    if (drive - hold <= 0.0) return ContactMode::kAtStop;
    return f.has_stiction() ? ContactMode::kSlidePos : ContactMode::kSmoothPos;
  }
  // A smooth contact at v = 0 accelerates as drive - sigma0 z (dz/dt = 0 there).
  if (!f.has_stiction()) return drive - hold >= 0.0 ? ContactMode::kSmoothPos : ContactMode::kSmoothNeg;
  if (std::abs(drive) <= hold) return ContactMode::kStuck;
  return drive > 0 ? ContactMode::kSlidePos : ContactMode::kSlideNeg;
}

EventOutcome Plant::apply_event(std::size_t which, Mode& mode, std::span<double> x,
                                double /*t*/) const {
  const auto& L = layout_;
  const ActiveEvent ev = active_events(mode).items.at(which);
  const std::size_t c = ev.contact;
  const std::size_t ix = c == kSeal ? L.x : L.load_x;
  const std::size_t iv = c == kSeal ? L.v : L.load_v;
  EventOutcome out;
  switch (ev.type) {
    case EventType::kVelocityZero: {
      const ContactMode m = mode_of(mode, c);
      if (m == ContactMode::kSmoothPos || m == ContactMode::kSmoothNeg) {
        // Located where v is already past 0: the same motion continues on the other branch.
        set_mode(mode, c, m == ContactMode::kSmoothPos ? ContactMode::kSmoothNeg
                                                       : ContactMode::kSmoothPos);
        out.kind = EventKind::kReversal;
        break;
      }
      x[iv] = 0.0;
      const ContactMode next = rest_mode(c, x, false);
      out.kind = next == ContactMode::kStuck ? EventKind::kStick : EventKind::kReversal;
      set_mode(mode, c, next);
      break;
    }
    case EventType::kBreakaway:
      set_mode(mode, c,
               drive_force<double>(c, x) > 0 ? ContactMode::kSlidePos : ContactMode::kSlideNeg);
      out.kind = EventKind::kSlip;
      break;
    case EventType::kStopRelease:
      set_mode(mode, c,
               seal_->has_stiction() ? ContactMode::kSlidePos : ContactMode::kSmoothPos);
      out.kind = EventKind::kStopRelease;
      break;
    case EventType::kStopHit:
      // A hard stop: no penetration, the velocity is set to zero (docs/model.md, "Start and end of a run").
      x[ix] = 0.0;
      x[iv] = 0.0;
      set_mode(mode, c, rest_mode(c, x, true));
      out.kind = EventKind::kStopHit;
      break;
    case EventType::kQuasiEnter:
    case EventType::kQuasiExit: {
      const int d = direction_of(mode_of(mode, c));
      const bool enter = ev.type == EventType::kQuasiEnter;
      const Mode before = mode;
      set_mode(mode, c,
               enter ? (d > 0 ? ContactMode::kQuasiPos : ContactMode::kQuasiNeg)
                     : (d > 0 ? ContactMode::kSmoothPos : ContactMode::kSmoothNeg));
      settle_bristle(c, enter ? mode : before, enter, x);
      out.kind = EventKind::kModeSwitch;
      break;
    }
    case EventType::kStrokeEnd:
      x[ix] = geometry_.stroke_m;
      out.kind = EventKind::kTerminal;
      out.terminate = true;
      out.message = "end of stroke reached";
      break;
  }
  return out;
}

Mode Plant::sliding_mode(int direction) const {
  Mode mode;
  const auto slide = [&](const FrictionModel& f) {
    if (!f.has_stiction()) return ContactMode::kSmooth;
    return direction > 0 ? ContactMode::kSlidePos : ContactMode::kSlideNeg;
  };
  set_mode(mode, kSeal, slide(*seal_));
  if (contacts_ == 2) set_mode(mode, kGuide, slide(*guide_));
  return mode;
}

Mode Plant::initial_mode(std::span<const double> x, double /*t*/) const {
  Mode mode;
  const auto& L = layout_;
  const auto start = [&](std::size_t c, double pos, double vel, bool can_stop) {
    if (vel != 0.0) {
      const FrictionModel& f = c == kSeal ? *seal_ : *guide_;
      set_mode(mode, c,
               !f.has_stiction() ? (vel > 0 ? ContactMode::kSmoothPos : ContactMode::kSmoothNeg)
               : vel > 0         ? ContactMode::kSlidePos
                                 : ContactMode::kSlideNeg);
      return;
    }
    set_mode(mode, c, rest_mode(c, x, can_stop && pos <= 0.0));
  };
  start(kSeal, x[L.x], x[L.v], true);
  if (contacts_ == 2) start(kGuide, x[L.load_x], x[L.load_v], false);
  return mode;
}

PlantOutputs Plant::outputs(const Mode& mode, std::span<const double> x) const {
  PlantOutputs out;
  std::array<double, kMaxGmsElements> scratch{};  // the most internal states of a contact
  const auto reported = [&](std::size_t c) {
    const ContactMode m = mode_of(mode, c);
    const double drive = drive_force<double>(c, x);
    if (m == ContactMode::kStuck) return drive;  // static friction balances the drive
    if (m == ContactMode::kAtStop) {
      // The stop takes whatever pushes into it; friction holds at most its holding force.
      return seal_->has_stiction() ? std::clamp(drive, 0.0, holding_force(c, x))
                                   : holding_force(c, x);
    }
    if (quasi_static(m) && friction_of(c).params().kind == FrictionKind::kGms)
      return limit_force(c, mode, x);
    return friction_force<double>(c, m, x, std::span<double>(scratch));
  };
  out.seal_friction_N = reported(kSeal);
  if (contacts_ == 2) out.guide_friction_N = reported(kGuide);
  out.drive_force_N = drive_force<double>(kSeal, x);
  const auto [W1, W2] = mass_flows(x[layout_.P1], x[layout_.P2]);
  const bool ideal_S1 = !layout_.has_supply_line() && !layout_.has_valve_opening();
  out.W1_kg_per_s = ideal_S1 ? W1 : valve1_inflow(x);
  out.W2_kg_per_s = W2;
  out.piston_stuck = !moving(mode_of(mode, kSeal));
  return out;
}

}  // namespace pneumachaos
