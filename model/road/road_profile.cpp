#include "model/road/road_profile.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rig::model::road {

namespace {

/// The record in force at s: the last one starting at or before it (a later one at the same s
/// wins); none: 0.
OpenDrivePolynomial record_at(const std::vector<OpenDrivePolynomial>& records, double s_m) {
  const auto it =
      std::upper_bound(records.begin(), records.end(), s_m,
                       [](double s, const OpenDrivePolynomial& r) { return s < r.s_m; });
  if (it == records.begin()) return {s_m, 0, 0, 0, 0};
  return *(it - 1);
}

}  // namespace

RoadProfile::RoadProfile(const std::vector<OpenDrivePolynomial>& elevation,
                         const std::vector<OpenDrivePolynomial>& superelevation, double s_begin_m,
                         double s_end_m)
    : s_begin_(s_begin_m), s_end_(s_end_m) {
  std::vector<double> starts{-std::numeric_limits<double>::infinity()};
  for (const auto* records : {&elevation, &superelevation}) {
    for (const OpenDrivePolynomial& r : *records) starts.push_back(r.s_m);
  }
  std::sort(starts.begin(), starts.end());
  starts.erase(std::unique(starts.begin(), starts.end()), starts.end());
  for (const double s : starts) {
    Segment& g = segments_.emplace_back();
    g.s_m = s;
    g.elevation = record_at(elevation, s);
    g.superelevation = record_at(superelevation, s);
    const OpenDrivePolynomial& p = g.superelevation;
    g.constant_superelevation = p.b == 0 && p.c == 0 && p.d == 0;
    g.cos_superelevation = std::cos(p.a);
    g.tan_superelevation = std::tan(p.a);
  }
}

int RoadProfile::find(double s_m, int hint) const noexcept {
  const int n = static_cast<int>(segments_.size());
  auto covers = [&](int i) {
    return i >= 0 && i < n && segments_[i].s_m <= s_m && (i + 1 == n || s_m < segments_[i + 1].s_m);
  };
  for (const int i : {hint, hint + 1, hint - 1}) {
    if (covers(i)) return i;
  }
  const auto it = std::upper_bound(segments_.begin(), segments_.end(), s_m,
                                   [](double s, const Segment& g) { return s < g.s_m; });
  return std::max(0, static_cast<int>(it - segments_.begin()) - 1);
}

CrossSection RoadProfile::at(double s_m, int& segment) const noexcept {
  const bool held = !(s_m >= s_begin_ && s_m <= s_end_);
  s_m = std::clamp(s_m, s_begin_, s_end_);
  segment = find(s_m, segment);
  const Segment& g = segments_[static_cast<std::size_t>(segment)];
  CrossSection c;
  const OpenDrivePolynomial& e = g.elevation;
  const double de = s_m - e.s_m;
  c.elevation_m = e.a + de * (e.b + de * (e.c + de * e.d));
  c.elevation_slope = held ? 0.0 : e.b + de * (2.0 * e.c + de * 3.0 * e.d);
  const OpenDrivePolynomial& p = g.superelevation;
  if (g.constant_superelevation) {
    c.superelevation_rad = p.a;
    c.tan_superelevation = g.tan_superelevation;
    c.cos_superelevation = g.cos_superelevation;
    return c;
  }
  const double dp = s_m - p.s_m;
  c.superelevation_rad = p.a + dp * (p.b + dp * (p.c + dp * p.d));
  c.superelevation_rate = held ? 0.0 : p.b + dp * (2.0 * p.c + dp * 3.0 * p.d);
  c.cos_superelevation = std::cos(c.superelevation_rad);
  c.tan_superelevation = std::sin(c.superelevation_rad) / c.cos_superelevation;
  return c;
}

}  // namespace rig::model::road
