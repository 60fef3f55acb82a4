// The bore texture's table (src/model/texture_table.hpp), against the sines it stands for.
#include <gtest/gtest.h>

#include <cmath>

#include "pneumachaos/model/plant.hpp"
#include "pneumachaos/model/scenario_toml.hpp"
#include "pneumachaos/model/variation.hpp"

namespace pneumachaos {
namespace {

// The level g of a contact sliding fast (the Stribeck drop spent), as its model gives it.
double level_at(const FrictionModel& m, double position_m) {
  return m.steady_force_N({0.5, 2.0e5, position_m});
}

// The Plant's seal (table) against the same parameters without a table (the sines), over the
// stroke, for several seeded textures at the sweeps' 2 % and at 10 %: the difference stays
// within the cubic Hermite bound docs/model.md states, 1.5e-8 sum |a| of the level.
TEST(TextureTable, PlantLevelsMatchTheSinesWithinTheHermiteBound) {
  for (const char* rel : {"variation.texture_rel=0.02", "variation.texture_rel=0.1"}) {
    const Scenario base = build_scenario("", {rel});
    for (std::uint64_t r = 0; r < 4; ++r) {
      const Scenario s = vary(base, run_seed(3, 1, r));
      ASSERT_FALSE(s.friction.texture.empty());
      double amplitude_sum = 0.0;
      for (const TextureMode& m : s.friction.texture) amplitude_sum += std::abs(m.amplitude);
      const Plant plant(s);
      const auto sines = make_friction_model(s.friction);
      const double stroke = s.cylinder.stroke_m;
      double worst = 0.0;
      for (int i = 0; i <= 20000; ++i) {
        const double x = -0.04 + (stroke + 0.08) * i / 20000.0;
        const double exact = level_at(*sines, x);
        worst = std::max(worst, std::abs(level_at(plant.seal_friction(), x) - exact) / exact);
      }
      EXPECT_LE(worst, 1.5e-8 * amplitude_sum) << rel << " run " << r;
      // Not vacuous: the texture moves the level by far more than the bound.
      EXPECT_GT(std::abs(level_at(*sines, 0.1) - level_at(*sines, 0.1 + 0.004)) /
                    level_at(*sines, 0.1),
                1e3 * 1.5e-8 * amplitude_sum);
    }
  }
}

// Beyond the tabulated range (the stroke and 5 cm either side) the sines themselves are
// evaluated: the same number bit for bit.
TEST(TextureTable, OutsideTheStrokeTheSinesAreEvaluated) {
  const Scenario s = vary(build_scenario("", {"variation.texture_rel=0.05"}), run_seed(3, 1, 0));
  const Plant plant(s);
  const auto sines = make_friction_model(s.friction);
  for (const double x : {-0.2, -0.051, s.cylinder.stroke_m + 0.051, 3.0}) {
    EXPECT_EQ(level_at(plant.seal_friction(), x), level_at(*sines, x)) << x;
  }
}

// The table is the Plant's evaluation cache, held by its friction models beside the
// parameters (TabulatedFriction), never part of the FrictionParams a user fills; it is built
// for a textured contact only, and inside the stroke it is what the model reads (a level
// that differs from the sines, within the bound above).
template <typename P>
concept HoldsTextureTable = requires(P p) {
  p.texture_table;
};
static_assert(!HoldsTextureTable<FrictionParams>, "the texture table is no friction parameter");
static_assert(HoldsTextureTable<TabulatedFriction>);

TEST(TextureTable, ThePlantsModelsHoldTheTableForTexturedContactsOnly) {
  const Scenario plain = build_scenario("", {});
  EXPECT_EQ(Plant(plain).seal_friction().params().texture_table, nullptr);
  const Scenario s = vary(build_scenario("", {"variation.texture_rel=0.05"}), run_seed(3, 1, 0));
  const Plant plant(s);
  ASSERT_NE(plant.seal_friction().params().texture_table, nullptr);
  EXPECT_EQ(make_friction_model(s.friction)->params().texture_table, nullptr);
  const auto sines = make_friction_model(s.friction);
  int differing = 0;
  for (int i = 0; i < 100; ++i) {
    const double x = s.cylinder.stroke_m * (i + 0.5) / 100.0;
    differing += level_at(plant.seal_friction(), x) != level_at(*sines, x);
  }
  EXPECT_GT(differing, 50);  // the table's rounding differs from the sines' at most points
}

}  // namespace
}  // namespace pneumachaos
