#include "analysis/fft.hpp"

#include <kissfft.hh>
#include <memory>

namespace pneumachaos {

std::size_t fast_fft_size(std::size_t min_size) {
  for (std::size_t n = std::max<std::size_t>(min_size, 1);; ++n) {
    std::size_t m = n;
    for (std::size_t p : {2, 3, 5}) {  // the radices KissFFT has fast butterflies for
      while (m % p == 0) m /= p;
    }
    if (m == 1) return n;
  }
}

namespace {

// Transforms in -> out with one of the last plans made, kept per thread. Making
// a plan computes n twiddle factors (complex exponentials): in a sweep, where every record has
// the same length, remaking it costs half of the autocorrelation (docs/notes/performance.md).
// Plans beyond 2^17 points (1e6-sample records) are made for the call and not kept, so they
// add nothing to the analysis' peak memory.
void transform(std::size_t n, bool inverse, const std::complex<double>* in,
               std::complex<double>* out) {
  constexpr std::size_t kLargestKept = std::size_t{1} << 17;
  if (n > kLargestKept) {
    kissfft<double>(n, inverse).transform(in, out);
    return;
  }
  // One analysis uses a few sizes (autocorrelation, periodogram, spectrum segments).
  constexpr std::size_t kSlots = 4;
  struct Kept {
    std::size_t n = 0;
    bool inverse = false;
    std::unique_ptr<kissfft<double>> plan;
  };
  thread_local Kept kept[kSlots];
  thread_local std::size_t next = 0;
  for (const Kept& k : kept) {
    if (k.plan && k.n == n && k.inverse == inverse) {
      k.plan->transform(in, out);
      return;
    }
  }
  Kept& k = kept[next++ % kSlots];
  k = Kept{n, inverse, std::make_unique<kissfft<double>>(n, inverse)};
  k.plan->transform(in, out);
}

}  // namespace

std::vector<std::complex<double>> forward_dft(std::span<const double> x, std::size_t n) {
  std::vector<std::complex<double>> in(n, 0.0), out(n);
  for (std::size_t i = 0; i < std::min(n, x.size()); ++i) in[i] = x[i];
  transform(n, false, in.data(), out.data());
  return out;
}

std::vector<double> inverse_dft_real(const std::vector<std::complex<double>>& X) {
  std::vector<std::complex<double>> out(X.size());
  transform(X.size(), true, X.data(), out.data());
  std::vector<double> re(X.size());
  for (std::size_t i = 0; i < X.size(); ++i) re[i] = out[i].real();
  return re;
}

struct DftPlan::Impl {
  explicit Impl(std::size_t n) : forward(n, false), inverse(n, true) {}
  kissfft<double> forward, inverse;
};

DftPlan::DftPlan(std::size_t n) : n_(n), impl_(std::make_unique<Impl>(n)), buffer_(n) {}
DftPlan::~DftPlan() = default;

void DftPlan::forward(std::span<const double> x, std::vector<std::complex<double>>& X) const {
  for (std::size_t i = 0; i < n_; ++i) buffer_[i] = x[i];
  X.resize(n_);
  impl_->forward.transform(buffer_.data(), X.data());
}

void DftPlan::transform(const std::vector<std::complex<double>>& in,
                        std::vector<std::complex<double>>& out, bool inverse) const {
  out.resize(n_);
  (inverse ? impl_->inverse : impl_->forward).transform(in.data(), out.data());
}

void DftPlan::inverse_real(const std::vector<std::complex<double>>& X,
                           std::vector<double>& x) const {
  impl_->inverse.transform(X.data(), buffer_.data());
  x.resize(n_);
  for (std::size_t i = 0; i < n_; ++i) x[i] = buffer_[i].real();
}

}  // namespace pneumachaos
