#include "report/report_assets.hpp"

#include <string_view>
#include <utility>

#include "pneumachaos/io/atomic_file.hpp"
#include "report_assets/embedded_assets.hpp"

namespace pneumachaos {

void write_report_assets(const std::string& dir) {
  for (const auto& [name, text] :
       {std::pair<const char*, std::string_view>{"report.js", assets::report_js},
        {"report_charts.js", assets::report_charts_js},
        {"report.css", assets::report_css}}) {
    AtomicFile f(dir + "/" + name);
    f.stream() << text;
    f.commit();
  }
}

}  // namespace pneumachaos
