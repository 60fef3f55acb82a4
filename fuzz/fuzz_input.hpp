#pragma once
// What the analysis harnesses make of libFuzzer's bytes: a few option bytes from the front,
// then a record of 16-bit samples (as an A/D converter gives them, so repeats, plateaus and
// steps are common) times a power of ten chosen by one byte, so magnitudes from 1e-12 to
// 1e12 are reached. Every value is finite, as analyze_series demands of a record; bounding
// the record's length keeps each input cheap enough for 10^6 executions.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <vector>

namespace pneumachaos::fuzz {

class FuzzInput {
 public:
  FuzzInput(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  /// The next byte, 0 once the input is used up.
  std::uint8_t byte() { return pos_ < size_ ? data_[pos_++] : 0; }

  /// A whole number in [lo, hi] from the next byte.
  std::size_t in_range(std::size_t lo, std::size_t hi) { return lo + byte() % (hi - lo + 1); }

  /// The rest of the input as at most max_samples samples, scaled by 10^(byte % 25 - 12).
  std::vector<double> samples(std::size_t max_samples) {
    const double scale = std::pow(10.0, static_cast<int>(byte() % 25) - 12);
    std::vector<double> x;
    while (pos_ + 1 < size_ && x.size() < max_samples) {
      const auto raw = static_cast<std::int16_t>(data_[pos_] | (data_[pos_ + 1] << 8));
      x.push_back(static_cast<double>(raw) * scale);
      pos_ += 2;
    }
    return x;
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

/// Ends the process (a crash libFuzzer reports) when a stated property fails.
inline void require(bool property) {
  if (!property) std::abort();
}

}  // namespace pneumachaos::fuzz
