#include "rig/kpi/iso3888_kpis.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace rig::kpi {
namespace {

struct Point {
  double x, y;
};

/// The outline's corners in the road frame at a pose: front left, front right, rear right,
/// rear left.
std::array<Point, 4> outline(const Iso3888Params& p, double x, double y, double yaw) {
  const double c = std::cos(yaw), s = std::sin(yaw), w = 0.5 * p.vehicle_width_m;
  const double front = p.cg_to_front_m, rear = p.cg_to_front_m - p.vehicle_length_m;
  const auto at = [&](double bx, double by) {
    return Point{x + c * bx - s * by, y + s * bx + c * by};
  };
  return {at(front, w), at(front, -w), at(rear, -w), at(rear, w)};
}

/// The y range of the outline's part within x in [x0, x1] (the polygon clipped to the strip:
/// its corners inside and its edges' crossings of the strip's two lines); false if none of it
/// lies there.
bool y_range_in_strip(const std::array<Point, 4>& poly, double x0, double x1, double& y_min,
                      double& y_max) {
  y_min = 1e300, y_max = -1e300;
  const auto take = [&](double y) { y_min = std::min(y_min, y), y_max = std::max(y_max, y); };
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Point& a = poly[i];
    const Point& b = poly[(i + 1) % poly.size()];
    if (a.x >= x0 && a.x <= x1) take(a.y);
    for (const double xl : {x0, x1}) {  // the edge a-b crossing the line x = xl
      if ((a.x - xl) * (b.x - xl) < 0.0) take(a.y + (xl - a.x) / (b.x - a.x) * (b.y - a.y));
    }
  }
  return y_min <= y_max;
}

/// The distance from a point to the outline at a pose (0 inside).
double distance_to_outline(const Iso3888Params& p, double x, double y, double yaw, Point q) {
  const double c = std::cos(yaw), s = std::sin(yaw);
  const double bx = c * (q.x - x) + s * (q.y - y), by = -s * (q.x - x) + c * (q.y - y);
  const double rear = p.cg_to_front_m - p.vehicle_length_m, w = 0.5 * p.vehicle_width_m;
  const double dx = bx < rear ? rear - bx : bx > p.cg_to_front_m ? bx - p.cg_to_front_m : 0.0;
  const double dy = std::abs(by) > w ? std::abs(by) - w : 0.0;
  return std::hypot(dx, dy);
}

std::vector<Point> cones(const Iso3888Params& p) {
  std::vector<Point> out;
  for (const Iso3888Lane& l : iso3888_lanes(p)) {
    const double off = 0.5 * l.width_m + p.cone_radius_m;
    for (double x = l.from_x_m;; x += p.cone_spacing_m) {
      const double xc = std::min(x, l.to_x_m);
      out.push_back({xc, l.centre_y_m + off});
      out.push_back({xc, l.centre_y_m - off});
      if (xc >= l.to_x_m - 1e-9) break;
    }
  }
  return out;
}

}  // namespace

std::vector<Iso3888Lane> iso3888_lanes(const Iso3888Params& p) {
  const double b = p.vehicle_width_m, s = p.start_x_m;
  return {{s, s + 15.0, 0.0, 1.1 * b + 0.25},
          {s + 45.0, s + 70.0, p.lane_offset_m, 1.2 * b + 0.25},
          {s + 95.0, s + 110.0, 0.0, 1.3 * b + 0.25}};
}

double lanes_kept(const Iso3888Params& p, std::span<const double> x_m, std::span<const double> y_m,
                  std::span<const double> yaw_rad) {
  const std::vector<Iso3888Lane> lanes = iso3888_lanes(p);
  std::vector<bool> left(lanes.size(), false), visited(lanes.size(), false);
  bool seen_end = false;
  for (std::size_t i = 0; i < x_m.size() && i < y_m.size() && i < yaw_rad.size(); ++i) {
    const auto poly = outline(p, x_m[i], y_m[i], yaw_rad[i]);
    for (std::size_t k = 0; k < lanes.size(); ++k) {
      double lo = 0.0, hi = 0.0;
      const Iso3888Lane& l = lanes[k];
      if (!y_range_in_strip(poly, l.from_x_m, l.to_x_m, lo, hi)) continue;
      visited[k] = true;
      if (hi > l.centre_y_m + 0.5 * l.width_m || lo < l.centre_y_m - 0.5 * l.width_m)
        left[k] = true;
    }
    double rear_x = poly[0].x;
    for (const Point& c : poly) rear_x = std::min(rear_x, c.x);
    seen_end = seen_end || rear_x > lanes.back().to_x_m;  // all of it past lane 5
  }
  if (!seen_end) return 0.0;  // the track was not driven through: no lane counts as kept
  double kept = 0.0;
  for (std::size_t k = 0; k < lanes.size(); ++k) kept += visited[k] && !left[k] ? 1.0 : 0.0;
  return kept;
}

double cones_hit(const Iso3888Params& p, std::span<const double> x_m, std::span<const double> y_m,
                 std::span<const double> yaw_rad) {
  const std::vector<Point> all = cones(p);
  std::vector<bool> hit(all.size(), false);
  const double reach = p.vehicle_length_m + p.vehicle_width_m;  // no cone further is near
  for (std::size_t i = 0; i < x_m.size() && i < y_m.size() && i < yaw_rad.size(); ++i) {
    for (std::size_t c = 0; c < all.size(); ++c) {
      if (hit[c] || std::abs(all[c].x - x_m[i]) > reach) continue;
      if (distance_to_outline(p, x_m[i], y_m[i], yaw_rad[i], all[c]) <= p.cone_radius_m)
        hit[c] = true;
    }
  }
  return static_cast<double>(std::count(hit.begin(), hit.end(), true));
}

}  // namespace rig::kpi
