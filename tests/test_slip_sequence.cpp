// The slips' own sequence (docs/analysis.md "Slip sequence"): stick-slip records generated
// here, each slip a half sine after a rest, the slip sizes following a known rule.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include "pneumachaos/analysis/slip_sequence.hpp"
#include "pneumachaos/core/error.hpp"

namespace pneumachaos {
namespace {

constexpr double kRate = 1000.0;
constexpr std::size_t kRest = 40;

// One slip per size in [0, 1]: a rest of kRest samples, then a half sine of 60 + 60 size
// samples and peak 0.05 + 0.1 size (a bigger slip is faster and longer, as on the rig).
// Its displacement is (2 / pi) peak duration, up to the rectangle rule's error.
std::vector<double> stick_slip(const std::vector<double>& sizes) {
  std::vector<double> v;
  for (double size : sizes) {
    v.insert(v.end(), kRest, 0.0);
    const auto len = static_cast<std::size_t>(std::lround(60.0 + 60.0 * size));
    for (std::size_t i = 0; i < len; ++i) {
      v.push_back((0.05 + 0.1 * size) *
                  std::sin(std::numbers::pi * static_cast<double>(i) / static_cast<double>(len)));
    }
  }
  v.insert(v.end(), kRest, 0.0);
  return v;
}

SlipSequenceTest test_record(const std::vector<double>& sizes) {
  const std::vector<double> v = stick_slip(sizes);
  const auto rests = find_rests(v, 0.01 * 0.15, 5);
  return slip_sequence_test(v, kRate, rests);
}

template <typename Map>
std::vector<double> iterate(std::size_t n, double x, Map map) {
  std::vector<double> s(n);
  for (double& v : s) v = x = map(x);
  return s;
}

std::vector<double> logistic(std::size_t n, double x0) {
  return iterate(n, x0, [](double x) { return 4.0 * x * (1.0 - x); });
}

std::vector<double> uniform(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<double> s(n);
  for (double& v : s) v = static_cast<double>(rng() >> 11) * 0x1.0p-53;
  return s;
}

TEST(SlipSequence, DisplacementsOfGeneratedSlips) {
  const std::vector<double> sizes{0.0, 0.5, 1.0, 0.25};
  const std::vector<double> v = stick_slip(sizes);
  const auto rests = find_rests(v, 0.01 * 0.15, 5);
  // Each rest is kRest zeros plus the slip's first sample (sin 0 = 0) and, where it is
  // below 1 % of the peak, the slip's last samples: a rest per gap, the ends included.
  ASSERT_EQ(rests.intervals.size(), sizes.size() + 1);
  const std::vector<double> d = slip_displacements(v, kRate, rests);
  ASSERT_EQ(d.size(), sizes.size());
  for (std::size_t k = 0; k < sizes.size(); ++k) {
    const double len = std::round(60.0 + 60.0 * sizes[k]);
    const double exact = 2.0 / std::numbers::pi * (0.05 + 0.1 * sizes[k]) * len / kRate;
    // The samples left in the rests are below 1 % of the peak: a few 1e-3 of the area.
    EXPECT_NEAR(d[k], exact, 3e-3 * exact) << k;
  }
}

TEST(SlipSequence, CreepInsideTheRestBandIsNoSlip) {
  // A rest broken by a creep that stays inside the band |x| <= level (its spread exceeds half
  // the level, so the rest detection splits the rest there) holds no slip: still 4 slips.
  std::vector<double> v = stick_slip({0.0, 0.5, 1.0, 0.25});
  const double level = 0.01 * 0.15;
  for (std::size_t i = 0; i < 30; ++i) v.insert(v.begin() + 130, 0.9 * level);
  const auto rests = find_rests(v, level, 5);
  EXPECT_GT(rests.intervals.size(), 5u);
  EXPECT_EQ(slip_displacements(v, kRate, rests).size(), 4u);
  // A creep burst above the band but far below a slip (3 % of the peak speed, as a frozen-rig
  // record shows between slips) is no slip either; at a threshold below it, it is one.
  for (std::size_t i = 0; i < 20; ++i) {
    const double bump = std::sin(std::numbers::pi * static_cast<double>(i) / 20.0);
    v.insert(v.begin() + 120 + static_cast<std::ptrdiff_t>(i), 0.03 * 0.15 * bump);
  }
  const auto crept = find_rests(v, level, 5);
  EXPECT_EQ(slip_displacements(v, kRate, crept, 0.1 * 0.15).size(), 4u);
  EXPECT_EQ(slip_displacements(v, kRate, crept, 0.01 * 0.15).size(), 5u);
}

TEST(SlipSequence, PeriodicSlipsAreNotChaotic) {
  // Period 1 (all slips alike, 1 % slip-to-slip jitter): the slips do not vary enough.
  std::mt19937_64 rng(7);
  std::vector<double> one(60);
  for (double& s : one) s = 0.5 + 0.01 * (static_cast<double>(rng() >> 11) * 0x1.0p-53 - 0.5);
  const SlipSequenceTest t1 = test_record(one);
  EXPECT_TRUE(t1.run);
  EXPECT_FALSE(t1.varies);
  EXPECT_FALSE(t1.chaotic);
  // Period 2, exact and with 10 % slip-to-slip noise: it repeats at lag 2.
  for (double noise : {0.0, 0.1}) {
    std::vector<double> two(60);
    for (std::size_t k = 0; k < two.size(); ++k) {
      two[k] = (k % 2 == 0 ? 0.2 : 0.9) + noise * 0.7 * (uniform(1, k + 11)[0] - 0.5);
    }
    const SlipSequenceTest t2 = test_record(two);
    EXPECT_TRUE(t2.varies) << noise;
    EXPECT_TRUE(t2.repeats) << noise;
    EXPECT_EQ(t2.repeat_lag % 2, 0u) << noise;
    EXPECT_FALSE(t2.chaotic) << noise;
  }
}

TEST(SlipSequence, ChaoticMapsAreChaotic) {
  // Logistic x -> 4x(1 - x) and tent x -> 1.99 min(x, 1 - x) (exponents ln 2 and ln 1.99 per
  // slip), 30 and 60 slips: deterministic, irregular, no repeat.
  for (std::size_t n : {30, 60}) {
    const SlipSequenceTest l = test_record(logistic(n, 0.3));
    EXPECT_TRUE(l.chaotic) << "logistic " << n << ": error " << l.prediction_error
                           << ", surrogates' median " << l.surrogate_median;
    const auto tent = iterate(n, 0.3, [](double x) { return 1.99 * std::min(x, 1.0 - x); });
    const SlipSequenceTest t = test_record(tent);
    EXPECT_TRUE(t.chaotic) << "tent " << n << ": error " << t.prediction_error
                           << ", surrogates' median " << t.surrogate_median;
    EXPECT_EQ(l.surrogates_below, 0u);
    EXPECT_FALSE(l.repeats);
  }
}

TEST(SlipSequence, NoiseDrivenSlipsAreNotChaotic) {
  // i.i.d. uniform slip sizes, and red ones (AR(1), coefficient 0.8, mapped into [0, 1]):
  // irregular but not deterministic. Twenty seeds each; a rank test alone would pass ~1 in
  // 40 by chance, the size of effect (error <= half the surrogates' median) none.
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const SlipSequenceTest iid = test_record(uniform(60, seed));
    EXPECT_TRUE(iid.run);
    EXPECT_FALSE(iid.chaotic) << "i.i.d., seed " << seed << ": error " << iid.prediction_error;
    std::vector<double> red = uniform(60, seed + 100);
    double a = 0.0;
    for (double& s : red) {
      a = 0.8 * a + (s - 0.5);
      s = 0.5 + 0.25 * std::tanh(a);
    }
    const SlipSequenceTest r = test_record(red);
    EXPECT_FALSE(r.chaotic) << "AR(1), seed " << seed << ": error " << r.prediction_error;
  }
}

TEST(SlipSequence, QuasiPeriodicSlipsAreNotChaotic) {
  // Slip sizes from a rotation by the golden mean, through a nonlinear profile: deterministic
  // and irregular, but a torus, not chaos; its near return (8 slips) reads as a repeat.
  std::vector<double> s(60);
  const double w = (std::sqrt(5.0) - 1.0) / 2.0;
  for (std::size_t k = 0; k < s.size(); ++k) {
    const double phase = std::fmod(w * static_cast<double>(k), 1.0);
    s[k] = 0.5 + 0.4 * std::sin(2.0 * std::numbers::pi * phase) * std::abs(std::cos(
                                                                          std::numbers::pi * phase));
  }
  const SlipSequenceTest t = test_record(s);
  EXPECT_TRUE(t.repeats) << t.repeat_mismatch;
  EXPECT_FALSE(t.chaotic);
}

TEST(SlipSequence, TooFewSlipsIsNotRun) {
  const SlipSequenceTest t = test_record(logistic(12, 0.3));
  EXPECT_FALSE(t.run);
  EXPECT_FALSE(t.chaotic);
  EXPECT_EQ(t.slips, 12u);
  EXPECT_NE(t.reason.find("12 slips between rests, at least 20 needed"), std::string::npos)
      << t.reason;
  const std::vector<double> flat(500, 0.0);
  const SlipSequenceTest none = slip_sequence_test(flat, kRate, find_rests(flat, 1e-3, 5));
  EXPECT_FALSE(none.run);
  EXPECT_EQ(none.slips, 0u);
}

TEST(SlipSequence, BadOptionsNameTheOption) {
  SlipSequenceOptions o;
  o.min_slips = 3;
  try {
    o.validate();
    FAIL() << "min_slips = 3 accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("slip_sequence.min_slips"), std::string::npos);
  }
  o = {};
  o.min_peak_fraction = 1.5;
  EXPECT_THROW(o.validate(), Error);
  o = {};
  o.max_error_ratio = 0.0;
  EXPECT_THROW(o.validate(), Error);
  o = {};
  o.neighbours = 0;
  EXPECT_THROW(o.validate(), Error);
}

}  // namespace
}  // namespace pneumachaos
