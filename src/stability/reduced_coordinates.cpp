#include "reduced_coordinates.hpp"

namespace pneumachaos::reduced {

std::vector<Entry> entries(const StateLayout& L) {
  std::vector<Entry> r;
  for (std::size_t i = 0; i < L.size; ++i) {
    if (i == L.x) continue;
    if (i == L.load_x) {
      r.push_back({"deflection", i, true});
    } else {  // by the layout's name, as the output channel (theta, z_gms2, z_guide, ...)
      r.push_back({L.entries[i].name, i});
    }
  }
  return r;
}

Eigen::VectorXd of(const StateLayout& L, const std::vector<Entry>& r, std::span<const double> x) {
  Eigen::VectorXd y(static_cast<Eigen::Index>(r.size()));
  for (std::size_t k = 0; k < r.size(); ++k)
    y[static_cast<Eigen::Index>(k)] = r[k].deflection ? x[L.x] - x[r[k].full] : x[r[k].full];
  return y;
}

std::vector<double> full(const StateLayout& L, const std::vector<Entry>& r,
                         std::vector<double> base, const Eigen::VectorXd& y) {
  for (std::size_t k = 0; k < r.size(); ++k) {
    const double yk = y[static_cast<Eigen::Index>(k)];
    base[r[k].full] = r[k].deflection ? base[L.x] - yk : yk;
  }
  return base;
}

Eigen::VectorXd rates(const Plant& plant, const std::vector<Entry>& r, std::span<const double> x) {
  std::vector<double> dx(x.size());
  plant.derivative(plant.sliding_mode(+1), x, dx, 0.0);
  return of(plant.layout(), r, dx);  // the deflection's rate is v - v_load, as its value's
}

Eigen::MatrixXd jacobian(const Plant& plant, const std::vector<Entry>& r,
                         std::span<const double> x) {
  const StateLayout& L = plant.layout();
  const auto n = static_cast<Eigen::Index>(L.size);
  const auto m = static_cast<Eigen::Index>(r.size());
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> dfdx(n, n);
  Eigen::VectorXd dfdt(n);
  plant.jacobian(plant.sliding_mode(+1), x, 0.0, std::span<double>(dfdx.data(), dfdx.size()),
                 std::span<double>(dfdt.data(), dfdt.size()));
  // The reduced state is a linear function of the full one and back (of and full), so the
  // chain rule is exact: J = D dfdx E.
  Eigen::MatrixXd E = Eigen::MatrixXd::Zero(n, m);  // d full state / d reduced state
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(m, n);  // d reduced rate / d full rate
  for (Eigen::Index k = 0; k < m; ++k) {
    const auto i = static_cast<Eigen::Index>(r[static_cast<std::size_t>(k)].full);
    if (r[static_cast<std::size_t>(k)].deflection) {
      E(i, k) = -1.0;  // x_load = x - deflection
      D(k, static_cast<Eigen::Index>(L.x)) = 1.0;
      D(k, i) = -1.0;
    } else {
      E(i, k) = 1.0;
      D(k, i) = 1.0;
    }
  }
  return D * dfdx * E;
}

}  // namespace pneumachaos::reduced
