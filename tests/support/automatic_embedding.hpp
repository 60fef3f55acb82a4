#pragma once
// The automatic embedding `analyze` uses, for the estimators' own tests: AMI delay, Theiler
// window max(delay, first zero of the autocorrelation), Cao dimension. Options: any estimator's
// options with delay, theiler and dimension fields (DivergenceOptions, JacobianOptions).

#include <algorithm>
#include <cstddef>
#include <vector>

#include "pneumachaos/analysis/autocorrelation.hpp"
#include "pneumachaos/analysis/embedding_parameters.hpp"

namespace pneumachaos::testing {

template <class Options>
Options automatic_embedding(const std::vector<double>& x) {
  Options o;
  o.delay = choose_delay(x).delay;
  const Autocorrelation acf = autocorrelation(x, 1.0);
  o.theiler =
      std::max<std::size_t>(o.delay, static_cast<std::size_t>(std::max(acf.first_zero_s, 1.0)));
  o.dimension = choose_dimension(x, o.delay, o.theiler).dimension;
  return o;
}

}  // namespace pneumachaos::testing
