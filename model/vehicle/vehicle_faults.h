#pragma once
/// @file
/// Vehicle faults (issue 12.5): a state that is no longer a vehicle on a road - rolled or
/// pitched beyond a limit, a body point below the road, a speed or rate beyond physical bounds,
/// or not finite at all. Detection only, and pure: FaultCheck is built once from the parameters
/// and checks a state after every step (VehicleModel::finish_step, before any output is
/// written), without allocation. What to do about a fault is the caller's decision.

#include <array>
#include <vector>

#include "model/road/road.h"
#include "model/stepped_model.h"
#include "model/vehicle/free_body/mount.h"
#include "model/vehicle/vehicle_state.h"

namespace rig::model::vehicle {

/// The default body points: the 8 corners of a box, x from the rearmost to the frontmost axle
/// (to the support point of a supported unit where that lies further out), y at +-half the
/// widest track, z from the lowest unloaded wheel-centre height (the body's floor never goes
/// lower without a tire going through the road) to twice the CG height (the roof). Body axes,
/// from the CG.
[[nodiscard]] std::vector<std::array<double, 3>> default_body_points(const VehicleParams& p);

class FaultCheck {
 public:
  /// The limits of p.fault_limits, the body points of p.chassis (or the default box), the
  /// road of p.road. Throws std::invalid_argument on more than kMaxBodyPoints points or a
  /// limit that is not > 0.
  explicit FaultCheck(const VehicleParams& p);

  /// The first fault of `s`, in this order: not finite, CG speed, angular rate, wheel spins,
  /// roll, pitch, body points, free bodies through their stops (kind kNone if there is none).
  /// `time_s` is stamped on it.
  [[nodiscard]] ModelFault check(const VehicleState& s, double time_s) const noexcept;

  [[nodiscard]] int body_point_count() const noexcept { return point_count_; }
  [[nodiscard]] const Vec3& body_point(int i) const noexcept {
    return points_[static_cast<std::size_t>(i)];
  }
  /// The spin limit of wheel i [rad/s]: the speed limit over its unloaded radius.
  [[nodiscard]] double spin_limit_radps(int i) const noexcept {
    return spin_limit_radps_[static_cast<std::size_t>(i)];
  }

 private:
  [[nodiscard]] ModelFault check_body_points(const Eigen::VectorXd& y,
                                             double time_s) const noexcept;

  [[nodiscard]] ModelFault check_free_bodies(const VehicleState& s, double time_s) const noexcept;

  FaultLimits limits_;
  std::vector<FreeBodyParams> free_bodies_;
  std::vector<std::array<Mount, kMaxMounts>> free_body_mounts_;  ///< made once
  road::Road road_;
  /// Each body point's last cell on the road's surface: a cache that only speeds the query up
  /// (model/road/surface.h: any hint gives the same answer), hence mutable in the const check.
  mutable std::array<road::SurfaceHint, kMaxBodyPoints> hints_{};
  int wheel_count_ = 0;
  std::array<double, kMaxWheels> spin_limit_radps_{};
  int point_count_ = 0;
  std::array<Vec3, kMaxBodyPoints> points_{};
};

}  // namespace rig::model::vehicle
