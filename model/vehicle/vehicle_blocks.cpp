#include "model/vehicle/vehicle_blocks.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "model/tire/vertical_tire_force.h"
#include "model/vehicle/steering/rack_in_the_loop.h"

namespace rig::model::vehicle {
namespace {

solver::ArrowheadPartition framework_partition(const VehicleParams& p) {
  solver::ArrowheadPartition partition;
  partition.body_size = 6;
  partition.leaf_sizes.assign(p.axles.size(), 2);      // two hub travels per axle
  partition.body_tail_size = p.frame.enabled ? 1 : 0;  // the frame's twist, in the body's corner
  return partition;
}

std::unique_ptr<HalfShafts> make_shafts(const VehicleParams& p, VehicleState& state,
                                        const VehicleWorkspace& work) {
  const DrivenWheels driven = driven_wheels(p);
  if (driven.count == 0 || !p.drivetrain.differentials.empty()) return nullptr;
  return std::make_unique<HalfShafts>(p.drivetrain, state, work, driven.wheel, driven.count);
}

std::unique_ptr<differential::DifferentialShafts> make_differentials(const VehicleParams& p,
                                                                     VehicleState& state,
                                                                     const VehicleWorkspace& work) {
  if (driven_wheels(p).count == 0 || p.drivetrain.differentials.empty()) return nullptr;
  return std::make_unique<differential::DifferentialShafts>(p, state, work);
}

template <typename A, typename B>
DrivenShafts* either(const std::unique_ptr<A>& a, const std::unique_ptr<B>& b) {
  if (a) return a.get();
  return b.get();
}

}  // namespace

DrivenWheels driven_wheels(const VehicleParams& p) noexcept {
  DrivenWheels d;
  for (int i = 0; i < 2 * static_cast<int>(p.axles.size()); ++i) {
    if (p.axles[static_cast<std::size_t>(i / 2)].driven)
      d.wheel[static_cast<std::size_t>(d.count++)] = i;
  }
  return d;
}

namespace {
/// What moves the rack, as [steering] system says.
std::unique_ptr<SteeringSystem> make_steering_system(const SteeringParams& p, VehicleState& state,
                                                     const VehicleInputs& inputs,
                                                     const VehicleWorkspace& work) {
  if (p.system == SteeringSystemKind::kSteerByWire)
    return std::make_unique<SteerByWire>(p, state, inputs, work);
  if (p.system == SteeringSystemKind::kRackInTheLoop)
    return std::make_unique<RackInTheLoop>(p, state, inputs);
  return std::make_unique<ColumnSteering>(p, state, inputs);
}
}  // namespace

VehicleBlocks::VehicleBlocks(const VehicleParams& p, VehicleState& state,
                             const VehicleInputs& inputs, VehicleWorkspace& work)
    : p_(p),
      state_(state),
      inputs_(inputs),
      work_(work),
      kinematics_(p),
      framework_(p, state, work),
      shafts_(make_shafts(p, state, work)),
      differentials_(make_differentials(p, state, work)),
      driven_shafts_(either(shafts_, differentials_)),
      drivetrain_(p.drivetrain, state, inputs, work, driven_shafts_),
      steering_system_(make_steering_system(p.steering, state, inputs, work)),
      wheel_stage_(p, state, inputs, work, driven_shafts_, drivetrain_),
      drivetrain_stepper_(drivetrain_),
      framework_stepper_(framework_, framework_partition(p)),
      sequence_(framework_stepper_) {
  // eq. (8) order: force elements (tires, half shafts), subsystems, framework last
  for (int i = 0; i < work.wheel_count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    tires_.push_back(std::make_unique<tire::TmeasyForceElement>(
        p.axles[k / 2].tire.tmeasy, work.wheels[k].tire, state.tire_deflection_m[k]));
    tire_steppers_.push_back(std::make_unique<solver::ForceElementStepper<2>>(*tires_.back()));
    sequence_.add_stage(*tire_steppers_.back());
  }
  if (shafts_) {
    shaft_stepper_ = std::make_unique<solver::ForceElementStepper<Eigen::Dynamic>>(*shafts_);
    sequence_.add_stage(*shaft_stepper_);
  }
  if (differentials_) {
    work_.differential_count = differentials_->tree().count;  // reported from the start
    shaft_stepper_ = std::make_unique<solver::ForceElementStepper<Eigen::Dynamic>>(*differentials_);
    sequence_.add_stage(*shaft_stepper_);
  }
  if (driven_shafts_ != nullptr) sequence_.add_stage(drivetrain_stepper_);
  // the steering block: the simple model's 2 DOF, or the enhanced model's system + knuckles
  if (p.steering.model == SteeringModel::kEnhanced) {
    enhanced_steering_ = std::make_unique<EnhancedSteering>(p, *steering_system_, state, work);
    steering_stage_ = std::make_unique<EnhancedSteeringStage>(*enhanced_steering_);
  } else {
    simple_steering_ = std::make_unique<SimpleSteering>(*steering_system_, state, work);
    steering_stage_ = std::make_unique<solver::MechanicalStepper<2>>(*simple_steering_);
  }
  if (std::any_of(p.axles.begin(), p.axles.end(), [](const AxleParams& a) { return a.steered; }))
    sequence_.add_stage(*steering_stage_);
  sequence_.add_stage(wheel_stage_);
  // rigid axles on leaf springs: the leaves replace the springs behind the axle's seam
  for (std::size_t a = 0; a < p.axles.size(); ++a) {
    if (!p.axles[a].has_leaf_spring) continue;
    if (leaf_axles_.size() >= static_cast<std::size_t>(kMaxLeafAxles))
      throw std::invalid_argument("vehicle: at most " + std::to_string(kMaxLeafAxles) +
                                  " axles on leaf springs");
    const int i = 2 * static_cast<int>(a);
    leaf_axles_.push_back(std::make_unique<LeafAxleSuspension>(
        static_cast<int>(a), p.axles[a], framework_.preload_n(i), framework_.preload_n(i + 1),
        state.leaf_axles[leaf_axles_.size()]));
    framework_.set_axle_suspension(static_cast<int>(a), *leaf_axles_.back());
  }
  build_leaf_balances(p, state);
  // free bodies (subsystems of eq. 2 at the chassis' y_V(k)); their mounts act on the framework
  if (!p.free_bodies.empty()) {
    free_bodies_ = std::make_unique<FreeBodies>(p, framework_.road(), state, work);
    framework_.attach_free_bodies(free_bodies_.get());
    for (int i = 0; i < free_bodies_->count(); ++i) sequence_.add_stage(free_bodies_->stage(i));
  }
}

void VehicleBlocks::build_leaf_balances(const VehicleParams& p, VehicleState& state) {
  const auto element = [this](int axle) -> LeafAxleSuspension& {
    for (const auto& l : leaf_axles_)
      if (l->rest_state().axle == axle) return *l;
    throw std::invalid_argument("vehicle: a leaf balance's axle " + std::to_string(axle + 1) +
                                " has no leaf springs");
  };
  for (const LoadSharingParams& g : p.load_sharing) {
    if (g.kind != LoadSharingKind::kLeafBalance) continue;
    if (leaf_balances_.size() >= static_cast<std::size_t>(kMaxLeafBalances))
      throw std::invalid_argument("vehicle: at most " + std::to_string(kMaxLeafBalances) +
                                  " leaf balance");
    LeafAxleSuspension& front = element(g.first_axle);
    LeafAxleSuspension& rear = element(g.first_axle + 1);
    leaf_balances_.push_back(std::make_unique<LeafBalance>(
        p, g.first_axle, g.pivot_x_m, front, rear, state.leaf_balances[leaf_balances_.size()]));
    front.join(*leaf_balances_.back(), 0);
    rear.join(*leaf_balances_.back(), 1);
    front.set_rest(front.slot());  // the rockers settled: the axles' rest is the group's
    rear.set_rest(rear.slot());
  }
}

void VehicleBlocks::update_contacts(double lookahead_s) noexcept {
  const auto& y = state_.framework_y;
  const auto& z = state_.framework_z;
  kinematics_.update(state_, work_);  // eq. (29) at y_V(k), before any contact is evaluated
  work_.lookahead_s = lookahead_s;
  const Mat3 rot = body_to_road(y(3), y(4), y(5));
  for (int i = 0; i < work_.wheel_count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    WheelWork& w = work_.wheels[k];
    const tire::TmeasyParams& t = p_.axles[k / 2].tire.tmeasy;
    const bool plane = framework_.road().is_plane();
    if (!plane) w.road = framework_.road_plane(rot, y, z, i, lookahead_s, w.probe_hints);
    const WheelContact c = framework_.contact(rot, y, z, i);
    w.load_n = tire::vertical_tire_force(t.vertical_stiffness_npm, t.vertical_damping_nspm,
                                         c.penetration_m, c.penetration_rate_mps)
                   .force_n;
    tire::TireContact& tc = w.tire;
    tc.kinematics = {c.vx_mps, c.vy_mps, state_.spin_radps[k],
                     tire::dynamic_rolling_radius(t.radius_unloaded_m, c.penetration_m)};
    w.road_friction = plane ? framework_.road().friction(i % 2 == 1) : w.road.mu;
    tc.characteristic = tire::characteristic_at(t, w.load_n, w.road_friction);
    const tire::TireSlip slip =
        tire::slip_of(tc.characteristic, tc.kinematics, t.velocity_floor_mps);
    tc.f_per_slip = slip.f_per_slip;
    tc.sliding_ratio = slip.sliding_ratio;
  }
  work_.carrier_speed_radps = drivetrain_.carrier_speed_radps();
  if (differentials_) differentials_->begin_step(inputs_);  // locks and clutch capacities
}

void VehicleBlocks::update_outputs() noexcept {
  const auto& y = state_.framework_y;
  const auto& z = state_.framework_z;
  const Mat3 rot = body_to_road(y(3), y(4), y(5));
  const bool plane = framework_.road().is_plane();
  for (int i = 0; i < work_.wheel_count; ++i) {
    WheelWork& w = work_.wheels[static_cast<std::size_t>(i)];
    const WheelContact c = framework_.contact(rot, y, z, i);
    w.out = framework_.wheel_forces(c, y, z, i);
    // the plane road is z = 0 of the road frame; else the local plane's height under the
    // wheel: at its static contact point, the probes' centre (on a 20 mm cleat at most 10 mm,
    // where the contact point on the tilted plane may lie higher than the cleat)
    w.road_z_m = plane ? 0.0 : w.road.point_m.z();
  }
  work_.torsion_bar_torque_nm =
      steering_system_->torsion_bar_torque_nm(state_.steering_y, state_.steering_z);
  work_.assist_torque_nm = steering_system_->assist_torque_nm(state_.steering_y, state_.steering_z);
  work_.engine_torque_nm =
      delivered_engine_torque_nm(p_.drivetrain, inputs_.throttle, drivetrain_.engine_speed_radps(),
                                 work_.engine_torque_cut_nm, inputs_.ignition_on);
  if (differentials_)
    differentials_->speeds(drivetrain_.carrier_speed_radps(), work_.differentials);
}

}  // namespace rig::model::vehicle
