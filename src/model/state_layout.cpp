#include "pneumachaos/model/state_layout.hpp"

namespace pneumachaos {

std::size_t StateLayout::append(const std::string& name, const std::string& unit,
                                std::size_t count) {
  const std::size_t first = size;
  for (std::size_t i = 0; i < count; ++i) {
    entries.push_back({count == 1 || i == 0 ? name : name + std::to_string(i + 1), unit});
  }
  size += count;
  return first;
}

}  // namespace pneumachaos
