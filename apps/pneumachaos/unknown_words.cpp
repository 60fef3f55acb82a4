#include "unknown_words.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

#include "pneumachaos/core/error.hpp"

namespace pneumachaos::cli {
namespace {

// Levenshtein distance with transpositions counted as one edit (optimal string alignment).
std::size_t edit_distance(std::string_view a, std::string_view b) {
  const std::size_t n = a.size(), m = b.size();
  std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1));
  for (std::size_t i = 0; i <= n; ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= m; ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= n; ++i) {
    for (std::size_t j = 1; j <= m; ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  }
  return d[n][m];
}

// "; did you mean X?" for the nearest choice within a third of the word's length (at least
// two edits), or a choice the word begins; else "".
std::string did_you_mean(const std::string& word, const std::vector<std::string>& choices) {
  const std::string* best = nullptr;
  std::size_t best_d = std::max<std::size_t>(2, word.size() / 3) + 1;
  for (const auto& c : choices) {
    const std::size_t d = c.starts_with(word) && word.size() >= 3 ? 1 : edit_distance(word, c);
    if (d < best_d) {
      best_d = d;
      best = &c;
    }
  }
  return best == nullptr ? "" : fmt::format("; did you mean {}?", *best);
}

}  // namespace

void refuse_unknown_words(const CLI::App& app, int argc, char** argv) {
  if (argc < 2) return;
  const std::string first = argv[1];
  if (first.starts_with("-")) return;  // --help, --version: CLI11's
  const CLI::App* command = nullptr;
  std::vector<std::string> commands;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
    commands.push_back(sub->get_name());
    if (sub->get_name() == first) command = sub;
  }
  if (command == nullptr) {
    throw Error("", fmt::format("unknown command {}{} (the commands: {})", first,
                                did_you_mean(first, commands), fmt::join(commands, ", ")));
  }
  std::vector<std::string> options;
  for (const CLI::Option* o : command->get_options()) {
    for (const auto& l : o->get_lnames()) options.push_back("--" + l);
    for (const auto& f : o->get_fnames())
      if (f.starts_with("--")) options.push_back(f);
  }
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--") return;
    if (!arg.starts_with("--")) continue;
    const std::string name = arg.substr(0, arg.find('='));
    const auto known = std::find(options.begin(), options.end(), name);
    if (known == options.end()) {
      throw Error(first, fmt::format("unknown option {}{} (see `pneumachaos {} --help`)", name,
                                     did_you_mean(name, options), first));
    }
    // The option's value (a separate argument) is no option, even when it starts with "--".
    const CLI::Option* o = command->get_option_no_throw(name);
    if (o != nullptr && o->get_type_size_max() > 0 && arg.find('=') == std::string::npos) ++i;
  }
}

}  // namespace pneumachaos::cli
