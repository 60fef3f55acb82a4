#pragma once
// Friction models behind one interface (docs/model.md, "Friction").

#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace pneumachaos {

enum class FrictionKind { kClassic, kStribeck, kLuGre, kGms };

/// Frictional memory of the stribeck model: kLag makes the Stribeck drop follow the velocity
/// with a first-order lag in time (Hess & Soom 1990); kRateState with two state variables
/// that evolve with the slip, as the two-state friction law of Gu, Rice, Ruina & Tse (1984)
/// (docs/model.md, "Friction").
enum class FrictionMemory { kNone, kLag, kRateState };

/// One sinusoidal component of a friction texture along the bore: the friction levels are
/// multiplied by 1 + sum(amplitude * sin(wavenumber * x + phase)).
struct TextureMode {
  double amplitude = 0.0;  ///< relative
  double wavenumber_per_m = 0.0;
  double phase = 0.0;
};

/// A random part of the seal's friction level along the bore (docs/model.md, "Friction"): a
/// stationary Gaussian field with an exponential correlation in position, drawn per run by
/// the variation (variation.seal_noise_rel), written as a sum of sines whose wavenumbers are
/// all harmonics of `period_m`. The field therefore repeats every period, which is longer than
/// the stroke: a piston whose volumes are frozen (cylinder.frozen_position_mm) may travel past
/// the stroke and meets the same bore again, as on a rig that cycles.
struct RandomLevelField {
  std::vector<TextureMode> modes;  ///< empty: no random field
  double period_m = 0.0;
};

class TextureTable;  // src/model/texture_table.hpp

/// Most elements a GMS seal may have (each is one ODE state).
inline constexpr int kMaxGmsElements = 10;

// Each model's parameters in a struct of their own (docs/model.md, "Friction"). The ones the
// friction fits adjust are templates on the scalar type, as BasicFrictionInput: double here,
// an automatic-differentiation scalar in the fits (src/identify/friction_fits.cpp).

/// The friction-velocity curve every model builds on, g(v) = Fc + (Fs - Fc) exp(-(|v|/vs)^delta),
/// and the viscous term B v. Forces in N, velocities in m/s.
template <typename T>
struct BasicStribeckCurve {
  T coulomb_N = T(20.0);                  ///< Fc, kinetic friction level
  T static_N = T(40.0);                   ///< Fs, breakaway (stiction) level
  T viscous_Ns_per_m = T(30.0);           ///< B (classic, stribeck) = sigma2 (lugre)
  T stribeck_velocity_m_per_s = T(0.01);  ///< vs
  T stribeck_exponent = T(2.0);           ///< delta in exp(-(|v|/vs)^delta)
};
using StribeckCurve = BasicStribeckCurve<double>;

/// Pressure dependence (docs/model.md, "Friction"): Fc = Fc0 + coulomb_N_per_Pa (P1 + P2 - 2 Pa)
/// with Fc0 the curve's level, Fs likewise with static_N_per_Pa.
template <typename T>
struct BasicPressureGains {
  T coulomb_N_per_Pa = T(0.0);
  T static_N_per_Pa = T(0.0);
};
using PressureGains = BasicPressureGains<double>;

/// LuGre's bristles (kind = kLuGre): dz/dt = v - sigma0 |v| z / g(v),
/// F = sigma0 z + sigma1 dz/dt + B v.
template <typename T>
struct BasicLuGreBristles {
  T sigma0_N_per_m = T(1.0e5);   ///< bristle stiffness
  T sigma1_Ns_per_m = T(300.0);  ///< bristle damping
  /// In the Plant: the bristle relaxation rate sigma0 |v| / g(v) [1/s] above which the
  /// bristle is taken on its steady state z = g sgn v / sigma0 (left again below half of it;
  /// docs/model.md, "Friction"); 0: never. The bristle's stiffness bounds an explicit step.
  double quasi_static_rate_per_s = 4000.0;
};
using LuGreBristles = BasicLuGreBristles<double>;

/// Generalized Maxwell-slip elements (kind = kGms; docs/model.md, "Friction"): their number,
/// their total presliding stiffness (equal shares) and the sliding distance over which a
/// slipping element is attracted to its share of the Stribeck level.
struct GmsElements {
  int count = 4;  ///< 1 to kMaxGmsElements
  double stiffness_N_per_m = 1.0e5;
  double attraction_length_m = 250e-6;
  /// In the Plant: the slowest element's loading rate 4 |v| / r_N [1/s] above which the
  /// elements are taken on their quasi-static limit (docs/model.md, "Friction"); 0: never.
  /// Off unless set: at thresholds the chaotic point reaches, the limit moves it beyond its
  /// integration error; the default scenario sets one that only fast sliding reaches
  /// (docs/notes/performance.md, "The GMS seal's quasi-static limit").
  double quasi_static_rate_per_s = 0.0;
};

/// The Stribeck drop's lag behind the velocity (kind = kStribeck, memory = kLag).
struct StribeckLag {
  double time_s = 0.005;  ///< time constant
};

/// Two state variables of the Stribeck drop that evolve with the slip (kind = kStribeck,
/// memory = kRateState; docs/model.md, "Friction"): each relaxes to the steady weight
/// exp(-(|v|/vs)^delta) over its own slip length, d theta_i/dt = -(|v| / L_i)(theta_i - w(v))
/// (Ruina's slip law), and the force has a direct effect of the velocity,
/// F = [Fc + (Fs - Fc)(share theta_1 + (1 - share) theta_2) + A ln(1 + |v|/v_A)] sgn v + B v.
struct RateStateMemory {
  double slip_length_m = 20e-6;    ///< L_1, the first state's slip length
  double slip_length2_m = 200e-6;  ///< L_2, the second state's
  double share = 0.5;              ///< the first state's share of the Stribeck drop, 0..1
  double direct_N = 0.0;           ///< A, the direct effect's force scale
  double direct_velocity_m_per_s = 1e-3;  ///< v_A, its reference velocity
};

/// A seal's friction: the model `kind` (with `memory` for stribeck) and each model's
/// parameters, which are kept when the kind changes; a model reads the curve, the pressure
/// gains and the texture, and its own struct.
struct FrictionParams {
  FrictionKind kind = FrictionKind::kStribeck;
  FrictionMemory memory = FrictionMemory::kNone;  ///< stribeck only
  StribeckCurve curve;
  PressureGains pressure_gain;
  /// Position-dependent texture (docs/model.md, "Friction"; docs/sweep.md); empty: uniform bore.
  std::vector<TextureMode> texture;
  /// The seal's random level along the bore, added to the texture's factor; empty: none.
  RandomLevelField level_field;
  LuGreBristles lugre;
  GmsElements gms;
  StribeckLag lag;
  RateStateMemory rate_state;
  /// The threshold of this model's quasi-static limit (0: none).
  [[nodiscard]] double quasi_static_threshold() const {
    if (kind == FrictionKind::kGms) return gms.quasi_static_rate_per_s;
    return kind == FrictionKind::kLuGre ? lugre.quasi_static_rate_per_s : 0.0;
  }
  /// The fraction of that threshold at which the limit is left again (hysteresis). GMS leaves
  /// earlier than LuGre: its first-order lag is poorest where the contact decelerates through
  /// the Stribeck drop, and leaving at 3/4 keeps the start-up's dip at fast sliding in the
  /// full law (docs/notes/performance.md, "The GMS seal's quasi-static limit").
  [[nodiscard]] double quasi_static_exit_fraction() const {
    return kind == FrictionKind::kGms ? 0.75 : 0.5;
  }
  [[nodiscard]] bool lagged() const {
    return kind == FrictionKind::kStribeck && memory == FrictionMemory::kLag;
  }
  [[nodiscard]] bool rate_and_state() const {
    return kind == FrictionKind::kStribeck && memory == FrictionMemory::kRateState;
  }
};

/// The parameters as a FrictionModel evaluates them: the user's, with the bore's texture
/// tabulated along the stroke and the random level field over one period when the Plant built
/// the model (evaluation caches, not parameters: docs/model.md, "Friction"); positions
/// outside the texture's table use the sines, the field's table repeats with its period.
struct TabulatedFriction : FrictionParams {
  TabulatedFriction(const FrictionParams& p, std::shared_ptr<const TextureTable> table,
                    std::shared_ptr<const TextureTable> field)
      : FrictionParams(p), texture_table(std::move(table)), level_table(std::move(field)) {}
  std::shared_ptr<const TextureTable> texture_table;
  std::shared_ptr<const TextureTable> level_table;
};

/// What a friction model sees of the plant, in the scalar type of the evaluation (double,
/// or an automatic-differentiation scalar when the plant's Jacobian is taken).
template <typename T>
struct BasicFrictionInput {
  T v_m_per_s = T(0.0);     ///< sliding velocity of the contact
  T gauge_sum_Pa = T(0.0);  ///< P1 + P2 - 2 Pa (0 for a contact not on the seal)
  T position_m = T(0.0);    ///< position along the contact (for textures)
};
using FrictionInput = BasicFrictionInput<double>;

class FrictionModel {
 public:
  /// `texture_table`, `level_table`: the texture and the random level field of `p`
  /// tabulated (the Plant's; null: the sines).
  explicit FrictionModel(const FrictionParams& p,
                         std::shared_ptr<const TextureTable> texture_table = nullptr,
                         std::shared_ptr<const TextureTable> level_table = nullptr)
      : p_(p, std::move(texture_table), std::move(level_table)) {}
  virtual ~FrictionModel() = default;

  /// Internal states carried in the ODE state (LuGre: bristle deflection z [m]).
  [[nodiscard]] virtual std::size_t state_count() const { return 0; }
  /// Name, unit and typical magnitude of the internal states (LuGre: z, m, 1 um).
  [[nodiscard]] virtual const char* state_name() const { return "z"; }
  [[nodiscard]] virtual const char* state_unit() const { return "m"; }
  [[nodiscard]] virtual double state_scale() const { return 1e-6; }
  /// The internal states after a long rest (the start of a run): zero unless overridden.
  virtual void rest_state(std::span<double> z) const;
  /// True stiction: the contact may be stuck with v held at exactly 0 (classic, stribeck).
  [[nodiscard]] virtual bool has_stiction() const = 0;

  /// Friction force [N] opposing motion. Stiction models: while sliding in `direction`
  /// (+1/-1), the velocity read as direction*max(direction*v, 0). Smooth models ignore
  /// direction and use the internal state z, writing dz/dt to dz.
  virtual double force_N(const FrictionInput& in, int direction, std::span<const double> z,
                         std::span<double> dz) const = 0;

  /// Largest holding force at rest: Fs for stiction models; for smooth models the force at
  /// v = 0 with the present internal state.
  [[nodiscard]] virtual double holding_force_N(const FrictionInput& in,
                                               std::span<const double> z) const = 0;

  /// Steady-state friction at constant velocity v != 0 (the friction-velocity curve).
  [[nodiscard]] virtual double steady_force_N(const FrictionInput& in) const = 0;

  /// Slope dF/dv of the steady curve at v (the paper's B, negative on a Stribeck drop).
  [[nodiscard]] double steady_slope_Ns_per_m(const FrictionInput& in) const;

  /// Steady internal state at constant velocity (zero for models without state).
  virtual void steady_state(const FrictionInput& in, std::span<double> z) const;

  [[nodiscard]] const TabulatedFriction& params() const { return p_; }

 protected:
  TabulatedFriction p_;
};

std::unique_ptr<FrictionModel> make_friction_model(
    const FrictionParams& params, std::shared_ptr<const TextureTable> texture_table = nullptr,
    std::shared_ptr<const TextureTable> level_table = nullptr);
const char* friction_kind_name(FrictionKind kind);

}  // namespace pneumachaos
