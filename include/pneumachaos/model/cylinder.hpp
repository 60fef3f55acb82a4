#pragma once
// Double-acting cylinder geometry (MODEL.md: V1 = V10 + A1 x, V2 = V20 - A2 x).

namespace pneumachaos {

struct CylinderGeometry {
  double bore_m = 0.040;
  double rod_m = 0.016;
  double stroke_m = 0.500;
  double dead_volume_head_m3 = 20e-6;  ///< chamber 1 volume at x = 0, tubing included
  double dead_volume_rod_m3 = 20e-6;   ///< chamber 2 volume at x = stroke, tubing included

  [[nodiscard]] double area_head_m2() const;  ///< A1, full bore
  [[nodiscard]] double area_rod_m2() const;   ///< A2, annulus
  [[nodiscard]] double volume_head_m3(double x_m) const {
    return dead_volume_head_m3 + area_head_m2() * x_m;
  }
  [[nodiscard]] double volume_rod_m3(double x_m) const {
    return dead_volume_rod_m3 + area_rod_m2() * (stroke_m - x_m);
  }
};

}  // namespace pneumachaos
