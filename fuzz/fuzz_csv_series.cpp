// libFuzzer harness: the CSV series reader on arbitrary text. Bad input must end in
// pneumachaos::Error; anything else (a crash, a sanitizer report, another exception) is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/io/csv_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  for (const char* column : {"v", "x"}) {
    pneumachaos::CsvSeriesOptions options;
    options.column = column;
    try {
      (void)pneumachaos::parse_csv_series(text, "fuzz.csv", options);
    } catch (const pneumachaos::Error&) {
    }
  }
  return 0;
}
