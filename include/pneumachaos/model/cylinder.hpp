#pragma once
// Double-acting cylinder geometry (docs/model.md: V1 = V10 + A1 x, V2 = V20 - A2 x).

namespace pneumachaos {

struct CylinderGeometry {
  double bore_m = 0.040;
  double rod_m = 0.016;
  double stroke_m = 0.500;
  double dead_volume_head_m3 = 20e-6;  ///< chamber 1 volume at x = 0, tubing included
  double dead_volume_rod_m3 = 20e-6;   ///< chamber 2 volume at x = stroke, tubing included
  /// When >= 0: the chamber volumes are evaluated at this piston position whatever x is, and
  /// the stroke end does not stop the run (docs/virtual_rig.md: "volumes frozen at one piston
  /// position"): the dynamics of a long stroke around one position, for long records.
  double frozen_position_m = -1e-3;  ///< -1 mm: off (the key's documented value)
  [[nodiscard]] bool volumes_frozen() const { return frozen_position_m >= 0.0; }

  [[nodiscard]] double area_head_m2() const;  ///< A1, full bore
  [[nodiscard]] double area_rod_m2() const;   ///< A2, annulus
  /// V1 and V2 at piston position x (any scalar type: double, or an automatic-differentiation
  /// scalar when the plant's Jacobian is taken).
  template <typename T>
  [[nodiscard]] T volume_head_m3(const T& x_m) const {
    if (volumes_frozen()) return T(dead_volume_head_m3 + area_head_m2() * frozen_position_m);
    return dead_volume_head_m3 + area_head_m2() * x_m;
  }
  template <typename T>
  [[nodiscard]] T volume_rod_m3(const T& x_m) const {
    if (volumes_frozen()) {
      return T(dead_volume_rod_m3 + area_rod_m2() * (stroke_m - frozen_position_m));
    }
    return dead_volume_rod_m3 + area_rod_m2() * (stroke_m - x_m);
  }
};

}  // namespace pneumachaos
