#pragma once
// What a calibration's evaluations say about its claims together (private to the calibrate
// module): which claims the optimizer reached at all, which sets of claims it reached at one
// point (the front), and which pairs it reached only apart. When a calibration misses its
// goals, this is its evidence: not the best point alone, but what the searched box allows
// (docs/guide/calibrate.md, "What the evaluations say together").

#include <cstddef>
#include <string>
#include <vector>

#include "evaluation_journal.hpp"

namespace pneumachaos::detail {

/// One claim over every evaluation the model accepted.
struct ClaimReach {
  std::string id;
  std::size_t evaluated = 0;  ///< evaluations with a margin (the claim could be judged)
  std::size_t agreed = 0;     ///< evaluations with a positive margin
  double best_margin = 0.0;   ///< NaN when never evaluated
  std::size_t best_evaluation = 0;
};

/// A set of claims agreed at one evaluation that no evaluation extends: the front.
struct AgreedSet {
  std::vector<std::size_t> claims;  ///< indices into the claim ids, ascending
  std::size_t evaluations = 0;      ///< evaluations agreeing with exactly this set
  std::size_t example = 0;          ///< the one among them with the lowest objective
};

/// Two claims each agreed somewhere but never at the same evaluation.
struct ClaimConflict {
  std::size_t a = 0, b = 0;  ///< indices into the claim ids, a < b
  /// Pearson correlation of their margins over the evaluations that judged both (NaN with
  /// fewer than three or without spread): how strongly the box trades one for the other.
  double correlation = 0.0;
};

struct ClaimFront {
  std::vector<std::string> ids;
  std::size_t accepted = 0;  ///< evaluations the model did not refuse (some claim judged)
  std::vector<ClaimReach> reach;
  std::vector<AgreedSet> front;  ///< largest sets first
  std::vector<ClaimConflict> conflicts;
};

/// The front of `entries` whose terms are the margins of the claims `ids`, in that order. An
/// entry with no margin at all (a point the model refused) counts for nothing.
ClaimFront claim_front(const std::vector<std::string>& ids,
                       const std::vector<JournalEntry>& entries);

/// The same as a Markdown section (for summary.md).
std::string claim_front_md(const ClaimFront& f);

}  // namespace pneumachaos::detail
