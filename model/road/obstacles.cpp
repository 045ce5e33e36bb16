#include "model/road/obstacles.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace rig::model::road {

namespace {

void require(bool ok, const char* what) {
  if (!ok) throw std::invalid_argument(what);
}

void check(const ObstacleParams& p) {
  for (const double v : {p.x_m, p.y_m, p.heading_rad, p.s_m, p.length_m, p.height_m, p.rise_m,
                         p.fall_m, p.wavelength_m}) {
    require(std::isfinite(v), "obstacle: a number is not finite");
  }
  require(p.length_m > 0, "obstacle: length_m must be > 0");
  require(p.width_m > 0 && !std::isnan(p.width_m), "obstacle: width_m must be > 0");
  require(p.height_m != 0, "obstacle: height_m must not be 0");
  switch (p.kind) {
    case ObstacleKind::kCleat:
      require(p.height_m > 0, "cleat: height_m must be > 0 (a hole is a pothole)");
      break;
    case ObstacleKind::kPothole:
      require(p.height_m < 0, "pothole: height_m must be < 0 (its depth)");
      break;
    case ObstacleKind::kRamp:
      require(p.rise_m >= 0 && p.fall_m >= 0 && p.rise_m + p.fall_m <= p.length_m,
              "ramp: rise_m and fall_m must be >= 0 with rise_m + fall_m <= length_m");
      break;
    case ObstacleKind::kBump:
      break;
    case ObstacleKind::kSine: {
      require(p.wavelength_m > 0, "sine: wavelength_m must be > 0");
      const double waves = p.length_m / p.wavelength_m;
      require(std::abs(waves - std::round(waves)) <= 1e-9 * waves,
              "sine: length_m must be a whole number of wavelengths");
      break;
    }
  }
}

}  // namespace

Obstacle::Obstacle(const ObstacleParams& params)
    : p_(params), cos_(std::cos(params.heading_rad)), sin_(std::sin(params.heading_rad)) {
  check(p_);
}

SurfaceHeight Obstacle::profile(double r_m) const noexcept {
  const double h = p_.height_m;
  const double two_pi = 2.0 * std::numbers::pi;
  switch (p_.kind) {
    case ObstacleKind::kCleat:
    case ObstacleKind::kPothole:
      return {h, 0, 0};
    case ObstacleKind::kRamp:
      if (r_m < p_.rise_m) return {h * r_m / p_.rise_m, h / p_.rise_m, 0};
      if (r_m > p_.length_m - p_.fall_m)
        return {h * (p_.length_m - r_m) / p_.fall_m, -h / p_.fall_m, 0};
      return {h, 0, 0};
    case ObstacleKind::kBump:
    case ObstacleKind::kSine: {
      const double wave = p_.kind == ObstacleKind::kBump ? p_.length_m : p_.wavelength_m;
      const double k = two_pi / wave;
      return {0.5 * h * (1.0 - std::cos(k * r_m)), 0.5 * h * k * std::sin(k * r_m), 0};
    }
  }
  return {};
}

SurfaceHeight Obstacle::height(double x_m, double y_m) const noexcept {
  const double dx = x_m - p_.x_m, dy = y_m - p_.y_m;
  const double r = dx * cos_ + dy * sin_ - p_.s_m;
  const double b = -dx * sin_ + dy * cos_;
  if (!(r >= 0 && r <= p_.length_m && std::abs(b) <= 0.5 * p_.width_m)) return {};
  const SurfaceHeight along = profile(r);  // dz_dx holds dz/da here
  return {along.z_m, along.dz_dx * cos_, along.dz_dx * sin_};
}

SurfaceHeight Obstacles::height(double x_m, double y_m, SurfaceHint& /*hint*/) const noexcept {
  SurfaceHeight sum;
  for (const Obstacle& o : obstacles_) {
    const SurfaceHeight h = o.height(x_m, y_m);
    sum.z_m += h.z_m;
    sum.dz_dx += h.dz_dx;
    sum.dz_dy += h.dz_dy;
  }
  return sum;
}

}  // namespace rig::model::road
