#include "model/road/opendrive_reference_line.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "model/road/gauss_legendre.h"
#include "model/road/small_angle.h"

namespace rig::model::road {

namespace {

constexpr double kKnotStepMax_m = 0.5;
constexpr double kKnotTurnMax_rad = 0.1;  // heading change between knots (spiral, poly3)
constexpr int kMaxKnots = 1'000'000;
constexpr double kUnknownRate = std::numeric_limits<double>::infinity();

/// sin(x) / x, exact near 0 (the arc's chord over its length, halved angle).
double sinc(double x) noexcept { return std::abs(x) < 1e-4 ? 1.0 - x * x / 6.0 : std::sin(x) / x; }

double cubic(double a, double b, double c, double d, double p) noexcept {
  return a + p * (b + p * (c + p * d));
}
double cubic_slope(double b, double c, double d, double p) noexcept {
  return b + p * (2.0 * c + p * 3.0 * d);
}
double cubic_curve(double c, double d, double p) noexcept { return 2.0 * c + 6.0 * d * p; }

bool finite_geometry(const OpenDriveGeometry& g) {
  for (const double v : {g.s_m,
                         g.x_m,
                         g.y_m,
                         g.hdg_rad,
                         g.length_m,
                         g.curvature_1pm,
                         g.curv_start_1pm,
                         g.curv_end_1pm,
                         g.a,
                         g.b,
                         g.c,
                         g.d,
                         g.au,
                         g.bu,
                         g.cu,
                         g.du,
                         g.av,
                         g.bv,
                         g.cv,
                         g.dv}) {
    if (!std::isfinite(v)) return false;
  }
  return true;
}

double poly3_speed(const OpenDriveGeometry& g, double u) noexcept {
  const double slope = cubic_slope(g.b, g.c, g.d, u);
  return std::sqrt(1.0 + slope * slope);
}

/// The u at which the poly3's arc length from u0 reaches `length` (Newton on the arc length,
/// whose derivative is sqrt(1 + v'^2)); `six` picks the 6-point rule (knots) over the 3-point.
double poly3_u_at(const OpenDriveGeometry& g, double u0, double length, bool six) noexcept {
  auto speed = [&g](double u) { return poly3_speed(g, u); };
  double u = u0 + length / speed(u0);
  for (int it = 0; it < 8; ++it) {
    const double arc = six ? gauss_legendre6(u0, u, speed) : gauss_legendre3(u0, u, speed);
    const double step = (arc - length) / speed(u);
    u -= step;
    if (std::abs(step) < 1e-13 * (1.0 + std::abs(u))) break;
  }
  return u;
}

}  // namespace

OpenDriveReferenceLine::OpenDriveReferenceLine(const std::vector<OpenDriveGeometry>& plan_view) {
  for (const OpenDriveGeometry& g : plan_view) {
    if (!finite_geometry(g)) throw std::invalid_argument("plan view: a number is not finite");
    if (g.length_m < 0) throw std::invalid_argument("plan view: a negative length");
    if (!elements_.empty() && g.s_m < elements_.back().g.s_m)
      throw std::invalid_argument("plan view: geometries not in increasing s");
    if (g.length_m == 0) continue;  // no extent: nothing of the line is in it
    Element& e = elements_.emplace_back();
    e.g = g;
    e.cos_hdg = std::cos(g.hdg_rad);
    e.sin_hdg = std::sin(g.hdg_rad);
    e.spiral_rate = (g.curv_end_1pm - g.curv_start_1pm) / g.length_m;
    e.p_per_s = g.p_normalized ? 1.0 / g.length_m : 1.0;
  }
  if (elements_.empty()) throw std::invalid_argument("plan view: no geometry of positive length");
  for (std::size_t i = 0; i < elements_.size(); ++i) {
    Element& e = elements_[i];
    const double next_s = i + 1 < elements_.size() ? elements_[i + 1].g.s_m : e.g.s_m;
    add_knots(e, std::max(e.g.length_m, next_s - e.g.s_m));
  }
  start_s_ = elements_.front().g.s_m;
  end_s_ = elements_.back().g.s_m + elements_.back().g.length_m;
  start_pose_ = local(elements_.front(), 0.0);
  end_pose_ = local(elements_.back(), elements_.back().g.length_m);
  for (const Element& e : elements_) {
    const int n = std::max(2, static_cast<int>(std::ceil(e.g.length_m / 0.5)));
    for (int k = 0; k <= n; ++k) {
      const double ds = e.g.length_m * k / n;
      max_curvature_ = std::max(max_curvature_, std::abs(local(e, ds).curvature_1pm));
    }
  }
}

void OpenDriveReferenceLine::add_knots(Element& e, double span_m) {
  const OpenDriveGeometry& g = e.g;
  if (g.kind == OpenDriveGeometryKind::kSpiral) {
    const double k_max = std::max(std::abs(g.curv_start_1pm), std::abs(g.curv_end_1pm));
    // the turn over a knot step: k_max h + rate h^2 / 2 <= kKnotTurnMax_rad
    e.knot_step_m =
        std::min({kKnotStepMax_m, kKnotTurnMax_rad / std::max(k_max, 1e-12),
                  std::sqrt(kKnotTurnMax_rad / std::max(std::abs(e.spiral_rate), 1e-24))});
  } else if (g.kind == OpenDriveGeometryKind::kPoly3) {
    const double v2 = std::abs(g.c) + 3.0 * std::abs(g.d) * span_m;  // bounds |v''| / 2
    e.knot_step_m = std::min(kKnotStepMax_m, kKnotTurnMax_rad / std::max(2.0 * v2, 1e-12));
  } else {
    return;
  }
  const double intervals = std::ceil(span_m / e.knot_step_m);
  if (intervals + static_cast<double>(knots_.size()) > kMaxKnots)
    throw std::invalid_argument("the plan view is too long or too tightly curved: over " +
                                std::to_string(kMaxKnots) + " quadrature knots");
  e.first_knot = static_cast<int>(knots_.size());
  e.knot_count = static_cast<int>(intervals) + 1;
  if (g.kind == OpenDriveGeometryKind::kSpiral) {
    add_spiral_knots(e);
  } else {
    add_poly3_knots(e);
  }
}

void OpenDriveReferenceLine::add_spiral_knots(const Element& e) {
  const OpenDriveGeometry& g = e.g;
  auto heading = [&](double ds) {
    return g.hdg_rad + ds * (g.curv_start_1pm + 0.5 * e.spiral_rate * ds);
  };
  double x = g.x_m, y = g.y_m;
  for (int i = 0; i < e.knot_count; ++i) {
    const double s0 = i * e.knot_step_m;
    if (i > 0) {
      const Eigen::Vector2d d = gauss_legendre6(s0 - e.knot_step_m, s0, [&](double ds) {
        return Eigen::Vector2d(std::cos(heading(ds)), std::sin(heading(ds)));
      });
      x += d.x();
      y += d.y();
    }
    const double h = heading(s0);
    knots_.push_back({x, y, h, std::cos(h), std::sin(h)});
  }
}

void OpenDriveReferenceLine::add_poly3_knots(const Element& e) {
  double u = 0;
  knots_.push_back({u});
  for (int i = 1; i < e.knot_count; ++i) {
    u = poly3_u_at(e.g, u, e.knot_step_m, true);
    knots_.push_back({u});
  }
}

bool OpenDriveReferenceLine::in_element(double s_m, int element) const noexcept {
  const int n = element_count();
  if (element < 0) return s_m < start_s_;
  if (element >= n) return s_m > end_s_;
  return elements_[element].g.s_m <= s_m && s_m <= end_s_ &&
         (element + 1 == n || s_m < elements_[element + 1].g.s_m);
}

int OpenDriveReferenceLine::nearest_knot(const Element& e, double ds_m) noexcept {
  const double k = std::floor(ds_m / e.knot_step_m + 0.5);
  return static_cast<int>(std::clamp(k, 0.0, static_cast<double>(e.knot_count - 1)));
}

int OpenDriveReferenceLine::find(double s_m, int hint) const noexcept {
  const int n = element_count();
  auto covers = [&](int i) {
    return i >= 0 && i < n && elements_[i].g.s_m <= s_m &&
           (i + 1 == n || s_m < elements_[i + 1].g.s_m);
  };
  for (const int i : {hint, hint + 1, hint - 1}) {
    if (covers(i)) return i;
  }
  const auto it = std::upper_bound(elements_.begin(), elements_.end(), s_m,
                                   [](double s, const Element& e) { return s < e.g.s_m; });
  return static_cast<int>(it - elements_.begin()) - 1;  // -1: before the first
}

ReferencePose OpenDriveReferenceLine::pose(double s_m, int& element) const noexcept {
  if (s_m < start_s_) {
    element = -1;
    return straight(start_pose_, s_m - start_s_);
  }
  if (s_m > end_s_) {
    element = element_count();
    return straight(end_pose_, s_m - end_s_);
  }
  element = find(s_m, element);
  const Element& e = elements_[static_cast<std::size_t>(element)];
  return local(e, s_m - e.g.s_m);
}

ReferencePose OpenDriveReferenceLine::straight(const ReferencePose& from, double ds_m) noexcept {
  ReferencePose p = from;
  p.x_m += ds_m * from.cos_hdg;
  p.y_m += ds_m * from.sin_hdg;
  p.curvature_1pm = 0;
  p.speed = 1;
  p.curvature_rate = 0;
  return p;
}

ReferencePose OpenDriveReferenceLine::local(const Element& e, double ds_m) const noexcept {
  const OpenDriveGeometry& g = e.g;
  switch (g.kind) {
    case OpenDriveGeometryKind::kLine:
      return {g.x_m + ds_m * e.cos_hdg,
              g.y_m + ds_m * e.sin_hdg,
              g.hdg_rad,
              e.cos_hdg,
              e.sin_hdg,
              0.0,
              1.0,
              0.0};
    case OpenDriveGeometryKind::kArc:
      return arc(e, ds_m);
    case OpenDriveGeometryKind::kSpiral:
      return spiral(e, ds_m);
    case OpenDriveGeometryKind::kPoly3:
      return poly3(e, ds_m);
    case OpenDriveGeometryKind::kParamPoly3:
      return param_poly3(e, ds_m);
  }
  return {};
}

ReferencePose OpenDriveReferenceLine::arc(const Element& e, double ds_m) noexcept {
  // the chord 2 sin(k ds / 2) / k along the mean heading hdg + k ds / 2; one sine and cosine
  const OpenDriveGeometry& g = e.g;
  const double half = 0.5 * g.curvature_1pm * ds_m;
  const double ch = std::cos(half), sh = std::sin(half);
  const double chord = ds_m * sinc(half);
  const double cm = e.cos_hdg * ch - e.sin_hdg * sh, sm = e.sin_hdg * ch + e.cos_hdg * sh;
  return {g.x_m + chord * cm,
          g.y_m + chord * sm,
          g.hdg_rad + 2.0 * half,
          cm * ch - sm * sh,
          sm * ch + cm * sh,
          g.curvature_1pm,
          1.0,
          0.0};
}

ReferencePose OpenDriveReferenceLine::spiral(const Element& e, double ds_m) const noexcept {
  // from the nearest knot k: heading hdg_k + psi(d), psi(d) = kappa_k d + rate d^2 / 2 (small);
  // the position adds the integral of (cos psi, sin psi) over [0, d] by 3-point Gauss-Legendre
  const OpenDriveGeometry& g = e.g;
  const int k = nearest_knot(e, ds_m);
  const Knot& knot = knots_[static_cast<std::size_t>(e.first_knot) + static_cast<std::size_t>(k)];
  const double kappa_k = g.curv_start_1pm + e.spiral_rate * k * e.knot_step_m;
  const double d = ds_m - k * e.knot_step_m;
  const double half_rate = 0.5 * e.spiral_rate;
  const double half = 0.5 * d, dx = half * 0.7745966692414834;
  double ix = 0, iy = 0;
  for (const auto& [sigma, w] : {std::pair{half - dx, 5.0 / 9.0}, std::pair{half, 8.0 / 9.0},
                                 std::pair{half + dx, 5.0 / 9.0}}) {
    const CosSin c = cos_sin(sigma * (kappa_k + half_rate * sigma));
    ix += w * c.cos;
    iy += w * c.sin;
  }
  ix *= half;
  iy *= half;
  const double psi = d * (kappa_k + half_rate * d);
  const CosSin turn = cos_sin(psi);
  return {knot.x + knot.cos_hdg * ix - knot.sin_hdg * iy,
          knot.y + knot.sin_hdg * ix + knot.cos_hdg * iy,
          knot.hdg + psi,
          knot.cos_hdg * turn.cos - knot.sin_hdg * turn.sin,
          knot.sin_hdg * turn.cos + knot.cos_hdg * turn.sin,
          kappa_k + e.spiral_rate * d,
          1.0,
          e.spiral_rate};
}

ReferencePose OpenDriveReferenceLine::poly3(const Element& e, double ds_m) const noexcept {
  const OpenDriveGeometry& g = e.g;
  const int k = nearest_knot(e, ds_m);
  const double u =
      poly3_u_at(g, knots_[static_cast<std::size_t>(e.first_knot) + static_cast<std::size_t>(k)].x,
                 ds_m - k * e.knot_step_m, false);
  const double v = cubic(g.a, g.b, g.c, g.d, u);
  const double slope = cubic_slope(g.b, g.c, g.d, u);
  const double w = 1.0 + slope * slope;
  const double r = 1.0 / std::sqrt(w);  // the local tangent (1, v') / sqrt(w), rotated by hdg
  return {g.x_m + u * e.cos_hdg - v * e.sin_hdg,
          g.y_m + u * e.sin_hdg + v * e.cos_hdg,
          g.hdg_rad + std::atan(slope),
          (e.cos_hdg - slope * e.sin_hdg) * r,
          (e.sin_hdg + slope * e.cos_hdg) * r,
          cubic_curve(g.c, g.d, u) * r / w,
          1.0,
          kUnknownRate};
}

ReferencePose OpenDriveReferenceLine::param_poly3(const Element& e, double ds_m) noexcept {
  const OpenDriveGeometry& g = e.g;
  const double p = ds_m * e.p_per_s;
  const double u = cubic(g.au, g.bu, g.cu, g.du, p);
  const double v = cubic(g.av, g.bv, g.cv, g.dv, p);
  const double du = cubic_slope(g.bu, g.cu, g.du, p);
  const double dv = cubic_slope(g.bv, g.cv, g.dv, p);
  const double ddu = cubic_curve(g.cu, g.du, p);
  const double ddv = cubic_curve(g.cv, g.dv, p);
  const double q = du * du + dv * dv;
  const double rate = std::sqrt(q);
  const double r = rate > 0 ? 1.0 / rate : 0.0;
  // curvature of a parametric plane curve: (u' v'' - v' u'') / (u'^2 + v'^2)^(3/2)
  return {g.x_m + u * e.cos_hdg - v * e.sin_hdg,
          g.y_m + u * e.sin_hdg + v * e.cos_hdg,
          g.hdg_rad + std::atan2(dv, du),
          rate > 0 ? (du * e.cos_hdg - dv * e.sin_hdg) * r : e.cos_hdg,
          rate > 0 ? (du * e.sin_hdg + dv * e.cos_hdg) * r : e.sin_hdg,
          (du * ddv - dv * ddu) * r * r * r,
          rate * e.p_per_s,
          kUnknownRate};
}

}  // namespace rig::model::road
