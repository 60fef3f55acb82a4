#pragma once
// The scenario keys users write in TOML files and --set overrides: one table that knows each
// key's unit, default, allowed range and how it maps onto the SI Scenario. Docs, the TOML
// reader, the command line and error messages all come from this table.

#include <string>
#include <variant>
#include <vector>

#include "pneumachaos/model/scenario.hpp"

namespace pneumachaos {

/// A value as written by the user: a number (in the key's unit) or a word.
using SettingValue = std::variant<double, std::string>;

struct KeyInfo {
  std::string key;          ///< e.g. "cylinder.bore_mm"
  std::string unit;         ///< e.g. "mm"; empty for words
  std::string description;  ///< one line, says what the value means
  std::string choices;      ///< for words: "meter-out | meter-in"; empty for numbers
  std::string range;        ///< for numbers: e.g. "> 0"
};

/// All keys in documentation order.
std::vector<KeyInfo> scenario_key_infos();

/// Sets `key` on the scenario. `where` names the source (a file:line, "--set") for errors.
/// Throws Error for an unknown key, a word where a number is expected (and vice versa), a
/// non-finite number, a value outside the key's range, or an unknown choice.
void apply_setting(Scenario& scenario, const std::string& key, const SettingValue& value,
                   const std::string& where);

/// Parses "text" as the value type of `key` (number or word), for the command line.
SettingValue parse_setting_text(const std::string& key, const std::string& text,
                                const std::string& where);

/// The present value of `key` in user units, as TOML-ready text (numbers round-trip).
std::string setting_text(const Scenario& scenario, const std::string& key);

/// A complete, commented TOML scenario holding the values of `scenario`.
std::string scenario_to_toml(const Scenario& scenario);

}  // namespace pneumachaos
