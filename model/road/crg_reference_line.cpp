#include "model/road/crg_reference_line.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rig::model::road {
namespace {

/// The points of the cross sections: from the x/y channels, or integrated from the heading
/// channel (x_i = x_i-1 + du cos(phi_i), entry 0 unused) or the constant start heading; a given
/// end point takes the closure error, spread linearly over the points (as OpenCRG distributes it).
void reference_points(const CrgData& d, std::vector<double>& x, std::vector<double>& y) {
  const std::size_t n = d.nu();
  if (d.heading_rad.empty() && !d.ref_x_m.empty()) {
    x = d.ref_x_m;
    y = d.ref_y_m;
    return;
  }
  x.assign(n, d.start_x_m);
  y.assign(n, d.start_y_m);
  const double du = d.u_increment_m;
  for (std::size_t i = 1; i < n; ++i) {
    if (d.heading_rad.empty()) {  // straight: exact multiples, no accumulated rounding
      x[i] = d.start_x_m + static_cast<double>(i) * du * std::cos(d.start_phi_rad);
      y[i] = d.start_y_m + static_cast<double>(i) * du * std::sin(d.start_phi_rad);
    } else {
      x[i] = x[i - 1] + du * std::cos(d.heading_rad[i]);
      y[i] = y[i - 1] + du * std::sin(d.heading_rad[i]);
    }
  }
  if (!std::isfinite(d.end_x_m) || !std::isfinite(d.end_y_m) || n < 2) return;
  const double ex = d.end_x_m - x[n - 1];
  const double ey = d.end_y_m - y[n - 1];
  for (std::size_t i = 1; i < n; ++i) {
    const double w = static_cast<double>(i) / static_cast<double>(n - 1);
    x[i] += w * ex;
    y[i] += w * ey;
  }
}

}  // namespace

CrgReferenceLine::CrgReferenceLine(const CrgData& data)
    : u_first_m_(data.u_first_m),
      v_first_m_(data.v_m.front()),
      v_last_m_(data.v_m.back()),
      du_m_(data.u_increment_m) {
  reference_points(data, node_x_, node_y_);
  build_segments();
  start_clear_ = grid_behind_end(true);
  end_clear_ = grid_behind_end(false);
}

bool CrgReferenceLine::grid_behind_end(bool first) const noexcept {
  // the grid is the cross sections' edge points and the straight lines between them: it lies
  // behind the end's cross section if every edge point does
  const int last = segment_count() - 1;
  const Segment& g = segments_[static_cast<std::size_t>(first ? 0 : last)];
  const double ex = first ? node_x_m(0) : node_x_m(last + 1);
  const double ey = first ? node_y_m(0) : node_y_m(last + 1);
  const double tolerance = 1e-9 * (1 + du_m_ * (last + 1));
  for (int i = 0; i <= last + 1; ++i) {
    for (const double v : {v_first_m_, v_last_m_}) {
      double x = 0;
      double y = 0;
      point(u_first_m_ + i * du_m_, v, x, y);
      const double ahead = (x - ex) * g.tx + (y - ey) * g.ty;  // along the end's direction
      if (first ? ahead < -tolerance : ahead > tolerance) return false;
    }
  }
  return true;
}

bool CrgReferenceLine::beyond_the_ends(int k, const InSegment& s) const noexcept {
  return (k == 0 && s.before()) || (k == last_ && s.after());
}

void CrgReferenceLine::build_segments() {
  const std::size_t n = node_x_.size();
  segments_.resize(n - 1);
  last_ = static_cast<int>(n) - 2;
  for (std::size_t k = 0; k + 1 < n; ++k) {
    Segment& s = segments_[k];
    s.x0 = node_x_[k];
    s.y0 = node_y_[k];
    const double dx = node_x_[k + 1] - s.x0;
    const double dy = node_y_[k + 1] - s.y0;
    s.length = std::max(std::hypot(dx, dy), 1e-12);
    s.tx = dx / s.length;
    s.ty = dy / s.length;
  }
  // The cross section at point i runs along the normal of the chord P_i-1 P_i+1; its tangential
  // part relative to each adjacent segment, scaled to a unit normal part.
  auto tangential = [&](std::size_t node, const Segment& s) {
    const std::size_t lo = node == 0 ? 0 : node - 1;
    const std::size_t hi = std::min(node + 1, n - 1);
    const double cx = node_x_[hi] - node_x_[lo];
    const double cy = node_y_[hi] - node_y_[lo];
    const double mx = -cy;
    const double my = cx;
    const double normal_part = mx * -s.ty + my * s.tx;
    if (std::abs(normal_part) < 1e-10 * std::hypot(mx, my)) return 0.0;
    return (mx * s.tx + my * s.ty) / normal_part;
  };
  for (std::size_t k = 0; k + 1 < n; ++k) {
    segments_[k].a1 = tangential(k, segments_[k]);
    segments_[k].a2 = tangential(k + 1, segments_[k]);
    segments_[k].da = segments_[k].a2 - segments_[k].a1;
  }
}

CrgReferenceLine::InSegment CrgReferenceLine::in_segment(int k, double x_m,
                                                        double y_m) const noexcept {
  const Segment& s = segments_[static_cast<std::size_t>(k)];
  const double qx = x_m - s.x0;
  const double qy = y_m - s.y0;
  InSegment r;
  r.v = -s.ty * qx + s.tx * qy;
  r.w = s.tx * qx + s.ty * qy;
  r.den = s.length + r.v * s.da;
  r.num = r.w - r.v * s.a1;
  return r;
}

int CrgReferenceLine::walk(int k, double x_m, double y_m, InSegment& s) const noexcept {
  const int last = segment_count() - 1;
  s = in_segment(k, x_m, y_m);  // the wheel's usual cases first: the same or the next segment
  if (s.den > 0 && !s.before() && !s.after()) return k;
  if (s.den > 0 && s.after() && k < last) {
    s = in_segment(k + 1, x_m, y_m);
    if (s.den > 0 && !s.before() && (!s.after() || k + 1 == last)) return k + 1;
  }
  int direction = 0;
  for (int step = 0; step <= last + 1; ++step) {
    s = in_segment(k, x_m, y_m);
    if (!(s.den > 0)) {
      k = search(x_m, y_m);
      s = in_segment(k, x_m, y_m);
      return k;
    }
    if (s.before() && k > 0) {
      if (direction > 0) return k;  // between two cross sections that cross: stay
      --k;
      direction = -1;
    } else if (s.after() && k < last) {
      if (direction < 0) return k;
      ++k;
      direction = 1;
    } else {
      return k;
    }
  }
  return k;
}

int CrgReferenceLine::search(double x_m, double y_m) const noexcept {
  const int last = segment_count() - 1;
  int best_grid = -1;  // between the segment's cross sections and within the grid's width
  int best = -1;       // any, the straight continuations included
  double best_grid_v = std::numeric_limits<double>::infinity();
  double best_v = best_grid_v;
  for (int k = 0; k <= last; ++k) {
    const InSegment s = in_segment(k, x_m, y_m);
    const bool between = !s.before() && !s.after();
    if (!(s.den > 0) || !(between || beyond_the_ends(k, s))) continue;
    const double v = std::abs(s.v);
    if (between && s.v >= v_first_m_ && s.v <= v_last_m_ && v < best_grid_v) {
      best_grid = k;
      best_grid_v = v;
    }
    if (v < best_v) {
      best = k;
      best_v = v;
    }
  }
  if (best_grid >= 0) return best_grid;
  if (best >= 0) return best;
  // nowhere regular (inside a curve beyond its centre): the segment of the nearest point
  double best_d = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= last + 1; ++i) {
    const double d = std::hypot(x_m - node_x_m(i), y_m - node_y_m(i));
    if (d < best_d) {
      best_d = d;
      best = std::min(i, last);
    }
  }
  return best;
}

CrgStation CrgReferenceLine::station(int k, const InSegment& s, bool beyond) const noexcept {
  const Segment& g = segments_[static_cast<std::size_t>(k)];
  const double nx = -g.ty;
  const double ny = g.tx;
  CrgStation r;
  r.v_m = s.v;
  r.dv_dx = nx;
  r.dv_dy = ny;
  if (beyond) {  // the straight continuation
    const double from_m = k == 0 ? s.w : s.w - g.length;
    r.u_m = u_first_m_ + (k == 0 ? 0.0 : (last_ + 1) * du_m_) + from_m;
    r.du_dx = g.tx;
    r.du_dy = g.ty;
    return r;
  }
  const double inv_den = 1.0 / s.den;
  const double f = std::clamp(s.num * inv_den, 0.0, 1.0);
  r.u_m = u_first_m_ + (k + f) * du_m_;
  r.segment = k;
  r.fraction = f;
  // df/dp = (t - a1 n - f (a2 - a1) n) / (L + v (a2 - a1))
  const double a = g.a1 + f * g.da;
  r.du_dx = du_m_ * (g.tx - a * nx) * inv_den;
  r.du_dy = du_m_ * (g.ty - a * ny) * inv_den;
  return r;
}

CrgStation CrgReferenceLine::locate(double x_m, double y_m, int& segment) const noexcept {
  InSegment s;
  if (segment >= 0 && segment <= last_) {
    segment = walk(segment, x_m, y_m, s);
    // a continuation beyond an end, but maybe on the grid elsewhere (a road bending back)
    if (beyond_the_ends(segment, s) && !(segment == 0 && s.before() ? start_clear_ : end_clear_)) {
      segment = search(x_m, y_m);
      s = in_segment(segment, x_m, y_m);
    }
  } else {
    segment = search(x_m, y_m);
    s = in_segment(segment, x_m, y_m);
  }
  return station(segment, s, beyond_the_ends(segment, s));
}

void CrgReferenceLine::point(double u_m, double v_m, double& x_m, double& y_m) const noexcept {
  const int last = segment_count() - 1;
  const double t = (u_m - u_first_m_) / du_m_;
  if (t < 0 || t > last + 1) {  // the straight continuation
    const int k = t < 0 ? 0 : last;
    const Segment& g = segments_[static_cast<std::size_t>(k)];
    const double from_m = t < 0 ? u_m - u_first_m_ : u_m - u_first_m_ - (last + 1) * du_m_;
    const double x0 = t < 0 ? g.x0 : node_x_m(last + 1);
    const double y0 = t < 0 ? g.y0 : node_y_m(last + 1);
    x_m = x0 + from_m * g.tx - v_m * g.ty;
    y_m = y0 + from_m * g.ty + v_m * g.tx;
    return;
  }
  const int k = std::min(static_cast<int>(t), last);
  const double f = t - k;
  const Segment& g = segments_[static_cast<std::size_t>(k)];
  // A = P_k + v m'_k, B = P_k+1 + v m'_k+1, p = A + f (B - A); m' = n + a t
  const double ax = g.x0 + v_m * (-g.ty + g.a1 * g.tx);
  const double ay = g.y0 + v_m * (g.tx + g.a1 * g.ty);
  const double bx = node_x_m(k + 1) + v_m * (-g.ty + g.a2 * g.tx);
  const double by = node_y_m(k + 1) + v_m * (g.tx + g.a2 * g.ty);
  x_m = ax + f * (bx - ax);
  y_m = ay + f * (by - ay);
}

double CrgReferenceLine::heading_rad(double u_m) const noexcept {
  const int last = segment_count() - 1;
  const double t = std::floor((u_m - u_first_m_) / du_m_);
  const int k = t < 0 ? 0 : (t > last ? last : static_cast<int>(t));
  const Segment& g = segments_[static_cast<std::size_t>(k)];
  return std::atan2(g.ty, g.tx);
}

}  // namespace rig::model::road
