#pragma once
/// @file
/// The reference line of an OpenCRG grid and the map between (x, y) of the file's frame and the
/// grid's (u, v), as OpenCRG evaluates it (crg_eval_uv2xy / crg_eval_xy2uv of the OpenCRG tools):
/// the line is the polygon through the points P_i of the cross sections (integrated from the
/// heading channel, x_i = x_{i-1} + du cos(phi_i), or given by x/y channels). Inside segment
/// [P_k, P_k+1] the cross section at P_k runs along m_k, the normal of the chord P_k-1 P_k+1
/// (at the ends: of the segment), scaled so that its component along the segment's normal n_k is
/// 1; a point is
///   p(f, v) = P_k + v m'_k + f (P_k+1 + v m'_k+1 - P_k - v m'_k),   u = u_k + f du,
/// so v is the distance from the segment (v = (p - P_k) . n_k) and f follows in closed form.
/// Before the first / beyond the last point the line continues straight along its end
/// segment (REFLINE_CONTINUATION = 0). Where several places fit a point (a road that bends back
/// near itself), the one whose grid holds it wins: a segment with the point between its cross
/// sections and within the grid's width, the nearest such (least |v|); else the nearest of all,
/// the straight continuations included. Constant after construction; locate() is noexcept and
/// allocation-free and walks from the probe's last segment (a rolling wheel costs a step); it
/// searches all segments only without a hint, or when the walk ends on a continuation beyond an
/// end across whose last cross section parts of the grid lie (a road that bends back).

#include <vector>

#include "model/road/crg_data.h"

namespace rig::model::road {

/// Where a point lies on the grid, with the gradients of u and v over the file frame's x and y.
struct CrgStation {
  double u_m = 0;
  double v_m = 0;
  double du_dx = 1;
  double du_dy = 0;
  double dv_dx = 0;
  double dv_dy = 1;
  /// Between the cross sections `segment` and `segment` + 1, at `fraction` (0..1) of the way;
  /// -1 on a straight continuation beyond an end.
  int segment = -1;
  double fraction = 0;
};

class CrgReferenceLine {
 public:
  explicit CrgReferenceLine(const CrgData& data);

  /// (u, v) of (x, y) of the file frame. `segment` is the probe's hint (the segment of its last
  /// query; out of range: none, a search over all segments); updated.
  [[nodiscard]] CrgStation locate(double x_m, double y_m, int& segment) const noexcept;
  /// (x, y) of (u, v): OpenCRG's uv2xy (the inverse of locate inside the grid).
  void point(double u_m, double v_m, double& x_m, double& y_m) const noexcept;
  /// Heading [rad] of the segment that holds u (before the start: the first, beyond the end: the
  /// last).
  [[nodiscard]] double heading_rad(double u_m) const noexcept;

  [[nodiscard]] int segment_count() const noexcept { return last_ + 1; }
  [[nodiscard]] double node_x_m(int i) const noexcept {
    return node_x_[static_cast<std::size_t>(i)];
  }
  [[nodiscard]] double node_y_m(int i) const noexcept {
    return node_y_[static_cast<std::size_t>(i)];
  }

 private:
  /// A segment P_k -> P_k+1: its start, unit tangent t, length, and the tangential parts a1, a2
  /// of the scaled cross-section directions m'_k = n + a1 t, m'_k+1 = n + a2 t (n = (-t_y, t_x)).
  struct Segment {
    double x0 = 0;
    double y0 = 0;
    double tx = 1;
    double ty = 0;
    double length = 1;
    double a1 = 0;
    double a2 = 0;
    double da = 0;  ///< a2 - a1
  };
  /// A point in segment k: fraction f along it (0..1 inside), distance v, and the denominator
  /// L + v (a2 - a1) (<= 0: beyond where neighbouring cross sections cross).
  struct InSegment {
    double v = 0;
    double w = 0;    ///< distance along the tangent from the segment's start
    double num = 0;  ///< w - v a1: f = num / den, so that the walk needs no division
    double den = 1;
    [[nodiscard]] bool before() const noexcept { return num < 0; }
    [[nodiscard]] bool after() const noexcept { return num > den; }
  };

  void build_segments();
  [[nodiscard]] InSegment in_segment(int k, double x_m, double y_m) const noexcept;
  /// The segment the walk from k ends in, and the point in it (`s`): at once where the probe is
  /// still in segment k or has moved into a neighbour (a rolling wheel), else step by step.
  [[nodiscard]] int walk(int k, double x_m, double y_m, InSegment& s) const noexcept;
  [[nodiscard]] int search(double x_m, double y_m) const noexcept;
  [[nodiscard]] CrgStation station(int k, const InSegment& s, bool beyond) const noexcept;
  [[nodiscard]] bool beyond_the_ends(int k, const InSegment& s) const noexcept;
  /// Whether the whole grid lies behind the first / last cross section (then no point beyond it
  /// can be on the grid).
  [[nodiscard]] bool grid_behind_end(bool first) const noexcept;

  int last_ = 0;  ///< the last segment
  double u_first_m_ = 0;
  double v_first_m_ = 0;  ///< the grid's width (right and left edges)
  double v_last_m_ = 0;
  bool start_clear_ = true;  ///< grid_behind_end(true)
  bool end_clear_ = true;
  double du_m_ = 1;
  std::vector<double> node_x_;
  std::vector<double> node_y_;
  std::vector<Segment> segments_;
};

}  // namespace rig::model::road
