#include <fmt/format.h>

#include <charconv>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/io/csv_fields.hpp"
#include "pneumachaos/sweep/sweep.hpp"

namespace pneumachaos {
namespace {

std::string clean(std::string s) {
  for (char& c : s) c = (c == ',' || c == '\n' || c == '\r' || c == '"') ? ';' : c;
  return s;
}

double to_double(const std::string& f) {
  if (f == "nan") return kNaN;
  double v = 0.0;
  const auto [p, ec] = std::from_chars(f.data(), f.data() + f.size(), v);
  if (ec != std::errc() || p != f.data() + f.size())
    throw Error("journal", "bad number \"" + f + "\"");
  return v;
}

std::uint64_t to_u64(const std::string& f) {
  std::uint64_t v = 0;
  const auto [p, ec] = std::from_chars(f.data(), f.data() + f.size(), v);
  if (ec != std::errc() || p != f.data() + f.size())
    throw Error("journal", "bad integer \"" + f + "\"");
  return v;
}

}  // namespace

std::string RunRecord::csv_header() {
  return "point,repeat,seed,ok,termination,t_final_s,steps,sticks,mean_v_m_per_s,std_v_m_per_s,"
         "lambda_per_s,lambda_uncertainty_per_s,wolf_per_s,broadband_share,late_acf,regime,"
         "chaotic,stick_slip,zero_one_K,prediction_ratio,repeat_share,lambda_model_per_s,"
         "lambda_model_uncertainty_per_s,lambda_model_span_s,reason";
}

std::string RunRecord::encode() const {
  return fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}",
                     point, repeat, seed, ok ? 1 : 0, clean(termination), t_final_s, steps, sticks,
                     mean_v, std_v, lambda, lambda_uncertainty, wolf, broadband, late_acf, regime,
                     chaotic ? 1 : 0, stick_slip ? 1 : 0, zero_one_K, prediction_ratio,
                     repeat_share, lambda_model, lambda_model_uncertainty, lambda_model_span_s, clean(reason));
}

RunRecord RunRecord::decode(const std::string& line) {
  const std::vector<std::string> f = split_csv_fields(line);
  if (f.size() != kFields)
    throw Error("journal", fmt::format("a record has {} fields, expected {}", f.size(), kFields));
  RunRecord r;
  r.point = to_u64(f[0]);
  r.repeat = to_u64(f[1]);
  r.seed = to_u64(f[2]);
  r.ok = f[3] == "1";
  r.termination = f[4];
  r.t_final_s = to_double(f[5]);
  r.steps = to_u64(f[6]);
  r.sticks = to_u64(f[7]);
  r.mean_v = to_double(f[8]);
  r.std_v = to_double(f[9]);
  r.lambda = to_double(f[10]);
  r.lambda_uncertainty = to_double(f[11]);
  r.wolf = to_double(f[12]);
  r.broadband = to_double(f[13]);
  r.late_acf = to_double(f[14]);
  r.regime = f[15];
  r.chaotic = f[16] == "1";
  r.stick_slip = f[17] == "1";
  r.zero_one_K = to_double(f[18]);
  r.prediction_ratio = to_double(f[19]);
  r.repeat_share = to_double(f[20]);
  r.lambda_model = to_double(f[21]);
  r.lambda_model_uncertainty = to_double(f[22]);
  r.lambda_model_span_s = to_double(f[23]);
  r.reason = f[24];
  return r;
}

}  // namespace pneumachaos
