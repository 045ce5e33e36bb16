#pragma once
/// @file
/// The vehicle's free bodies (`[[free_body]]`): one block and stepper each (FreeBody: cab,
/// engine; Seat), built once; the stages of the sequential step (eq. 8) before the framework;
/// the mounts' reactions and their partials on the chassis for the framework; the outputs
/// (relative motion, on-stop flag) and the placement of the bodies with the chassis.

#include <memory>
#include <vector>

#include "model/report.h"
#include "model/solver/mechanical_stepper.h"
#include "model/vehicle/free_body/free_body.h"
#include "model/vehicle/free_body/seat.h"

namespace rig::model::vehicle {

class FreeBodies {
 public:
  /// One block per p.free_bodies entry (slot = its index; allocates). p, road, state and work
  /// must outlive it.
  FreeBodies(const VehicleParams& p, const road::Road& road, VehicleState& state,
             const VehicleWorkspace& work);
  FreeBodies(const FreeBodies&) = delete;
  FreeBodies& operator=(const FreeBodies&) = delete;

  [[nodiscard]] int count() const noexcept { return static_cast<int>(stages_.size()); }
  /// The stepper of body i (a stage of the sequence).
  [[nodiscard]] solver::Stage& stage(int i) noexcept {
    return *stages_[static_cast<std::size_t>(i)];
  }
  /// Body i's 6-DOF block (null for a seat) and seat block (null otherwise).
  [[nodiscard]] FreeBody* body(int i) noexcept {
    return bodies_[static_cast<std::size_t>(i)].get();
  }
  [[nodiscard]] Seat* seat(int i) noexcept { return seats_[static_cast<std::size_t>(i)].get(); }

  /// Adds every body's reaction to the chassis' generalized forces (force and moment about the
  /// CG, chassis axes) at the chassis coordinates y, speeds z (the framework's first six).
  void add_chassis_load(const RigidPose& chassis, Eigen::Ref<Vec6> q) const noexcept;
  /// Adds their partials (speed space for y: the caller multiplies by K).
  void add_chassis_jacobians(const RigidPose& chassis, Mat6& dq_ds, Mat6& dq_dz) const noexcept;

 private:
  std::unique_ptr<PredictedChassis> chassis_;  ///< shared by the bodies (a stable address)
  std::vector<std::unique_ptr<FreeBody>> bodies_;
  std::vector<std::unique_ptr<Seat>> seats_;
  std::vector<std::unique_ptr<solver::Stage>> stages_;
};

/// The largest |d| - clearance of body i's mounts at the state (> 0: on its stops). Pure; for
/// the report and the fault check. `mounts`: the body's mounts made once (make_mount), or null
/// to make them here.
[[nodiscard]] double free_body_beyond_stop_m(const FreeBodyParams& b, int slot,
                                             const VehicleState& s,
                                             const Mount* mounts = nullptr) noexcept;
/// Body i's motion relative to the chassis (the seat: its deflection and rate in z only).
[[nodiscard]] RelativeMotion free_body_motion(const FreeBodyParams& b, int slot,
                                              const VehicleState& s) noexcept;

/// Every body at its design position relative to the chassis state, moving with it.
void place_free_bodies(const VehicleParams& p, VehicleState& s) noexcept;
/// Every body keeps its motion relative to the chassis while the chassis' coordinates and
/// speeds go from (old_y, old_z) to the state's (settling, a forward speed set).
void carry_free_bodies(const VehicleParams& p, const Vec6& old_y, const Vec6& old_z,
                       VehicleState& s) noexcept;

/// The report's free-body entries of the leading unit (ModelReport::bodies, body_count).
void fill_free_body_report(const VehicleParams& p, const VehicleState& s,
                           ModelReport& report) noexcept;

}  // namespace rig::model::vehicle
