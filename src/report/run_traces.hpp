#pragma once
// What the page's run panel draws for each run of a map: the velocity record the sweep's
// analysis judged, its spectrum and its autocorrelation, cut to a few hundred points each and
// quantised for display (runs/FIGURE.js, read by src/report/assets/report.js).

#include <cstddef>
#include <map>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "report/report_data.hpp"

namespace pneumachaos {

/// A series for the page: n values, x of the k-th at x0 + k dx, each value quantised to 12
/// bits between lo and hi and written as two characters of the base64 alphabet (value =
/// lo + (hi - lo) * code / 4095): about a third of the text of printed numbers, and 1/4095 of
/// the chart's height is below a pixel.
std::string quantise_series(const std::vector<double>& values, double& lo, double& hi);

/// The values of x in `buckets` equal parts, each part's smallest and largest in the order they
/// occur: a record's shape at any length (a stride would alias its oscillation). x itself
/// when it has no more than 2 x buckets values.
std::vector<double> min_max_decimate(const std::vector<double>& x, std::size_t buckets);

/// One map's run traces: the record the sweep judged, cut for display, and its spectrum and
/// autocorrelation as the analysis library computes them under the sweep's options. Kept while
/// the sweep runs (keep, as its SweepOptions::on_run), so no run is simulated twice.
class RunTraces {
 public:
  /// Keeps a simulated run's traces; thread-safe, never throws (a run with no traces keeps why).
  void keep(const SweepRun& run);

  /// runs/FIGURE.js: the script that adds the map's runs to window.PNEUMACHAOS_RUNS[FIGURE]
  /// ("POINT:REPEAT" -> traces). A run not kept (its sweep resumed from the journal, or ran on
  /// another MPI rank) is simulated again here (simulate_run: the same record to the last
  /// bit), on `threads` threads (0: all).
  [[nodiscard]] std::string js(const MapData& map, const std::vector<RunKey>& runs,
                               std::size_t threads);

 private:
  std::mutex mutex_;
  std::map<std::pair<std::size_t, std::size_t>, std::string> traces_;  ///< JSON, by run
};

}  // namespace pneumachaos
