#pragma once
// The page's own script and style (src/report/assets/), written beside index.html.

#include <string>

namespace pneumachaos {

/// Writes report.js, report_charts.js and report.css into the report folder `dir`.
void write_report_assets(const std::string& dir);

}  // namespace pneumachaos
