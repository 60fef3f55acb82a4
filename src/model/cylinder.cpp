#include "pneumachaos/model/cylinder.hpp"

#include <numbers>

namespace pneumachaos {

double CylinderGeometry::area_head_m2() const { return std::numbers::pi / 4.0 * bore_m * bore_m; }

double CylinderGeometry::area_rod_m2() const {
  return std::numbers::pi / 4.0 * (bore_m * bore_m - rod_m * rod_m);
}

double CylinderGeometry::head_perimeter_m() const { return std::numbers::pi * bore_m; }

double CylinderGeometry::rod_perimeter_m() const { return std::numbers::pi * (bore_m + rod_m); }

}  // namespace pneumachaos
