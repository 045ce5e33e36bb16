#pragma once
/// @file
/// An OpenDRIVE road's reference line (its <planView>): position, heading and curvature at a
/// station s. Each geometry element is evaluated as ASAM OpenDRIVE 1.7 sec. 9 defines it: a line;
/// an arc of constant curvature; a spiral (clothoid) whose curvature is linear in s; a poly3
/// v(u) in the element's local u/v frame (u along the start heading), s its arc length; a
/// paramPoly3 (u(p), v(p)) whose p runs linearly with s (pRange arcLength: p = ds, normalized:
/// p = ds / length). Before the first element and after the last the line runs on straight
/// along the end's heading (the rule model/road/DESIGN.md states for OpenDRIVE).
///
/// Constant after construction; pose() is noexcept and allocation-free. The clothoid's Fresnel
/// integrals and the poly3's arc length are integrated once, by 6-point Gauss-Legendre, to knots
/// at most 0.5 m apart (and close enough that the heading turns at most 0.1 rad between them); a
/// query integrates from its nearest knot by 3-point Gauss-Legendre, the clothoid's small turn
/// angles by their sine and cosine series: no trigonometric call on a spiral.

#include <vector>

#include "model/road/opendrive_road.h"

namespace rig::model::road {

/// The reference line at one station.
struct ReferencePose {
  double x_m = 0;
  double y_m = 0;
  double hdg_rad = 0;  ///< tangent heading (from +x, counter-clockwise)
  double cos_hdg = 1;  ///< its cosine and sine (the unit tangent)
  double sin_hdg = 0;
  double curvature_1pm = 0;  ///< > 0: turning left
  double speed = 1;          ///< |dP/ds|: 1 where s is arc length (all but paramPoly3)
  /// d curvature / ds [1/m^2]: 0 on lines and arcs (a circle is exact there), the clothoid's
  /// rate, infinity where it is not at hand (poly3, paramPoly3)
  double curvature_rate = 0;
};

class OpenDriveReferenceLine {
 public:
  /// Throws std::invalid_argument if the plan view is empty, not in increasing s, has a
  /// non-finite number or a negative length (io/config checks these first, with file:line).
  explicit OpenDriveReferenceLine(const std::vector<OpenDriveGeometry>& plan_view);

  /// The pose at station s [m]. `element` is the caller's hint: the element of the last query
  /// (any value works; it is updated to the element used, -1 and the count mean the straight
  /// extensions before and after).
  [[nodiscard]] ReferencePose pose(double s_m, int& element) const noexcept;

  /// Whether station s lies in `element` (as pose() numbers them, the extensions included).
  [[nodiscard]] bool in_element(double s_m, int element) const noexcept;

  [[nodiscard]] double start_s_m() const noexcept { return start_s_; }
  /// Where the last element ends (its s + length).
  [[nodiscard]] double end_s_m() const noexcept { return end_s_; }
  [[nodiscard]] int element_count() const noexcept { return static_cast<int>(elements_.size()); }
  /// The largest |curvature| over the knots and element ends [1/m] (0 for lines only).
  [[nodiscard]] double max_curvature_1pm() const noexcept { return max_curvature_; }

 private:
  struct Element {
    OpenDriveGeometry g;
    double cos_hdg = 1, sin_hdg = 0;
    double spiral_rate = 0;  ///< spiral: d(curvature)/ds [1/m^2]
    double p_per_s = 1;      ///< paramPoly3: dp/ds
    int first_knot = 0;      ///< spiral, poly3: knots_[first_knot ..] every knot_step_m
    int knot_count = 0;
    double knot_step_m = 1;
  };
  /// spiral: the pose at the knot; poly3: u at the knot (in x).
  struct Knot {
    double x = 0, y = 0, hdg = 0, cos_hdg = 1, sin_hdg = 0;
  };

  void add_knots(Element& e, double span_m);
  void add_spiral_knots(const Element& e);
  void add_poly3_knots(const Element& e);
  [[nodiscard]] int find(double s_m, int hint) const noexcept;
  [[nodiscard]] static int nearest_knot(const Element& e, double ds_m) noexcept;
  [[nodiscard]] ReferencePose local(const Element& e, double ds_m) const noexcept;
  [[nodiscard]] static ReferencePose arc(const Element& e, double ds_m) noexcept;
  [[nodiscard]] ReferencePose spiral(const Element& e, double ds_m) const noexcept;
  [[nodiscard]] ReferencePose poly3(const Element& e, double ds_m) const noexcept;
  [[nodiscard]] static ReferencePose param_poly3(const Element& e, double ds_m) noexcept;
  [[nodiscard]] static ReferencePose straight(const ReferencePose& from, double ds_m) noexcept;

  std::vector<Element> elements_;
  std::vector<Knot> knots_;
  double start_s_ = 0, end_s_ = 0;
  ReferencePose start_pose_, end_pose_;
  double max_curvature_ = 0;
};

}  // namespace rig::model::road
