#pragma once
/// @file
/// A profile along s made of OpenDRIVE cubic records (<elevation>, <superelevation>): each
/// a + b ds + c ds^2 + d ds^3 with ds = s - s_record, valid until the next record starts
/// (ASAM OpenDRIVE 1.7 sec. 10.5). Before the first record the profile is 0 (OpenDRIVE's
/// default); outside [s_begin, s_end] (the reference line's extent) the value at the nearer end
/// is held with slope 0 (model/road/DESIGN.md: off the ends the last elevation is held).

#include <algorithm>
#include <utility>
#include <vector>

#include "model/road/opendrive_road.h"

namespace rig::model::road {

struct ProfileValue {
  double value = 0;
  double slope = 0;  ///< d value / ds
};

class PiecewiseCubic {
 public:
  PiecewiseCubic() = default;
  PiecewiseCubic(std::vector<OpenDrivePolynomial> records, double s_begin_m, double s_end_m)
      : records_(std::move(records)), s_begin_(s_begin_m), s_end_(s_end_m) {}

  [[nodiscard]] ProfileValue at(double s_m) const noexcept {
    bool held = false;
    if (s_m < s_begin_) {
      s_m = s_begin_;
      held = true;
    } else if (s_m > s_end_) {
      s_m = s_end_;
      held = true;
    }
    const auto it =
        std::upper_bound(records_.begin(), records_.end(), s_m,
                         [](double s, const OpenDrivePolynomial& r) { return s < r.s_m; });
    if (it == records_.begin()) return {};
    const OpenDrivePolynomial& r = *(it - 1);
    const double ds = s_m - r.s_m;
    const double value = r.a + ds * (r.b + ds * (r.c + ds * r.d));
    const double slope = r.b + ds * (2.0 * r.c + ds * 3.0 * r.d);
    return {value, held ? 0.0 : slope};
  }

  [[nodiscard]] bool empty() const noexcept { return records_.empty(); }

 private:
  std::vector<OpenDrivePolynomial> records_;
  double s_begin_ = 0;
  double s_end_ = 0;
};

}  // namespace rig::model::road
