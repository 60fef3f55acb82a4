#include "report/figures.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "pneumachaos/plot/figure.hpp"

namespace pneumachaos {
namespace {

std::string records_table(const std::vector<LabelledRecord>& records, double max_s) {
  std::string out = "# t[s]";
  for (const auto& r : records) out += " v[mm/s](" + r.label + ")";
  out += "\n";
  std::size_t n = 0;
  for (const auto& r : records) n = std::max(n, r.series.size());
  const double rate = records.front().series.rate_Hz();
  for (std::size_t k = 0; k < n && k / rate <= max_s; ++k) {
    out += fmt::format("{}", k / rate);
    for (const auto& r : records) {
      const auto& v = r.series.channel("v").values;
      out += k < v.size() ? fmt::format(" {}", 1e3 * v[k]) : std::string(" NaN");
    }
    out += "\n";
  }
  return out;
}

std::string plot_columns(const std::string& file, const std::vector<LabelledRecord>& records) {
  std::string out;
  for (std::size_t i = 0; i < records.size(); ++i) {
    out += fmt::format("{}'{}' using 1:{} with lines lw 1.5 title '{}'", i ? ", " : "", file, i + 2,
                       records[i].label);
  }
  return out;
}

// The records of a panel that end before `asked_s`: a run stops at the stroke end, and a line
// that stops short must say why.
std::string early_ends(const std::vector<LabelledRecord>& records, const char* panel,
                       double asked_s) {
  std::string out;
  for (const auto& r : records) {
    const double end_s = static_cast<double>(r.series.size() - 1) / r.series.rate_Hz();
    if (end_s < asked_s - 1.5 / r.series.rate_Hz())
      out += fmt::format(" In ({}), {} ends at {:.1f} s: the piston reached the stroke end.", panel,
                         r.label, end_s);
  }
  return out;
}

}  // namespace

FigureSpec time_responses_figure(const std::vector<LabelledRecord>& meter_out,
                                 const std::vector<LabelledRecord>& meter_in) {
  FigureSpec f;
  f.name = "fig2_time_responses";
  f.caption =
      "Fig. 2: velocity responses of the paper's model (one rigid mass, eq. (4) friction) after "
      "the valve switches, under its own assumptions: (a) meter-out with the supply valve open "
      "wide (P1 = Ps, Section 3.2), (b) meter-in with the rod side open to atmosphere "
      "(Section 3.3)." +
      early_ends(meter_out, "a", 3.0) + early_ends(meter_in, "b", 3.0);
  f.data = {{"fig2_meter_out.dat", records_table(meter_out, 3.0)},
            {"fig2_meter_in.dat", records_table(meter_in, 3.0)}};
  f.height = 640;
  f.plot =
      "set multiplot layout 2,1\nset grid\nset xlabel 'time [s]'\nset ylabel 'velocity [mm/s]'\n"
      "set key outside right\n"
      "set title '(a) meter-out: exhaust speed controller S2, P1 = Ps'\nplot " +
      plot_columns("fig2_meter_out.dat", meter_out) +
      "\nset title '(b) meter-in: supply speed controller S1, P2 = Pa'\nplot " +
      plot_columns("fig2_meter_in.dat", meter_in) + "\nunset multiplot";
  return f;
}

// One gnuplot label per letter, offset from its point so the curve stays visible.
std::string loop_letters(const std::vector<std::vector<LoopLabel>>& letters) {
  std::string out;
  for (std::size_t r = 0; r < letters.size(); ++r)
    for (const LoopLabel& l : letters[r])
      out += fmt::format("set label '{}' at {},{} point pt 7 ps 1.2 lc 'black' offset 0.6,0.6 "
                         "font ',14'\n",
                         l.label, 1e3 * l.v_m_per_s, l.F_N);
  return out;
}

FigureSpec friction_loops_figure(const std::vector<LabelledRecord>& records, double seconds,
                                 const std::vector<std::array<double, 2>>& steady,
                                 const std::vector<std::vector<LoopLabel>>& letters) {
  FigureSpec f;
  f.name = "fig3_friction_velocity";
  f.caption = fmt::format(
      "Fig. 3: seal friction force against piston velocity over the last {:g} s of each record: "
      "the loops the friction traces while the velocity oscillates (the paper's A-B-C-B-D-A), "
      "beside the seal's steady friction-velocity curve (black, dashed), whose falling part at "
      "low speed is the negative slope B of the paper's Section 3.4. Letters mark one loop of "
      "each record as `pneumachaos friction` finds it (docs/friction.md): A breakaway (end of a "
      "stick), C top speed, D stop, B where the accelerating and decelerating branches cross.",
      seconds);
  std::string plot =
      "set grid\nset xlabel 'piston velocity [mm/s]'\nset ylabel 'seal friction [N]'\n"
      "set key below\n" + loop_letters(letters) + "plot ";
  for (std::size_t i = 0; i < records.size(); ++i) {
    const auto& s = records[i].series;
    const std::string file = fmt::format("fig3_record{}.dat", i + 1);
    std::string table = "# v[mm/s] F_friction[N] (" + records[i].label + ")\n";
    const auto& v = s.channel("v").values;
    const auto& F = s.channel("F_friction").values;
    // The last `seconds` of the record: the motion has settled onto its attractor.
    const std::size_t n = std::min(v.size(), static_cast<std::size_t>(seconds * s.rate_Hz()));
    for (std::size_t k = v.size() - n; k < v.size(); ++k)
      table += fmt::format("{} {}\n", 1e3 * v[k], F[k]);
    f.data.emplace_back(file, table);
    plot += fmt::format("{}'{}' using 1:2 with lines lw 1 title '{}'", i ? ", " : "", file,
                        records[i].label);
  }
  std::string curve = "# v[mm/s] F_steady[N]\n";
  for (const auto& [v, F] : steady) curve += fmt::format("{} {}\n", 1e3 * v, F);
  f.data.emplace_back("fig3_steady.dat", curve);
  f.plot = plot + ", 'fig3_steady.dat' using 1:2 with lines dt 2 lw 2 lc 'black' title 'steady "
                  "friction-velocity curve'";
  return f;
}

double stability_colour_scale(const StabilityMap& map) {
  std::vector<double> a;
  for (const auto& p : map.points)
    if (p.result.has_equilibrium()) a.push_back(std::abs(p.result.max_real_part_per_s));
  if (a.empty()) return 1.0;
  const auto k = (a.size() - 1) / 2;
  std::nth_element(a.begin(), a.begin() + static_cast<std::ptrdiff_t>(k), a.end());
  // Twice the median: the typical point sits mid-way to full colour whatever its sign.
  // Rounded up to a readable number, at least 1 1/s.
  const double q = std::max(1.0, 2.0 * a[k]);
  const double step = std::pow(10.0, std::floor(std::log10(q)));
  return std::ceil(q / step) * step;
}

FigureSpec stability_map_figure(const StabilityMap& map) {
  FigureSpec f;
  f.name = "stability_map";
  f.caption =
      "Stability of the steady motion over S1 x S2 (full-model Jacobian): largest real "
      "part of the eigenvalues, red self-excited, blue damped; crosses: no steady motion.";
  std::string table = "# S1[mm^2] S2[mm^2] max_real_part[1/s] (NaN: no equilibrium)\n";
  const double scale = stability_colour_scale(map);
  const std::size_t n2 = map.axes[1].values.size();
  std::size_t beyond = 0;
  for (std::size_t i = 0; i < map.points.size(); ++i) {
    const auto& p = map.points[i];
    const double v = p.result.has_equilibrium() ? p.result.max_real_part_per_s : NAN;
    table += fmt::format("{} {} {}\n", p.coordinates[0], p.coordinates[1], v);
    if ((i + 1) % n2 == 0) table += "\n";
    beyond += std::abs(v) > scale ? 1 : 0;
  }
  f.caption += fmt::format(
      " The colour scale is symmetric about 0 and set by the bulk of the values (+-{:g} 1/s, "
      "twice their median size) so the sign shows near 0; the {} points beyond it are drawn "
      "at full colour and marked with an open circle.",
      scale, beyond);
  f.data = {{"stability_map.dat", table}};
  f.plot =
      "set xlabel 'S1 [mm^2]'\nset ylabel 'S2 [mm^2]'\nset cblabel 'largest real part [1/s]' "
      "offset 2,0\n"
      "set palette defined (-1 'blue', 0 'white', 1 'red')\n" +
      fmt::format("set cbrange [-{0}:{0}]\n", scale) +
      "set title 'Stability of the steady motion: largest real part of the eigenvalues'\n"
      "set view map\nset key off\n"
      "plot 'stability_map.dat' using 1:2:3 with image, '' using 1:($3 != $3 ? $2 : 1/0) "
      "with points pt 2 lc 'black', " +
      fmt::format("'' using 1:(abs($3) > {} ? $2 : 1/0) with points pt 6 ps 0.6 lc 'black'", scale);
  return f;
}

namespace {

// The data layers of an incidence map: the grey image, the stick-slip outlines, the inferred
// points and the evaluated points without chaos (marked, so a white cell that was run is told
// from one that was not).
struct MapLayers {
  std::string grid = "# S1[mm^2] S2[mm^2] chaos_incidence stick_slip_incidence\n";
  std::string outline = "# stick-slip cells (outlined): x y dx dy, one edge per line\n";
  std::string inferred = "# points inferred from their cell, not run (adaptive map): x y\n";
  std::string calm = "# points run, no run chaotic: x y\n";
  std::size_t both = 0;  ///< cells chaotic at least once and stick-slip
};

MapLayers map_layers(const SweepSummary& summary, std::size_t n2, double d1, double d2) {
  MapLayers l;
  for (std::size_t i = 0; i < summary.per_point.size(); ++i) {
    const auto& p = summary.per_point[i];
    const double x = p.coordinates[0], y = p.coordinates[1];
    l.grid += fmt::format("{} {} {} {}\n", x, y, p.chaos_incidence, p.stick_slip_incidence);
    if ((i + 1) % n2 == 0) l.grid += "\n";
    if (p.inferred) l.inferred += fmt::format("{} {}\n", x, y);
    if (!p.inferred && p.chaos_incidence == 0.0) l.calm += fmt::format("{} {}\n", x, y);
    if (p.stick_slip_incidence < 0.5) continue;
    if (p.chaos_incidence > 0.0) ++l.both;
    // An outline inset into the cell, not a fill: the grey of the chaos incidence stays visible.
    const double x0 = x - 0.42 * d1, y0 = y - 0.42 * d2, w = 0.84 * d1, h = 0.84 * d2;
    l.outline += fmt::format("{0} {1} {2} 0\n{0} {1} 0 {3}\n{4} {1} 0 {3}\n{0} {5} {2} 0\n", x0, y0,
                             w, h, x0 + w, y0 + h);
  }
  return l;
}

}  // namespace

FigureSpec incidence_map_figure(const std::string& name, const std::string& title,
                                const SweepSpec& spec, const SweepSummary& summary) {
  const auto& s1 = spec.axes[0].values;
  const auto& s2 = spec.axes[1].values;
  const double d1 = s1.size() > 1 ? s1[1] - s1[0] : 0.05;
  const double d2 = s2.size() > 1 ? s2[1] - s2[0] : 0.15;
  const MapLayers l = map_layers(summary, s2.size(), d1, d2);
  FigureSpec f;
  f.name = name;
  f.caption = fmt::format(
      "{}: each cell is one (S1, S2) point of the grid; its grey is the share of its {} runs "
      "judged chaotic (white 0 %, black 100 %); a red outline marks stick-slip in at least half "
      "of its runs ({} cells are both chaotic at least once and stick-slip); a small grey "
      "circle marks a point run with no chaotic run. Left: the paper's full grid; right: the "
      "same map zoomed to S2 < 0.7 mm^2, where the regimes change.",
      title, spec.repeats, l.both);
  f.data = {
      {name + ".dat", l.grid}, {name + "_stick_slip.dat", l.outline}, {name + "_calm.dat", l.calm}};
  f.width = 1200;
  f.height = 600;
  std::string layers = fmt::format(
      "plot '{0}.dat' using 1:2:3 with image notitle, '{0}_stick_slip.dat' using 1:2:3:4 with "
      "vectors nohead lc '#d62728' lw 1.5 title 'stick-slip (half of the runs or more)', "
      "'{0}_calm.dat' using 1:2 with points pt 6 ps 0.7 lc 'gray40' title 'run, no chaos'",
      name);
  if (summary.inferred_points > 0) {  // an adaptive map: say which cells were not run
    f.caption += fmt::format(
        " Adaptive map: {} of the {} points were not run but inferred from the evaluated "
        "corners of their cell (docs/sweep.md, \"Adaptive maps\"); a small blue dot marks each.",
        summary.inferred_points, summary.per_point.size());
    f.data.emplace_back(name + "_inferred.dat", l.inferred);
    layers += fmt::format(
        ", '{}_inferred.dat' using 1:2 with points pt 7 ps 0.5 lc '#1f77b4' "
        "title 'inferred, not run'",
        name);
  }
  layers += "\n";
  f.plot = fmt::format(
      "set multiplot layout 1,2 title '{}'\nset xlabel 'S1 [mm^2]'\nset ylabel 'S2 [mm^2]'\n"
      "set cblabel 'chaos incidence (share of runs)' offset 1,0\nset palette gray negative\n"
      "set cbrange [0:1]\nset xrange [{}:{}]\nset key below horizontal\nset title 'full grid'\n"
      "set yrange [{}:{}]\n{}set title 'zoom: S2 < 0.7 mm^2'\nset yrange [{}:0.7]\n{}"
      "unset multiplot",
      title, s1.front() - d1 / 2, s1.back() + d1 / 2, s2.front() - d2 / 2, s2.back() + d2 / 2,
      layers, s2.front() - d2 / 2, layers);
  return f;
}

namespace {

FigureSpec fig7a_record(const std::vector<double>& v, double rate_Hz, double start_s) {
  FigureSpec f;
  f.name = "fig7a_record";
  f.caption = fmt::format(
      "Fig. 7a: the piston velocity of the chaotic example (S1 2.70, S2 0.35 mm^2), 5 s of the "
      "settled record analysed in Fig. 7b-d: from t = {:g} s on (the rest and start-up before "
      "it are left out).",
      start_s);
  std::string t = "# t[s] v[mm/s]\n";
  for (std::size_t k = 0; k < v.size() && k < static_cast<std::size_t>(5 * rate_Hz); ++k) {
    t += fmt::format("{} {}\n", start_s + k / rate_Hz, 1e3 * v[k]);
  }
  f.data = {{"fig7a_record.dat", t}};
  f.height = 360;
  f.plot =
      "set grid\nset xlabel 'time [s]'\nset ylabel 'velocity [mm/s]'\nset key off\n"
      "plot 'fig7a_record.dat' using 1:2 with lines lw 1";
  return f;
}

}  // namespace

std::array<double, 2> lyapunov_panel_range(const std::vector<double>& wolf,
                                          const std::vector<double>& model) {
  // The early running values are huge; the range holds the second halves of both estimates,
  // where they settle, with a margin.
  double lo = 0.0, hi = 1.0;
  for (const auto* x : {&wolf, &model})
    for (std::size_t k = x->size() / 2; k < x->size(); ++k) {
      lo = std::min(lo, (*x)[k]);
      hi = std::max(hi, (*x)[k]);
    }
  return {lo < 0.0 ? 1.2 * lo : 0.0, 1.5 * hi};
}

namespace {

FigureSpec fig7b_indices(double rate_Hz, const AnalysisResult& a,
                         const std::vector<double>& model_t,
                         const std::vector<double>& model_running) {
  FigureSpec f;
  f.name = "fig7b_indices";
  f.caption =
      "Fig. 7b: power spectrum, autocorrelation and the convergence of the maximum "
      "Lyapunov exponent: Wolf's running estimate from the record, the model's own (two "
      "nearby model states, renormalised) and the slope of the record's divergence curve " +
      std::string(a.divergence.found_linear_region
                      ? "(dashed)."
                      : "(not drawn: this record's divergence curve has no linear region).") +
      " They are three estimators of one exponent and need not agree closely: the "
      "record-based two see only the velocity, through a delay embedding of a finite record; "
      "the model's follows two nearby trajectories of the equations themselves and is the "
      "most direct.";
  std::string sp = "# f[Hz] psd[(mm/s)^2/Hz]\n";
  for (std::size_t k = 1; k < a.spectrum.psd.size(); ++k) {
    sp += fmt::format("{} {}\n", a.spectrum.frequency_Hz[k], 1e6 * a.spectrum.psd[k]);
  }
  std::string ac = "# lag[s] r\n";
  for (std::size_t k = 0; k < a.acf.r.size() && k < static_cast<std::size_t>(2 * rate_Hz); ++k) {
    ac += fmt::format("{} {}\n", k / rate_Hz, a.acf.r[k]);
  }
  std::string ly = "# t[s] wolf_running[1/s]\n";
  for (std::size_t k = 0; k < a.wolf.running_per_s.size(); ++k) {
    ly += fmt::format("{} {}\n", a.wolf.running_time_s[k], a.wolf.running_per_s[k]);
  }
  std::string ml = "# t[s] model_running[1/s]\n";
  for (std::size_t k = 0; k < model_running.size(); ++k)
    ml += fmt::format("{} {}\n", model_t[k] - model_t.front(), model_running[k]);
  f.data = {{"fig7b_spectrum.dat", sp},
            {"fig7b_acf.dat", ac},
            {"fig7b_wolf.dat", ly},
            {"fig7b_model.dat", ml}};
  f.width = 1200;
  f.height = 400;
  f.plot = fmt::format(
      "set multiplot layout 1,3\nset grid\n"
      "set title 'power spectrum'\nset logscale y\nset xrange [0:100]\nset xlabel 'frequency "
      "[Hz]'\n"
      "set ylabel 'PSD [(mm/s)^2/Hz]'\nset key off\nplot 'fig7b_spectrum.dat' using 1:2 with "
      "lines\n"
      "unset logscale y\nset xrange [*:*]\nset title 'autocorrelation'\nset xlabel 'lag [s]'\n"
      "set ylabel 'r'\nplot 'fig7b_acf.dat' using 1:2 with lines, 0 lc 'gray'\n"
      "set title 'maximum Lyapunov exponent'\nset xlabel 'time [s]'\nset ylabel '1/s'\n"
      "set key top right opaque\nset yrange [{}:{}]\n"
      "plot 'fig7b_wolf.dat' using 1:2 with lines title 'Wolf (running)', 'fig7b_model.dat' "
      "using 1:2 with lines title 'model (running)'{}\nunset multiplot",
      lyapunov_panel_range(a.wolf.running_per_s, model_running)[0],
      lyapunov_panel_range(a.wolf.running_per_s, model_running)[1],
      // No linear region: no line, rather than one drawn at 0.
      a.divergence.found_linear_region
          ? fmt::format(", {} with lines dt 2 title 'divergence curve'", a.divergence.lambda_per_s)
          : std::string());
  return f;
}

FigureSpec fig7c_trajectory(const std::vector<double>& v, double rate_Hz,
                            const AnalysisResult& a) {
  FigureSpec f;
  f.name = "fig7c_trajectory";
  f.caption = fmt::format(
      "Fig. 7c: the delay-embedded trajectory (v(t), v(t+tau), v(t+2 tau)) in mm/s, "
      "tau = {:.0f} ms: the first 4 s of the settled record analysed in Fig. 7b (the record "
      "from the time Fig. 7a starts; what came before is left out). The narrow loops near "
      "v = 0 are the piston nearly at rest between its swings.",
      1e3 * a.delay.delay / rate_Hz);
  const std::size_t tau = a.delay.delay;
  std::string t = "# v(t) v(t+tau) v(t+2tau) [mm/s]\n";
  for (std::size_t k = 0; k + 2 * tau < v.size() && k < static_cast<std::size_t>(4 * rate_Hz);
       ++k) {
    t += fmt::format("{} {} {}\n", 1e3 * v[k], 1e3 * v[k + tau], 1e3 * v[k + 2 * tau]);
  }
  f.data = {{"fig7c_trajectory.dat", t}};
  f.width = 700;
  f.height = 600;
  f.plot =
      "set xlabel 'v(t) [mm/s]'\nset ylabel 'v(t+tau) [mm/s]'\n"
      "set zlabel 'v(t+2tau) [mm/s]' rotate parallel\nset lmargin at screen 0.12\n"
      "set view 60,30\n"
      "set key off\nsplot 'fig7c_trajectory.dat' using 1:2:3 with lines lw 0.6";
  return f;
}

FigureSpec fig7d_poincare(const AnalysisResult& a) {
  FigureSpec f;
  f.name = "fig7d_poincare";
  f.caption = fmt::format(
      "Fig. 7d: Poincare section of the embedded trajectory through the plane "
      "v(t) = {:.1f} mm/s (upward crossings).",
      1e3 * a.poincare.level);
  std::string t = "# v(t+tau) v(t+2tau) [mm/s] at the crossings\n";
  for (const auto& p : a.poincare.points) t += fmt::format("{} {}\n", 1e3 * p[0], 1e3 * p[1]);
  f.data = {{"fig7d_poincare.dat", t}};
  f.width = 600;
  f.height = 560;
  f.plot =
      "set grid\nset xlabel 'v(t+tau) [mm/s]'\nset ylabel 'v(t+2tau) [mm/s]'\nset key off\n"
      "plot 'fig7d_poincare.dat' using 1:2 with points pt 7 ps 0.5";
  return f;
}

}  // namespace

std::vector<FigureSpec> chaotic_example_figures(const std::vector<double>& v, double rate_Hz,
                                                double start_s, const AnalysisResult& a,
                                                const std::vector<double>& model_t,
                                                const std::vector<double>& model_running) {
  return {fig7a_record(v, rate_Hz, start_s), fig7b_indices(rate_Hz, a, model_t, model_running),
          fig7c_trajectory(v, rate_Hz, a), fig7d_poincare(a)};
}

}  // namespace pneumachaos
