#pragma once
// Uniformly sampled, multi-channel time series with named channels and units.

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "pneumachaos/core/error.hpp"

namespace pneumachaos {

/// One named channel of a TimeSeries, e.g. name "v", unit "m/s".
struct Channel {
  std::string name;
  std::string unit;
  std::vector<double> values;
};

/// Samples taken at t_k = start_s + k / rate_Hz, k = 0 .. size()-1, on every channel.
class TimeSeries {
 public:
  /// rate_Hz must be positive and finite.
  explicit TimeSeries(double rate_Hz, double start_s = 0.0);

  /// Adds an empty channel; throws Error if the name already exists.
  std::size_t add_channel(std::string name, std::string unit);
  /// Adds a channel with its values, one per existing sample (any count for the first one).
  std::size_t add_channel(std::string name, std::string unit, std::vector<double> values);
  /// Appends one sample row: one value per channel, in channel order.
  void append(std::span<const double> row);

  [[nodiscard]] double rate_Hz() const noexcept { return rate_Hz_; }
  [[nodiscard]] double start_s() const noexcept { return start_s_; }
  [[nodiscard]] double time_s(std::size_t k) const noexcept {
    return start_s_ + static_cast<double>(k) / rate_Hz_;
  }
  [[nodiscard]] std::size_t size() const noexcept;
  [[nodiscard]] const std::vector<Channel>& channels() const noexcept { return channels_; }
  /// The channel with this name; throws Error naming the known channels if absent.
  [[nodiscard]] const Channel& channel(const std::string& name) const;
  [[nodiscard]] bool has_channel(const std::string& name) const noexcept;
  /// Moves the channels out (e.g. to hand them to numpy without a copy); the series is left
  /// without channels.
  [[nodiscard]] std::vector<Channel> take_channels() && { return std::move(channels_); }

 private:
  double rate_Hz_;
  double start_s_;
  std::vector<Channel> channels_;
};

inline constexpr ErrorField kWindowFromField{"window.from_s", "from"};
inline constexpr ErrorField kWindowToField{"window.to_s", "to"};

/// The samples with from_s <= t <= to_s (times on the series' own clock, start_s included),
/// e.g. to skip a start-up transient; unset bounds are the series' ends. Throws Error about
/// kWindowFromField or kWindowToField for a bound that is not finite, lies outside the
/// record, or leaves fewer than 2 samples.
TimeSeries time_window(const TimeSeries& series, std::optional<double> from_s,
                       std::optional<double> to_s);

}  // namespace pneumachaos
