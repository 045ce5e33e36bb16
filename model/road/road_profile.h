#pragma once
/// @file
/// An OpenDRIVE road's cross section along s: the elevation and superelevation cubics
/// (<elevation>, <superelevation>: each a + b ds + c ds^2 + d ds^3 with ds = s - s_record, valid
/// until the next record; ASAM OpenDRIVE 1.7 sec. 10.5) merged into segments, so that one
/// station finds both with one lookup that starts from the caller's segment (a wheel rolling on
/// stays in its segment or steps to the next). Before a profile's first record it is 0
/// (OpenDRIVE's default); outside [s_begin, s_end] (the reference line's extent) the values at
/// the nearer end are held with slope 0 (model/road/DESIGN.md). A segment whose superelevation is
/// constant keeps its tangent and cosine, so that the common level or constantly banked road
/// costs no trigonometric call. Constant after construction; at() noexcept, allocation-free.

#include <vector>

#include "model/road/opendrive_road.h"

namespace rig::model::road {

struct CrossSection {
  double elevation_m = 0;
  double elevation_slope = 0;  ///< d elevation / ds
  double superelevation_rad = 0;
  double superelevation_rate = 0;  ///< d superelevation / ds [rad/m]
  double tan_superelevation = 0;
  double cos_superelevation = 1;
};

class RoadProfile {
 public:
  RoadProfile() = default;
  RoadProfile(const std::vector<OpenDrivePolynomial>& elevation,
              const std::vector<OpenDrivePolynomial>& superelevation, double s_begin_m,
              double s_end_m);

  /// The cross section at s [m]; `segment` is the caller's hint (any value works; updated).
  [[nodiscard]] CrossSection at(double s_m, int& segment) const noexcept;

 private:
  struct Segment {
    double s_m = 0;                 ///< where it starts (the first: -infinity)
    OpenDrivePolynomial elevation;  ///< all zero before the first record
    OpenDrivePolynomial superelevation;
    bool constant_superelevation = true;
    double tan_superelevation = 0, cos_superelevation = 1;
  };
  [[nodiscard]] int find(double s_m, int hint) const noexcept;

  std::vector<Segment> segments_;
  double s_begin_ = 0, s_end_ = 0;
};

}  // namespace rig::model::road
