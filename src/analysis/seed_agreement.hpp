#pragma once
// The verdict decided again on further seeds of its two random tests, when one of them could
// turn it (docs/notes/analysis.md "Seed agreement"). Internal to the analysis module.

#include <cstddef>
#include <span>

#include "pneumachaos/analysis/analyze.hpp"

namespace pneumachaos {

/// The scale and embedding the seeded tests read (run_evidence_tests chooses them).
struct SeededTestSetup {
  std::size_t zero_one_step = 1;
  PredictionOptions prediction;
};

/// Copies a test's outcome into the evidence the verdict reads.
void note_zero_one(const ZeroOneResult& z, RegimeEvidence& e);
void note_surrogates(const SurrogateTest& s, RegimeEvidence& e);

/// Probability that the surrogate test's outcome (more predictable than every surrogate, or
/// not) turns on another seed: the surrogates' statistics taken as normal, the chance that
/// `count` new ones all lie above the record's (or not). 0 when the test did not run.
double surrogate_flip_probability(const SurrogateTest& s);

/// Probability that the 0-1 test's reading (K >= split, or its upper quartile below it)
/// turns on another seed: the distance to the split in standard errors of the median and of
/// the quartile over `frequencies` draws, the spread taken from the quartiles. 0: not run.
double zero_one_flip_probability(const ZeroOneResult& z, std::size_t frequencies, double split);

/// With options.verdict_seeds > 1 and a random test pivotal (forcing its outcome the other
/// way changes the regime), runs that test on seeds seed + 1, ... and reports the regime
/// that a majority of the seeds gives (else undetermined), with the tally (r.seed_agreement).
/// A pivotal test is run again only when its outcome could turn (its flip probability
/// >= 1 %).
void check_seed_agreement(std::span<const double> x, const AnalysisOptions& options,
                          const SeededTestSetup& setup, AnalysisResult& r);

}  // namespace pneumachaos
