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

}  // namespace pneumachaos
