#pragma once
// The transducers through which a record is measured (docs/model.md, "The transducer"): the
// piston velocity through a velocity transducer, the chamber pressures P1 and P2 through one
// kind of pressure transducer, each read by an A/D converter. Every field 0 (the default) is
// the ideal transducer: the record is the sampled signal itself.

namespace pneumachaos {

/// The largest A/D resolution accepted: 24 bits, the finest converters built.
inline constexpr int kMaxTransducerBits = 24;

/// The piston velocity's transducer; its converter's full scale is -range..+range.
struct VelocityTransducer {
  double noise_m_per_s = 0.0;  ///< sd of the white noise in the record
  double bandwidth_Hz = 0.0;   ///< corner frequency of the first-order lag; 0: unlimited
  int bits = 0;                ///< A/D resolution; 0: no quantisation
  double range_m_per_s = 0.0;  ///< full scale +-range (clipped beyond); 0: none
};

/// The chamber pressures' transducer (P1 and P2 alike); its full scale is 0..range gauge, and
/// its record stays absolute.
struct PressureTransducer {
  double noise_Pa = 0.0;      ///< sd of the white noise in the record
  double bandwidth_Hz = 0.0;  ///< corner frequency of the first-order lag; 0: unlimited
  int bits = 0;               ///< A/D resolution; 0: no quantisation
  double range_Pa = 0.0;      ///< full scale 0..range above ambient (clipped beyond); 0: none
};

/// Applied to each sampled signal in this order: the first-order lag, the noise, then the
/// converter (clip to the full scale, round to the nearest of its 2^bits levels).
struct TransducerParams {
  VelocityTransducer velocity;
  PressureTransducer pressure;

  /// Every field 0: the records are the sampled signals themselves.
  [[nodiscard]] bool ideal() const;
  /// The keys' ranges (>= 0, bits <= kMaxTransducerBits) and a full scale wherever bits > 0;
  /// throws Error naming the key (transducer.*).
  void validate() const;
};

}  // namespace pneumachaos
