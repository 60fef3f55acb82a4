// The model's own Lyapunov exponent (Benettin) against known values.
#include <gtest/gtest.h>

#include "pneumachaos/simulate/model_lyapunov.hpp"
#include "support/reference_systems.hpp"

namespace pneumachaos {
namespace {

TEST(ModelLyapunov, LorenzMatchesTheReference) {
  const testing::LorenzSystem lorenz;
  ModelLyapunovOptions o;
  o.transient_s = 20.0;
  o.measure_s = 400.0;
  o.renormalize_s = 0.5;
  o.max_step_s = 0.01;
  const ModelLyapunovResult r = model_lyapunov(lorenz, {1.0, 1.0, 20.0}, o);
  ASSERT_TRUE(r.ok) << r.message;
  // 0.9056 (Sprott 2003); 400 time units average the local fluctuations to about 2 %.
  EXPECT_NEAR(r.lambda_per_s, 0.9056, 0.03);
  EXPECT_LT(std::abs(r.lambda_per_s - 0.9056), 3.0 * r.uncertainty_per_s + 0.01);
  EXPECT_EQ(r.running_per_s.size(), r.renormalizations);
}

TEST(ModelLyapunov, HarmonicOscillatorIsNeutral) {
  const testing::HarmonicOscillator osc(2.0);
  ModelLyapunovOptions o;
  o.transient_s = 0.0;
  o.measure_s = 200.0;
  o.renormalize_s = 1.0;
  const ModelLyapunovResult r = model_lyapunov(osc, {1.0, 0.0}, o);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_LT(std::abs(r.lambda_per_s), 0.01);
}

TEST(ModelLyapunov, PeriodicStickSlipIsNotChaotic) {
  // The ramped block's stick-slip cycle is forced and periodic: no exponential divergence.
  const testing::RampedBlock block;
  ModelLyapunovOptions o;
  o.transient_s = 1.0;
  o.measure_s = 30.0;
  o.renormalize_s = 0.05;
  o.perturbed_state = 0;
  const ModelLyapunovResult r = model_lyapunov(block, {0.0, 0.0}, o);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_LT(r.lambda_per_s, 0.1);
}

}  // namespace
}  // namespace pneumachaos
