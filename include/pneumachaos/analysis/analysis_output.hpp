#pragma once
// Analysis results for people (a summary), for programs (JSON, a unit on every number) and
// for plotting (one CSV per curve).

#include <span>
#include <string>

#include "pneumachaos/analysis/analyze.hpp"
#include "pneumachaos/io/atomic_file.hpp"

namespace pneumachaos {

/// `unit` is the series' unit (e.g. "m/s"), used to state the PSD's unit. explain: the
/// verdict's whole rule is printed (wrapped) among the evidence; else a line says how to see it.
std::string analysis_summary(const AnalysisResult& r, const std::string& name,
                             const std::string& unit, bool explain = false);

/// Keys include lyapunov.wolf.value, lyapunov.divergence.value and .uncertainty, each with a
/// unit ("1/s"; bits/s beside it), and verdict.regime, verdict.chaotic, verdict.stick_slip.
std::string analysis_json(const AnalysisResult& r, const std::string& source,
                          const std::string& name, const std::string& unit);

/// Writes spectrum.csv, autocorrelation.csv, divergence.csv, wolf_running.csv,
/// embedding.csv (3-D delay trajectory), poincare.csv and maxima_map.csv into dir (created
/// if needed) as part of `out`: they appear when `out` is committed, together with the
/// command's other outputs.
void write_analysis_series(const AnalysisResult& r, std::span<const double> x,
                           const std::string& dir, const std::string& unit, OutputSet& out);

}  // namespace pneumachaos
