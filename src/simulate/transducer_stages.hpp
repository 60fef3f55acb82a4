#pragma once
// The stages of a transducer and its converter on one sampled channel (docs/model.md, "The
// transducer"); measured_channels.cpp chains them.

#include <vector>

namespace pneumachaos {

/// The first-order lag tau y' + y = x, tau = 1 / (2 pi bandwidth_Hz), solved exactly for the
/// input that joins the samples x (taken at rate_Hz) by straight lines (first-order hold),
/// from y = x[0] (the sensor settled on the first sample). Unit gain at DC; bandwidth 0 is an
/// unlimited transducer and returns x unchanged.
std::vector<double> first_order_lag(std::vector<double> x, double rate_Hz, double bandwidth_Hz);

/// A converter of 2^bits levels lo + k step, step = (hi - lo) / 2^bits, k = 0 .. 2^bits - 1:
/// each value becomes the nearest level, those beyond the full scale the end level (the top
/// level is hi - step, as a two's-complement converter's). Mid-tread: with lo = -hi, 0 is a
/// level. bits 0: the values are only clipped to [lo, hi].
void quantise(std::vector<double>& x, int bits, double lo, double hi);

}  // namespace pneumachaos
