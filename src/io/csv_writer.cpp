#include "pneumachaos/io/csv_writer.hpp"

#include <fmt/format.h>

#include <iterator>

namespace pneumachaos {

void write_csv(std::ostream& out, const TimeSeries& series) {
  fmt::memory_buffer buf;
  fmt::format_to(std::back_inserter(buf), "t[s]");
  for (const auto& c : series.channels())
    fmt::format_to(std::back_inserter(buf), ",{}[{}]", c.name, c.unit);
  buf.push_back('\n');
  for (std::size_t k = 0; k < series.size(); ++k) {
    fmt::format_to(std::back_inserter(buf), "{}", series.time_s(k));
    for (const auto& c : series.channels())
      fmt::format_to(std::back_inserter(buf), ",{}", c.values[k]);
    buf.push_back('\n');
    if (buf.size() > (1u << 16)) {
      out.write(buf.data(), static_cast<std::streamsize>(buf.size()));
      buf.clear();
    }
  }
  out.write(buf.data(), static_cast<std::streamsize>(buf.size()));
}

}  // namespace pneumachaos
