#pragma once
// The concept the event-locating integrator (module simulate) advances: a piecewise-smooth
// ODE whose right-hand side depends on a discrete mode, plus event functions that end a
// smooth segment. It lives in core so that model (the cylinder Plant) and test reference
// systems can implement it without depending on simulate.

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace pneumachaos {

/// Discrete state of a hybrid system: small integers whose meaning the system defines
/// (e.g. per friction contact: stuck, sliding forward, sliding backward, at a stop).
struct Mode {
  std::array<std::int8_t, 4> value{};
  friend bool operator==(const Mode&, const Mode&) = default;
};

/// Which Boost.Odeint stepper advances a HybridSystem.
enum class StepperKind : std::uint8_t {
  kDopri5,       ///< explicit Dormand-Prince 5(4) with dense output (non-stiff)
  kRosenbrock4,  ///< linearly implicit Rosenbrock 4(3) with dense output (stiff)
};

/// What an event did, as reported back to the integrator and counted in its Summary.
/// kModeSwitch: the same motion continues under another approximation (e.g. LuGre's
/// quasi-static limit); not counted as stick, slip or reversal.
enum class EventKind : std::uint8_t {
  kStick,
  kSlip,
  kReversal,
  kStopHit,
  kStopRelease,
  kTerminal,
  kModeSwitch
};

struct EventOutcome {
  EventKind kind = EventKind::kSlip;
  bool terminate = false;  ///< true ends the run (e.g. end of stroke)
  std::string message;     ///< why, when terminate is set
};

/// A piecewise-smooth system. Rule apart from state: implementations are immutable.
class HybridSystem {
 public:
  virtual ~HybridSystem() = default;

  [[nodiscard]] virtual std::size_t state_size() const = 0;

  /// Right-hand side dx/dt in the given mode. Must be smooth in x and t for a fixed mode.
  virtual void derivative(const Mode& mode, std::span<const double> x, std::span<double> dxdt,
                          double t) const = 0;

  /// Number of event functions active in this mode.
  [[nodiscard]] virtual std::size_t event_count(const Mode& mode) const = 0;

  /// Event functions g_i(x, t): positive while the mode is valid; an event fires where one
  /// becomes <= 0 (zero at the start of a segment is allowed and is not an event).
  virtual void event_functions(const Mode& mode, std::span<const double> x, double t,
                               std::span<double> g) const = 0;

  /// Applies the transition of event `which` at time t: may change the mode and the state
  /// (e.g. set a velocity to exactly zero). Chained transitions are resolved here, so the
  /// returned mode is consistent with the state.
  virtual EventOutcome apply_event(std::size_t which, Mode& mode, std::span<double> x,
                                   double t) const = 0;

  /// The mode consistent with an initial state.
  [[nodiscard]] virtual Mode initial_mode(std::span<const double> x, double t) const = 0;

  /// Exact partial derivatives of derivative() in `mode`: dfdx row-major (dfdx[i n + j] =
  /// d f_i / d x_j, n = state_size()) and dfdt[i] = d f_i / d t. Returns false when the system
  /// has none; the stiff stepper then differentiates numerically.
  virtual bool jacobian(const Mode& /*mode*/, std::span<const double> /*x*/, double /*t*/,
                        std::span<double> /*dfdx*/, std::span<double> /*dfdt*/) const {
    return false;
  }
};

}  // namespace pneumachaos
