#pragma once
// What the page's run panel draws for each run of a map: the velocity record the sweep's
// analysis judged, its spectrum and its autocorrelation, cut to a few hundred points each and
// quantised for display (runs/FIGURE.js, read by src/report/assets/report.js).

#include <cstddef>
#include <string>
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

/// runs/FIGURE.js: the script that adds the map's runs to window.PNEUMACHAOS_RUNS[FIGURE]
/// ("POINT:REPEAT" -> traces). Each run is simulated again as the sweep ran it (simulate_run:
/// the same record to the last bit) and analysed with the analysis library's spectrum and
/// autocorrelation under the sweep's options, on `threads` threads (0: all).
std::string run_traces_js(const MapData& map, const std::vector<RunKey>& runs,
                          std::size_t threads);

}  // namespace pneumachaos
