#include "pneumachaos/model/state_layout.hpp"

#include <algorithm>

namespace pneumachaos {

std::size_t StateLayout::append(const std::string& name, const std::string& unit, double scale,
                                StateBlock block, std::size_t count) {
  const std::size_t first = size;
  for (std::size_t i = 0; i < count; ++i) {
    entries.push_back(
        {count == 1 || i == 0 ? name : name + std::to_string(i + 1), unit, scale, block});
  }
  size += count;
  return first;
}

bool StateLayout::has(StateBlock block) const {
  return std::any_of(entries.begin(), entries.end(),
                     [block](const Entry& e) { return e.block == block; });
}

}  // namespace pneumachaos
