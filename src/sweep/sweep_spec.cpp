#include <fmt/format.h>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/model/scenario_keys.hpp"
#include "pneumachaos/sweep/sweep.hpp"

namespace pneumachaos {

void SweepSpec::validate() const {
  validate_grid(axes);
  if (repeats == 0) throw Error("repeats", "must be at least 1");
  if (runs() > 10'000'000)
    throw Error("grid", fmt::format("{} runs is more than 10 million", runs()));
  base.validate();
}

std::string SweepSpec::fingerprint() const {
  // FNV-1a over everything that decides the results; the text form of the scenario covers
  // every key.
  std::string text = "pneumachaos sweep v1\n" + scenario_to_toml(base);
  for (const auto& a : axes) {
    text += a.key + "=";
    for (double v : a.values) text += fmt::format("{};", v);
    text += "\n";
  }
  text += fmt::format("repeats={} seed={} wolf={}\n", repeats, seed, wolf);
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (unsigned char c : text) {
    h ^= c;
    h *= 0x100000001b3ULL;
  }
  return fmt::format("{:016x}", h);
}

}  // namespace pneumachaos
