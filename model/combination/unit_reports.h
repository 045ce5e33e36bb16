#pragma once
/// @file
/// The report of a combination starts with its units' own reports: unit 0 fills the whole
/// report (signals, unit 0, its wheels), every further unit contributes its unit entry.

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <numbers>
#include <vector>

#include "model/combination/joint.h"
#include "model/report.h"
#include "model/vehicle/vehicle_model.h"

namespace rig::model::combination {

/// Fills report.units[0..n) and unit_count from `units` (front to rear). No allocation: the
/// scratch report lives on the stack.
inline void fill_unit_reports(const std::vector<std::unique_ptr<vehicle::VehicleModel>>& units,
                              ModelReport& report) noexcept {
  units[0]->fill_report(report);
  const int n = std::min(static_cast<int>(units.size()), kMaxUnits);
  ModelReport unit_report;
  for (int k = 1; k < n; ++k) {
    units[static_cast<std::size_t>(k)]->fill_report(unit_report);
    report.units[static_cast<std::size_t>(k)] = unit_report.units[0];
  }
  report.unit_count = n;
}

/// |g|_inf of `joint` between the leading and the trailing unit at their current coordinates.
inline double joint_violation_m(const Joint& joint, const vehicle::VehicleModel& leading,
                                const vehicle::VehicleModel& trailing) noexcept {
  JointEvaluation e;
  joint.evaluate(leading.coordinates().head<6>(), trailing.coordinates().head<6>(), e);
  return e.g.head(joint.size()).lpNorm<Eigen::Infinity>();
}

/// Yaw of the leading unit minus yaw of the trailing unit, wrapped to [-pi, pi].
inline double articulation_rad(const vehicle::VehicleModel& leading,
                               const vehicle::VehicleModel& trailing) noexcept {
  return std::remainder(leading.coordinates()(3) - trailing.coordinates()(3), 2 * std::numbers::pi);
}

}  // namespace rig::model::combination
