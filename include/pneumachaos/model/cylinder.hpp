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
  /// the stroke end does not stop the run (docs/notes/virtual_rig.md, "What was tried":
  /// volumes frozen at one position): the dynamics of a long stroke around one position, for
  /// long records.
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
  /// Wetted wall of a chamber of volume V (docs/model.md, "Chamber temperatures"): its two
  /// end faces plus the barrel (and rod) over the length V / A the volume would fill, so the
  /// dead volume counts as more barrel.
  template <typename T>
  [[nodiscard]] T wall_area_head_m2(const T& V_m3) const {
    return 2.0 * area_head_m2() + head_perimeter_m() * V_m3 / area_head_m2();
  }
  template <typename T>
  [[nodiscard]] T wall_area_rod_m2(const T& V_m3) const {
    return 2.0 * area_rod_m2() + rod_perimeter_m() * V_m3 / area_rod_m2();
  }
  [[nodiscard]] double head_perimeter_m() const;  ///< pi bore
  [[nodiscard]] double rod_perimeter_m() const;   ///< pi (bore + rod): barrel and rod
};

}  // namespace pneumachaos
