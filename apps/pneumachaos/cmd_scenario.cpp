// `pneumachaos scenario`: the built-in defaults as a commented TOML file, or the key table.

#include <fmt/format.h>

#include "commands.hpp"
#include "pneumachaos/model/scenario_keys.hpp"
#include "pneumachaos/model/scenario_toml.hpp"

namespace pneumachaos::cli {
namespace {

// A Markdown table cell: "|" (in |v|, between a word key's choices) would end the cell.
std::string cell(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '|') out += '\\';
    out += c;
  }
  return out;
}

}  // namespace

Action add_scenario(CLI::App& app) {
  struct Args {
    ScenarioArgs scenario;
    bool keys = false;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "scenario", "Print a complete, commented scenario (defaults, or a file with overrides)");
  add_scenario_options(cmd, args->scenario);
  cmd->add_flag("--keys", args->keys, "list every key with its unit and range (Markdown table)");
  return [args]() {
    if (args->keys) {
      fmt::print("| key | unit | default | meaning | allowed |\n|---|---|---|---|---|\n");
      const Scenario d = default_scenario();
      for (const auto& k : scenario_key_infos()) {
        fmt::print("| `{}` | {} | {} | {} | {} |\n", k.key, k.unit, setting_text(d, k.key),
                   cell(k.description), cell(k.choices.empty() ? k.range : k.choices));
      }
      return kExitOk;
    }
    fmt::print("{}", scenario_to_toml(build_scenario(args->scenario.file, args->scenario.sets)));
    return kExitOk;
  };
}

}  // namespace pneumachaos::cli
