#include "model/road/friction_zones.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace rig::model::road {

namespace {

constexpr double kOnEdge_m = 1e-9;  // a point this close to a polygon's edge is on it (inside)

void require(bool ok, const char* what) {
  if (!ok) throw std::invalid_argument(what);
}

void check(const FrictionZone& z) {
  require(std::isfinite(z.mu) && z.mu >= 0, "friction zone: mu must be finite and >= 0");
  if (z.is_polygon) {
    const FrictionPolygon& p = z.polygon;
    require(p.x_m.size() == p.y_m.size() && p.x_m.size() >= 3,
            "friction zone: a polygon needs at least 3 corners");
    for (std::size_t i = 0; i < p.x_m.size(); ++i)
      require(std::isfinite(p.x_m[i]) && std::isfinite(p.y_m[i]),
              "friction zone: a polygon corner is not finite");
    return;
  }
  const FrictionRectangle& r = z.rectangle;
  require(std::isfinite(r.x_m) && std::isfinite(r.y_m) && std::isfinite(r.heading_rad),
          "friction zone: the line's origin and heading must be finite");
  require(r.s_from_m < r.s_to_m && r.v_from_m < r.v_to_m,
          "friction zone: s_from_m < s_to_m and v_from_m < v_to_m");
}

/// Distance from (x, y) to the segment (ax, ay)-(bx, by) below kOnEdge_m.
bool on_segment(double x, double y, double ax, double ay, double bx, double by) noexcept {
  const double ex = bx - ax, ey = by - ay;
  const double len2 = ex * ex + ey * ey;
  const double u = len2 > 0 ? std::clamp(((x - ax) * ex + (y - ay) * ey) / len2, 0.0, 1.0) : 0.0;
  const double dx = x - (ax + u * ex), dy = y - (ay + u * ey);
  return dx * dx + dy * dy <= kOnEdge_m * kOnEdge_m;
}

}  // namespace

FrictionZones::FrictionZones(std::vector<FrictionZone> zones) {
  zones_.reserve(zones.size());
  for (FrictionZone& z : zones) {
    check(z);
    Prepared& p = zones_.emplace_back();
    p.zone = std::move(z);
    p.cos = std::cos(p.zone.rectangle.heading_rad);
    p.sin = std::sin(p.zone.rectangle.heading_rad);
    if (p.zone.is_polygon) {
      const auto& xs = p.zone.polygon.x_m;
      const auto& ys = p.zone.polygon.y_m;
      p.min_x = *std::min_element(xs.begin(), xs.end()) - kOnEdge_m;
      p.max_x = *std::max_element(xs.begin(), xs.end()) + kOnEdge_m;
      p.min_y = *std::min_element(ys.begin(), ys.end()) - kOnEdge_m;
      p.max_y = *std::max_element(ys.begin(), ys.end()) + kOnEdge_m;
    }
  }
}

double FrictionZones::mu(double x_m, double y_m, double base_mu) const noexcept {
  for (auto it = zones_.rbegin(); it != zones_.rend(); ++it) {  // the later zone wins
    if (inside(*it, x_m, y_m)) return it->zone.mu;
  }
  return base_mu;
}

bool FrictionZones::inside(const Prepared& z, double x_m, double y_m) noexcept {
  if (z.zone.is_polygon) {
    if (x_m < z.min_x || x_m > z.max_x || y_m < z.min_y || y_m > z.max_y) return false;
    return inside_polygon(z, x_m, y_m);
  }
  const FrictionRectangle& r = z.zone.rectangle;
  const double dx = x_m - r.x_m, dy = y_m - r.y_m;
  const double a = dx * z.cos + dy * z.sin;
  const double b = -dx * z.sin + dy * z.cos;
  return a >= r.s_from_m && a <= r.s_to_m && b >= r.v_from_m && b <= r.v_to_m;
}

bool FrictionZones::inside_polygon(const Prepared& z, double x_m, double y_m) noexcept {
  const auto& xs = z.zone.polygon.x_m;
  const auto& ys = z.zone.polygon.y_m;
  const std::size_t n = xs.size();
  bool in = false;
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    if (on_segment(x_m, y_m, xs[j], ys[j], xs[i], ys[i])) return true;
    // even-odd rule: count crossings of the ray from the point towards +x
    if ((ys[i] > y_m) != (ys[j] > y_m) &&
        x_m < xs[j] + (y_m - ys[j]) * (xs[i] - xs[j]) / (ys[i] - ys[j])) {
      in = !in;
    }
  }
  return in;
}

}  // namespace rig::model::road
