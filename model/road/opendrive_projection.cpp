#include "model/road/opendrive_projection.h"

#include "model/road/small_angle.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

namespace rig::model::road {

namespace {

constexpr double kExtension_m = 100.0;  // sampled length of each straight extension
constexpr double kReachCap_m = 100.0;   // beyond |t| = 100 m every query searches globally
constexpr double kNewtonMaxStep_m = 5.0;
constexpr int kNewtonIterations = 12;
constexpr double kConverged_m = 1e-10;        // the foot's error left by the last step
constexpr double kCurvatureFloor_1pm = 0.05;  // Newton's error bound where the rate is unknown
constexpr std::size_t kMaxSamples = 1'000'000;

double squared(double v) noexcept { return v * v; }

}  // namespace

ReferenceLineProjection::ReferenceLineProjection(const OpenDriveReferenceLine& line) : line_(line) {
  const double k_max = line.max_curvature_1pm();
  step_ = std::clamp(k_max > 0 ? 0.125 / k_max : 1.0, 0.01, 1.0);
  const double s0 = line.start_s_m() - kExtension_m;
  const double length = line.end_s_m() - line.start_s_m() + 2.0 * kExtension_m;
  const double count = std::ceil(length / step_) + 1.0;
  if (count > static_cast<double>(kMaxSamples))
    throw std::invalid_argument("the reference line is too long for its curvature: " +
                                std::to_string(static_cast<long long>(count)) +
                                " projection samples of at most " + std::to_string(kMaxSamples) +
                                " (one every " + std::to_string(step_) + " m)");
  samples_.reserve(static_cast<std::size_t>(count));
  int element = -1;
  for (std::size_t k = 0; k < static_cast<std::size_t>(count); ++k) {
    const double s = std::min(s0 + static_cast<double>(k) * step_, s0 + length);
    const ReferencePose p = line.pose(s, element);
    samples_.push_back({s, p.x_m, p.y_m});
  }
  build_grid();
  estimate_reach(k_max);
}

void ReferenceLineProjection::build_grid() {
  double x1 = samples_.front().x, y1 = samples_.front().y;
  x0_ = x1;
  y0_ = y1;
  for (const Sample& p : samples_) {
    x0_ = std::min(x0_, p.x);
    y0_ = std::min(y0_, p.y);
    x1 = std::max(x1, p.x);
    y1 = std::max(y1, p.y);
  }
  const double n = static_cast<double>(samples_.size());
  // about one sample per cell on average (a line fills few cells of its box)
  cell_m_ = std::max({step_, std::sqrt((x1 - x0_) * (y1 - y0_) / n), 1e-3});
  while ((std::floor((x1 - x0_) / cell_m_) + 1) * (std::floor((y1 - y0_) / cell_m_) + 1) >
         4.0 * n + 16.0) {
    cell_m_ *= 1.5;
  }
  nx_ = static_cast<int>(std::floor((x1 - x0_) / cell_m_)) + 1;
  ny_ = static_cast<int>(std::floor((y1 - y0_) / cell_m_)) + 1;
  const auto cells = static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_);
  cell_start_.assign(cells + 1, 0);
  for (const Sample& p : samples_) ++cell_start_[cell_y(p.y) * nx_ + cell_x(p.x) + 1];
  for (std::size_t c = 0; c < cells; ++c) cell_start_[c + 1] += cell_start_[c];
  cell_samples_.assign(samples_.size(), 0);
  std::vector<int> fill(cell_start_.begin(), cell_start_.end() - 1);
  for (std::size_t k = 0; k < samples_.size(); ++k) {
    const Sample& p = samples_[k];
    cell_samples_[static_cast<std::size_t>(fill[cell_y(p.y) * nx_ + cell_x(p.x)]++)] =
        static_cast<int>(k);
  }
}

int ReferenceLineProjection::cell_x(double x) const noexcept {
  return std::clamp(static_cast<int>(std::floor((x - x0_) / cell_m_)), 0, nx_ - 1);
}
int ReferenceLineProjection::cell_y(double y) const noexcept {
  return std::clamp(static_cast<int>(std::floor((y - y0_) / cell_m_)), 0, ny_ - 1);
}

void ReferenceLineProjection::estimate_reach(double max_curvature_1pm) {
  // 0.9: the sampled curvature may miss a poly3's peak between samples
  const double r0 =
      std::min(max_curvature_1pm > 0 ? 0.9 / max_curvature_1pm : kReachCap_m, kReachCap_m);
  const double apart_m = std::numbers::pi * r0;
  // Only pairs closer than 2 r0 can bring the reach below r0: a grid of 2 r0 cells, each sample
  // against the 3 x 3 cells around its own (construction only, so a hash map will do).
  const double cell = 2.0 * r0;
  auto key = [cell](double x, double y) {
    return std::pair<long long, long long>{static_cast<long long>(std::floor(x / cell)),
                                           static_cast<long long>(std::floor(y / cell))};
  };
  std::map<std::pair<long long, long long>, std::vector<std::size_t>> cells;
  for (std::size_t k = 0; k < samples_.size(); ++k)
    cells[key(samples_[k].x, samples_[k].y)].push_back(k);
  double closest = std::numeric_limits<double>::infinity();
  for (const Sample& p : samples_) {
    const auto [ci, cj] = key(p.x, p.y);
    for (long long j = cj - 1; j <= cj + 1; ++j) {
      for (long long i = ci - 1; i <= ci + 1; ++i) {
        const auto it = cells.find({i, j});
        if (it == cells.end()) continue;
        for (const std::size_t k : it->second) {
          const Sample& q = samples_[k];
          if (std::abs(q.s - p.s) < apart_m) continue;
          closest = std::min(closest, squared(q.x - p.x) + squared(q.y - p.y));
        }
      }
    }
  }
  // a sampled distance overstates the true one by at most one sample step
  reach_ = std::max(0.0, std::min(r0, 0.5 * std::sqrt(closest) - step_));
}

Station ReferenceLineProjection::project(double x_m, double y_m, SurfaceHint& hint) const noexcept {
  Station out;
  if (!std::isfinite(x_m) || !std::isfinite(y_m)) return out;
  int element = hint.i - 1;
  if (hint.i >= 0 && std::isfinite(hint.s_m) && newton(x_m, y_m, hint.s_m, element, out) &&
      std::abs(out.t_m) < reach_) {
    hint.i = element + 1;
    hint.s_m = out.s_m;
    return out;
  }
  out = global(x_m, y_m, element);
  hint.i = element + 1;
  hint.s_m = out.s_m;
  return out;
}

namespace {

/// atan(x) / x, exact near 0 (the osculating circle's foot).
double atan_ratio(double x) noexcept {
  if (std::abs(x) > 1e-3) return std::atan(x) / x;
  const double x2 = x * x;
  return 1.0 - x2 / 3.0 + x2 * x2 / 5.0;
}

/// The pose moved by arc length `l` along its osculating circle (exact on lines and arcs).
ReferencePose along_circle(const ReferencePose& p, double l) noexcept {
  const double turn = p.curvature_1pm * l;
  const CosSin h = cos_sin(0.5 * turn);
  const double chord = std::abs(turn) > 1e-4 ? 2.0 * h.sin / p.curvature_1pm : l;
  const double cm = p.cos_hdg * h.cos - p.sin_hdg * h.sin;
  const double sm = p.sin_hdg * h.cos + p.cos_hdg * h.sin;
  ReferencePose q = p;
  q.x_m += chord * cm;
  q.y_m += chord * sm;
  q.hdg_rad += turn;
  q.cos_hdg = cm * h.cos - sm * h.sin;
  q.sin_hdg = sm * h.cos + cm * h.sin;
  q.curvature_1pm += p.curvature_rate * l;
  return q;
}

/// The circle's foot corrected onto the clothoid: there the tangent is turned by
/// eps = rate l^2 / 2 and the line lies rate l^3 / 6 further along the normal than the circle;
/// the foot moves on by the along-distance this leaves (to first order: its error is of
/// second order in eps).
void onto_clothoid(double x, double y, double l, ReferencePose& q, double& s) noexcept {
  const double eps = 0.5 * q.curvature_rate * l * l;
  const double off = q.curvature_rate * l * l * l / 6.0;
  q.x_m -= off * q.sin_hdg;
  q.y_m += off * q.cos_hdg;
  q.hdg_rad += eps;
  const double c = q.cos_hdg - eps * q.sin_hdg, sn = q.sin_hdg + eps * q.cos_hdg;
  const double r = 1.0 / std::sqrt(c * c + sn * sn);
  q.cos_hdg = c * r;
  q.sin_hdg = sn * r;
  const double dx = x - q.x_m, dy = y - q.y_m;
  const double t = -dx * q.sin_hdg + dy * q.cos_hdg;
  const double d = (dx * q.cos_hdg + dy * q.sin_hdg) / (1.0 - t * q.curvature_1pm);
  q.x_m += d * q.cos_hdg;
  q.y_m += d * q.sin_hdg;
  q.hdg_rad += d * q.curvature_1pm;
  s += d;
}

}  // namespace

bool ReferenceLineProjection::newton(double x, double y, double s, int& element,
                                     Station& out) const noexcept {
  for (int it = 0; it < kNewtonIterations; ++it) {
    const ReferencePose p = line_.pose(s, element);
    const double dx = x - p.x_m, dy = y - p.y_m;
    const double along = dx * p.cos_hdg + dy * p.sin_hdg;
    const double t = -dx * p.sin_hdg + dy * p.cos_hdg;
    const double bend = 1.0 - t * p.curvature_1pm;
    if (!(bend > 0.1)) return false;  // at or beyond the centre of curvature
    // The foot on the osculating circle: arc length atan(kappa a / (1 - kappa t)) / kappa. Exact
    // on lines and arcs; on a clothoid the tangent there is off by rate l^2 / 2, the foot by
    // about |t| rate l^2 / 2; elsewhere Newton's error, about kappa step^2.
    const double l = along / bend * atan_ratio(p.curvature_1pm * along / bend);
    const double step = l / p.speed;
    const double rate = std::abs(p.curvature_rate);
    // what the step leaves: 0 on lines and arcs; on a clothoid after its correction about
    // (|t| rate l^2)^2; elsewhere Newton's next error, about kappa step^2
    const double clothoid = (std::abs(t) + std::abs(l)) * rate * l * l;
    const double left =
        rate == 0 ? 0.0
                  : std::min(clothoid < 1e-4 ? clothoid * clothoid : clothoid,
                             step * step * (std::abs(p.curvature_1pm) + kCurvatureFloor_1pm));
    if (left < kConverged_m && line_.in_element(s + step, element)) {
      out.s_m = s + step;
      out.pose = p;
      if (p.speed == 1.0) {
        out.pose = along_circle(p, l);
        if (rate > 0 && std::isfinite(rate)) onto_clothoid(x, y, l, out.pose, out.s_m);
      } else {  // a paramPoly3, the step tiny here: first order along the tangent
        out.pose.x_m += l * p.cos_hdg;
        out.pose.y_m += l * p.sin_hdg;
      }
      out.t_m = -(x - out.pose.x_m) * out.pose.sin_hdg + (y - out.pose.y_m) * out.pose.cos_hdg;
      out.found = true;
      return true;
    }
    s += std::clamp(step, -kNewtonMaxStep_m, kNewtonMaxStep_m);
  }
  return false;
}

Station ReferenceLineProjection::global(double x, double y, int& element) const noexcept {
  const int k = nearest_sample(x, y);
  Station out;
  element = -2;  // no element hint: found by the sample's station
  if (newton(x, y, samples_[static_cast<std::size_t>(k)].s, element, out)) return out;
  const std::size_t lo = static_cast<std::size_t>(std::max(k - 1, 0));
  const std::size_t hi = std::min(static_cast<std::size_t>(k) + 1, samples_.size() - 1);
  return golden(x, y, samples_[lo].s, samples_[hi].s, element);
}

Station ReferenceLineProjection::golden(double x, double y, double s_lo, double s_hi,
                                        int& element) const noexcept {
  auto distance2 = [&](double s) {
    const ReferencePose p = line_.pose(s, element);
    return squared(x - p.x_m) + squared(y - p.y_m);
  };
  const double r = 0.5 * (std::sqrt(5.0) - 1.0);
  double a = s_lo, b = s_hi;
  double c = b - r * (b - a), d = a + r * (b - a);
  double fc = distance2(c), fd = distance2(d);
  for (int it = 0; it < 60 && b - a > 1e-10; ++it) {
    if (fc < fd) {
      b = d, d = c, fd = fc;
      c = b - r * (b - a), fc = distance2(c);
    } else {
      a = c, c = d, fc = fd;
      d = a + r * (b - a), fd = distance2(d);
    }
  }
  Station out;
  out.s_m = 0.5 * (a + b);
  out.pose = line_.pose(out.s_m, element);
  out.t_m = -(x - out.pose.x_m) * out.pose.sin_hdg + (y - out.pose.y_m) * out.pose.cos_hdg;
  out.found = true;
  return out;
}

int ReferenceLineProjection::nearest_sample(double x, double y) const noexcept {
  const double fx = std::floor((x - x0_) / cell_m_), fy = std::floor((y - y0_) / cell_m_);
  if (fx < 0 || fy < 0 || fx >= nx_ || fy >= ny_) return nearest_linear(x, y);
  const int ci = static_cast<int>(fx), cj = static_cast<int>(fy);
  double best = std::numeric_limits<double>::infinity();
  int best_k = 0;
  const int max_ring = std::max(nx_, ny_);
  for (int r = 0; r <= max_ring; ++r) {
    // every sample of ring r lies at least (r - 1) cells from the point
    if (r > 0 && best <= squared((r - 1) * cell_m_)) break;
    for (int j = cj - r; j <= cj + r; ++j) {
      if (j < 0 || j >= ny_) continue;
      const bool edge_row = j == cj - r || j == cj + r;
      for (int i = ci - r; i <= ci + r; i += edge_row ? 1 : 2 * std::max(r, 1)) {
        if (i < 0 || i >= nx_) continue;
        const int c = j * nx_ + i;
        for (int n = cell_start_[c]; n < cell_start_[c + 1]; ++n) {
          const Sample& q = samples_[static_cast<std::size_t>(cell_samples_[n])];
          const double d = squared(q.x - x) + squared(q.y - y);
          if (d < best) best = d, best_k = cell_samples_[n];
        }
      }
    }
  }
  return best_k;
}

int ReferenceLineProjection::nearest_linear(double x, double y) const noexcept {
  double best = std::numeric_limits<double>::infinity();
  int best_k = 0;
  for (std::size_t k = 0; k < samples_.size(); ++k) {
    const double d = squared(samples_[k].x - x) + squared(samples_[k].y - y);
    if (d < best) best = d, best_k = static_cast<int>(k);
  }
  return best_k;
}

}  // namespace rig::model::road
