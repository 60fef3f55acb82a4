#pragma once
// The report's figures (the paper's Figs. 2-7 and the stability map) as FigureSpecs: data
// tables and gnuplot commands, ready for render_figure.

#include <array>
#include <string>
#include <vector>

#include "pneumachaos/analysis/analyze.hpp"
#include "pneumachaos/core/time_series.hpp"
#include "pneumachaos/stability/stability_map.hpp"
#include "pneumachaos/sweep/sweep.hpp"

namespace pneumachaos {

struct FigureSpec;

/// A labelled velocity record for Fig. 2.
struct LabelledRecord {
  std::string label;
  TimeSeries series;
};

/// A lettered point of Fig. 3's loop (A breakaway, B branch crossing, C top speed, D stop).
struct LoopLabel {
  char label = 'A';
  double v_m_per_s = 0.0;
  double F_N = 0.0;
};

/// Fig. 2 as the paper labels it: (a) meter-out, (b) meter-in.
FigureSpec time_responses_figure(const std::vector<LabelledRecord>& meter_out,
                                 const std::vector<LabelledRecord>& meter_in);
/// Seal friction against piston velocity over `seconds` of each record (Fig. 3's loops),
/// with the seal's steady curve as (v [m/s], F [N]) pairs and, per record, the letters of one
/// loop (empty: none found).
FigureSpec friction_loops_figure(const std::vector<LabelledRecord>& records, double seconds,
                                 const std::vector<std::array<double, 2>>& steady,
                                 const std::vector<std::vector<LoopLabel>>& letters = {});
FigureSpec stability_map_figure(const StabilityMap& map);
/// The stability map's colour scale [1/s]: symmetric about 0, twice the median of |largest
/// real part| rounded up (at least 1), so the sign shows near 0; larger values saturate.
double stability_colour_scale(const StabilityMap& map);
/// Fig. 7b's exponent panel: a y range holding the second halves of Wolf's and the model's
/// running estimates (where they settle), from 0 (or below, for a negative estimate).
std::array<double, 2> lyapunov_panel_range(const std::vector<double>& wolf,
                                          const std::vector<double>& model);
/// Chaos incidence in grey (white 0 %, black 100 %) with the stick-slip region hatched.
FigureSpec incidence_map_figure(const std::string& name, const std::string& title,
                                const SweepSpec& spec, const SweepSummary& summary);
/// Fig. 7: (a) the record, (b) spectrum, autocorrelation and Lyapunov convergence,
/// (c) the delay-embedded trajectory, (d) its Poincare section. v is the settled record,
/// starting start_s after the simulation's start.
std::vector<FigureSpec> chaotic_example_figures(const std::vector<double>& v, double rate_Hz,
                                                double start_s, const AnalysisResult& a,
                                                const std::vector<double>& model_running_t,
                                                const std::vector<double>& model_running);

}  // namespace pneumachaos
