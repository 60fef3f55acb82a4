// The validation vocabulary (core/validation.hpp): a value outside its range is refused with an
// Error naming section.field, the value and the range; a NaN is outside every range; a value
// inside passes.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/core/validation.hpp"

namespace pneumachaos {
namespace {

using namespace validation;

// The Error's what(), or "(no error)".
std::string refusal(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(Validation, AValueOutsideItsRangeIsRefusedNamingTheFieldAndTheRange) {
  EXPECT_EQ(refusal([] { require_ge(field("verdict.min_samples"), 3, 16); }),
            "verdict.min_samples = 3: must be >= 16");
  EXPECT_EQ(refusal([] { require_gt(field("fit.max_factor"), 0.5, 1, "enclose the start"); }),
            "fit.max_factor = 0.5: must be > 1 (enclose the start)");
  EXPECT_EQ(refusal([] { require_lt(field("a.b"), 2, 2); }), "a.b = 2: must be < 2");
  EXPECT_EQ(refusal([] { require_le(field("a.b"), 3, 2); }), "a.b = 3: must be <= 2");
  EXPECT_EQ(refusal([] { require_between(field("a.b"), 1.5, 0, 1); }),
            "a.b = 1.5: must be between 0 and 1");
  EXPECT_EQ(refusal([] { require_ge_lt(field("a.b"), 1, 0, 1); }), "a.b = 1: must be >= 0 and < 1");
  EXPECT_EQ(refusal([] { require_gt_le(field("a.b"), 0, 0, 1); }), "a.b = 0: must be > 0 and <= 1");
  EXPECT_EQ(refusal([] { require_gt_lt(field("a.b"), 1, 0, 1); }), "a.b = 1: must be > 0 and < 1");
  EXPECT_EQ(refusal([] { require(false, field("a.b"), 4, "odd"); }), "a.b = 4: must be odd");
}

TEST(Validation, AValueInsideItsRangePasses) {
  EXPECT_EQ(refusal([] {
              require_ge(field("a.b"), 16, 16);
              require_gt(field("a.b"), 1.5, 1);
              require_between(field("a.b"), 1, 0, 1);
              require_ge_lt(field("a.b"), 0, 0, 1);
              require_gt_le(field("a.b"), 1, 0, 1);
              require_gt_lt(field("a.b"), 0.5, 0, 1);
              require_finite_gt(field("a.b"), 1e300, 0);
              require_finite(field("a.b"), -1.0);
            }),
            "(no error)");
}

TEST(Validation, NaNIsOutsideEveryRange) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::function<void()> checks[] = {
      [&] { require_gt(field("a.b"), nan, 0); },
      [&] { require_ge(field("a.b"), nan, 0); },
      [&] { require_lt(field("a.b"), nan, 0); },
      [&] { require_le(field("a.b"), nan, 0); },
      [&] { require_between(field("a.b"), nan, 0, 1); },
      [&] { require_ge_lt(field("a.b"), nan, 0, 1); },
      [&] { require_gt_le(field("a.b"), nan, 0, 1); },
      [&] { require_gt_lt(field("a.b"), nan, 0, 1); },
      [&] { require_finite_gt(field("a.b"), nan, 0); },
      [&] { require_finite_ge(field("a.b"), nan, 0); },
      [&] { require_finite(field("a.b"), nan); },
  };
  for (const auto& check : checks) {
    const std::string m = refusal(check);
    EXPECT_EQ(m.rfind("a.b = nan: must be ", 0), 0u) << m;
  }
  EXPECT_EQ(
      refusal([] { require_finite_ge(field("a.b"), std::numeric_limits<double>::infinity(), 0); }),
      "a.b = inf: must be finite and >= 0");
}

TEST(Validation, TheErrorCarriesTheFieldForTheCommandLine) {
  // The command line replaces the field's id by the option that set it and keeps the detail.
  constexpr ErrorField kRate{"csv.rate_Hz", "sampling rate"};
  try {
    require_finite_gt(kRate, 0, 0, "Hz");
    FAIL() << "not refused";
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), "csv.rate_Hz");
    EXPECT_EQ(e.detail(), " = 0");
    EXPECT_EQ(e.where(), "csv.rate_Hz = 0");
    EXPECT_EQ(e.message(), "must be finite and > 0 (Hz)");
    EXPECT_EQ(dynamic_cast<const RunError*>(&e), nullptr);  // bad input, not a failed run
  }
}

}  // namespace
}  // namespace pneumachaos
