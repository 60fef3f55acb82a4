#include "pneumachaos/analysis/fft.hpp"

#include <kissfft.hh>

namespace pneumachaos {

std::size_t fast_fft_size(std::size_t min_size) {
  for (std::size_t n = std::max<std::size_t>(min_size, 1);; ++n) {
    std::size_t m = n;
    for (std::size_t p : {2, 3, 5}) {
      while (m % p == 0) m /= p;
    }
    if (m == 1) return n;
  }
}

std::vector<std::complex<double>> forward_dft(std::span<const double> x, std::size_t n) {
  std::vector<std::complex<double>> in(n, 0.0), out(n);
  for (std::size_t i = 0; i < std::min(n, x.size()); ++i) in[i] = x[i];
  kissfft<double>(n, false).transform(in.data(), out.data());
  return out;
}

std::vector<double> inverse_dft_real(const std::vector<std::complex<double>>& X) {
  std::vector<std::complex<double>> out(X.size());
  kissfft<double>(X.size(), true).transform(X.data(), out.data());
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
