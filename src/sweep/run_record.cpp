// The run record's CSV form (runs.csv and the journal), declared once: one table of fields
// from which the header, the writer and the reader all follow, so a new field is one line.
#include <fmt/format.h>

#include <array>
#include <charconv>
#include <optional>
#include <type_traits>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/io/csv_fields.hpp"
#include "pneumachaos/sweep/sweep.hpp"

namespace pneumachaos {
namespace {

std::string clean(std::string s) {
  for (char& c : s) c = (c == ',' || c == '\n' || c == '\r' || c == '"') ? ';' : c;
  return s;
}

// Doubles print as their shortest round-trip form ("nan" for NaN), flags as 1 / 0, text
// with the CSV's separators replaced.
template <typename T>
std::string put(const T& v) {
  if constexpr (std::is_same_v<T, bool>) {
    return v ? "1" : "0";
  } else if constexpr (std::is_same_v<T, std::optional<bool>>) {
    return v ? put(*v) : std::string();  // empty: not judged
  } else if constexpr (std::is_same_v<T, std::string>) {
    return clean(v);
  } else {
    return fmt::format("{}", v);
  }
}

template <typename T>
void get(const std::string& f, T& out) {
  if constexpr (std::is_same_v<T, bool>) {
    out = f == "1";
  } else if constexpr (std::is_same_v<T, std::optional<bool>>) {
    out = f.empty() ? std::nullopt : std::optional<bool>(f == "1");
  } else if constexpr (std::is_same_v<T, std::string>) {
    out = f;
  } else {
    if (std::is_floating_point_v<T> && f == "nan") {
      out = kNaN;
      return;
    }
    const auto [p, ec] = std::from_chars(f.data(), f.data() + f.size(), out);
    if (ec != std::errc() || p != f.data() + f.size())
      throw Error("journal", fmt::format("bad {} \"{}\"",
                                         std::is_floating_point_v<T> ? "number" : "integer", f));
  }
}

struct Field {
  const char* name;
  std::string (*write)(const RunRecord&);
  void (*read)(RunRecord&, const std::string&);
};

template <auto Member>
constexpr Field field(const char* name) {
  return {name, [](const RunRecord& r) { return put(r.*Member); },
          [](RunRecord& r, const std::string& f) { get(f, r.*Member); }};
}

// The columns of runs.csv, in order.
constexpr std::array kTable = {
    field<&RunRecord::point>("point"),
    field<&RunRecord::repeat>("repeat"),
    field<&RunRecord::seed>("seed"),
    field<&RunRecord::ok>("ok"),
    field<&RunRecord::termination>("termination"),
    field<&RunRecord::t_final_s>("t_final_s"),
    field<&RunRecord::steps>("steps"),
    field<&RunRecord::sticks>("sticks"),
    field<&RunRecord::mean_v>("mean_v_m_per_s"),
    field<&RunRecord::std_v>("std_v_m_per_s"),
    field<&RunRecord::lambda>("lambda_per_s"),
    field<&RunRecord::lambda_uncertainty>("lambda_uncertainty_per_s"),
    field<&RunRecord::wolf>("wolf_per_s"),
    field<&RunRecord::broadband>("broadband_share"),
    field<&RunRecord::late_acf>("late_acf"),
    field<&RunRecord::regime>("regime"),
    field<&RunRecord::chaotic>("chaotic"),
    field<&RunRecord::stick_slip>("stick_slip"),
    field<&RunRecord::zero_one_K>("zero_one_K"),
    field<&RunRecord::prediction_ratio>("prediction_ratio"),
    field<&RunRecord::repeat_share>("repeat_share"),
    field<&RunRecord::lambda_model>("lambda_model_per_s"),
    field<&RunRecord::lambda_model_uncertainty>("lambda_model_uncertainty_per_s"),
    field<&RunRecord::lambda_model_span_s>("lambda_model_span_s"),
    field<&RunRecord::reason>("reason"),
    // Last, so that the columns before it keep their places for readers of older files.
    field<&RunRecord::paper_chaotic>("paper_chaotic"),
};

}  // namespace

const std::size_t RunRecord::kFields = kTable.size();

std::string RunRecord::csv_header() {
  std::string h;
  for (const Field& f : kTable) {
    if (!h.empty()) h += ',';
    h += f.name;
  }
  return h;
}

std::vector<std::pair<std::string, std::string>> RunRecord::named_fields() const {
  std::vector<std::pair<std::string, std::string>> out;
  for (const Field& f : kTable) out.emplace_back(f.name, f.write(*this));
  return out;
}

std::string RunRecord::encode() const {
  std::string line;
  for (const Field& f : kTable) {
    if (!line.empty()) line += ',';
    line += f.write(*this);
  }
  return line;
}

RunRecord RunRecord::decode(const std::string& line) {
  const std::vector<std::string> f = split_csv_fields(line);
  if (f.size() != kFields)
    throw Error("journal", fmt::format("a record has {} fields, expected {}", f.size(), kFields));
  RunRecord r;
  for (std::size_t i = 0; i < kFields; ++i) kTable[i].read(r, f[i]);
  return r;
}

}  // namespace pneumachaos
