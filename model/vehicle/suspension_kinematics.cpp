#include "model/vehicle/suspension_kinematics.h"

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>

namespace rig::model::vehicle {
namespace {

using kinematics::Grid2D;
using kinematics::KinematicTable;
using kinematics::WheelKinematics;

/// Node values of a table of the mirror wheel: f_R(z_k, u_l) = sign f_L(z_k, -u_l); on a grid
/// symmetric about u = 0, -u_l is the node u_(n-1-l).
std::vector<double> mirrored(const Grid2D& g, const std::vector<double>& left, double sign) {
  std::vector<double> right(left.size());
  for (int k = 0; k < g.z_count; ++k) {
    for (int l = 0; l < g.u_count; ++l) {
      right[static_cast<std::size_t>(k * g.u_count + l)] =
          sign * left[static_cast<std::size_t>(k * g.u_count + (g.u_count - 1 - l))];
    }
  }
  return right;
}

/// Left and right wheel of one axle from the left wheel's five tables.
std::pair<WheelKinematics, WheelKinematics> axle_pair(
    const Grid2D& g, std::vector<double> x, std::vector<double> y, std::vector<double> alpha,
    std::vector<double> beta, std::vector<double> gamma, kinematics::Interpolation method) {
  const auto n = static_cast<std::size_t>(g.z_count) * static_cast<std::size_t>(g.u_count);
  if (g.z_count < 1 || g.u_count < 1 || x.size() != n || y.size() != n || alpha.size() != n ||
      beta.size() != n || gamma.size() != n)
    throw std::invalid_argument("each of the five tables needs z_count x u_count values");
  WheelKinematics right(
      KinematicTable(g, mirrored(g, x, 1.0)), KinematicTable(g, mirrored(g, y, -1.0)),
      KinematicTable(g, mirrored(g, alpha, -1.0)), KinematicTable(g, mirrored(g, beta, 1.0)),
      KinematicTable(g, mirrored(g, gamma, -1.0)), method);
  WheelKinematics left(KinematicTable(g, std::move(x)), KinematicTable(g, std::move(y)),
                       KinematicTable(g, std::move(alpha)), KinematicTable(g, std::move(beta)),
                       KinematicTable(g, std::move(gamma)), method);
  return {std::move(left), std::move(right)};
}

bool nonzero(const KinematicTable& t) {
  const Grid2D& g = t.grid();
  for (int k = 0; k < g.z_count; ++k) {
    for (int l = 0; l < g.u_count; ++l) {
      if (t.node(k, l) != 0.0) return true;
    }
  }
  return false;
}

}  // namespace

kinematics::SuspensionGeometry left_wheel_geometry(const AxleParams& a, const SteeringParams& s) {
  const AxleKinematicsParams& k = a.kinematics;
  kinematics::SuspensionGeometry g;
  g.x0_m = 0;  // offsets from the design position (the framework's mount point)
  g.y0_m = 0;
  g.x_per_z = k.x_per_travel;
  g.track_per_z = k.track_per_travel;
  g.track_per_z2 = k.track_per_travel2_per_m;
  g.camber0_rad = k.camber_rad;
  g.camber_per_z = k.camber_per_travel_radpm;
  g.beta_per_z = 0;
  g.toe0_rad = k.toe_rad;
  g.bump_steer_per_z = k.bump_steer_radpm;
  g.steering_arm_m = a.steered ? s.steering_arm_m : 0.0;
  g.steer_y_per_u = 0;
  return g;
}

kinematics::Grid2D generated_grid(const AxleParams& a, const SteeringParams& s) {
  Grid2D g;
  g.z_step = 0.01;
  g.z_min = -std::ceil((a.rebound_stop_travel_m + 0.02) / g.z_step) * g.z_step;
  const double z_max = std::ceil((a.bump_stop_travel_m + 0.02) / g.z_step) * g.z_step;
  g.z_count = static_cast<int>(std::lround((z_max - g.z_min) / g.z_step)) + 1;
  if (a.steered && s.steering_arm_m > 0) {
    g.u_count = 21;
    g.u_min = -0.9 * s.steering_arm_m;
    g.u_step = -2.0 * g.u_min / (g.u_count - 1);
  }
  return g;
}

SuspensionKinematics::SuspensionKinematics(const VehicleParams& p) {
  for (std::size_t i = 0; i < p.axles.size(); ++i) {
    const AxleParams& a = p.axles[i];
    const AxleKinematicsParams& k = a.kinematics;
    const auto method =
        k.bicubic ? kinematics::Interpolation::kBicubic : kinematics::Interpolation::kBilinear;
    const std::string axle = "vehicle: axle " + std::to_string(i + 1) + " kinematics: ";
    std::pair<WheelKinematics, WheelKinematics> wheels;
    if (k.x_m.empty() && k.y_m.empty() && k.alpha_rad.empty() && k.beta_rad.empty() &&
        k.gamma_rad.empty()) {
      // the right wheel's geometry is the mirror image (see AxleKinematicsParams); the steer
      // from the rack, asin(u / arm), keeps its sign
      const Grid2D g = generated_grid(a, p.steering);
      kinematics::SuspensionGeometry left = left_wheel_geometry(a, p.steering);
      kinematics::SuspensionGeometry right = left;
      right.track_per_z = -left.track_per_z;
      right.track_per_z2 = -left.track_per_z2;
      right.camber0_rad = -left.camber0_rad;
      right.camber_per_z = -left.camber_per_z;
      right.toe0_rad = -left.toe0_rad;
      right.bump_steer_per_z = -left.bump_steer_per_z;
      if (a.steered && k.ackermann_percent != 0) {
        // Ackermann: k = share x track / (2 wheelbase), the wheelbase to the unsteered axles' line
        double x_sum = 0;
        int unsteered = 0;
        for (const AxleParams& o : p.axles) {
          if (!o.steered) x_sum += o.position_x_m, ++unsteered;
        }
        if (unsteered == 0)
          throw std::invalid_argument(axle + "ackermann_percent needs an unsteered axle");
        const double wheelbase_m = a.position_x_m - x_sum / unsteered;
        left.ackermann_cot_shift = 0.01 * k.ackermann_percent * a.track_m / (2 * wheelbase_m);
        right.ackermann_cot_shift = -left.ackermann_cot_shift;
      }
      wheels = {kinematics::generate_wheel_kinematics(left, g, method),
                kinematics::generate_wheel_kinematics(right, g, method)};
    } else {
      const Grid2D& g = k.grid;
      if (g.u_count > 1 && std::abs(g.u_min + 0.5 * g.u_step * (g.u_count - 1)) > 1e-9)
        throw std::invalid_argument(axle + "the rack-travel grid must be symmetric about 0");
      try {
        wheels = axle_pair(g, k.x_m, k.y_m, k.alpha_rad, k.beta_rad, k.gamma_rad, method);
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(axle + e.what());
      }
    }
    wheels_.push_back(std::move(wheels.first));
    wheels_.push_back(std::move(wheels.second));
    for (std::size_t w = wheels_.size() - 2; w < wheels_.size(); ++w) {
      const WheelKinematics& wk = wheels_[w];
      used_[w] = {nonzero(wk.x()), nonzero(wk.y()), nonzero(wk.alpha()), nonzero(wk.gamma())};
      if (a.kind == AxleKind::kRigid) rigid_[w] = {true, 0.5 * a.track_m, a.rigid.roll_steer};
    }
  }
}

kinematics::WheelPose SuspensionKinematics::pose(int wheel, double hub_travel_m,
                                                 double rack_travel_m) const noexcept {
  return wheels_[static_cast<std::size_t>(wheel)].evaluate(hub_travel_m, rack_travel_m);
}

void SuspensionKinematics::update(const VehicleState& state,
                                  VehicleWorkspace& work) const noexcept {
  for (int i = 0; i < work.wheel_count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    WheelWork& w = work.wheels[k];
    if (rigid_[k].rigid) {
      update_rigid_wheel(i, state, w);
      continue;
    }
    const double s = state.framework_y(6 + i);
    const double rack = state.rack_at_wheel_m[k];
    w.hub_travel_m = s;
    w.steer_at_rack_m = rack;
    const Used& used = used_[k];
    if (!(used.x || used.y || used.alpha || used.gamma)) continue;  // all stay 0
    // one set of interpolation weights for the functions of eq. (29) this wheel has
    const WheelKinematics& wk = wheels_[k];
    const kinematics::TableWeights tw = kinematics::table_weights(wk.grid(), wk.method(), s, rack);
    if (used.x) {
      const kinematics::TableValue x = wk.x().evaluate(tw);
      w.hub_x_m = x.value;
      w.hub_dx_ds = x.d_dz;
    }
    if (used.y) {
      const kinematics::TableValue v = wk.y().evaluate(tw);
      w.hub_y_m = v.value;
      w.hub_dy_ds = v.d_dz;
    }
    const double camber = used.alpha ? wk.alpha().evaluate(tw).value : 0.0;
    double steer = 0.0;
    if (used.gamma) {
      const kinematics::TableValue g = wk.gamma().evaluate(tw);
      steer = g.value;
      w.steer_d_du = g.d_du;
    }
    w.steer_kinematic_rad = steer;
    set_wheel_orientation(w, steer, camber);
  }
}

void SuspensionKinematics::update_rigid_wheel(int i, const VehicleState& state,
                                              WheelWork& w) const noexcept {
  const auto k = static_cast<std::size_t>(i);
  const Rigid& r = rigid_[k];
  const Eigen::Index h = 6 + 2 * (i / 2);
  const double roll = state.framework_y(h + 1);
  // heave +- (track/2) roll: rigid_hub_travel_m
  const double s = state.framework_y(h) + (i % 2 == 0 ? r.half_track_m : -r.half_track_m) * roll;
  const double rack = state.rack_at_wheel_m[k];
  w.hub_travel_m = s;
  w.steer_at_rack_m = rack;
  double steer = r.roll_steer * roll;
  if (used_[k].gamma) {
    const kinematics::TableValue g = wheels_[k].gamma().evaluate(
        kinematics::table_weights(wheels_[k].grid(), wheels_[k].method(), s, rack));
    steer += g.value;
    w.steer_d_du = g.d_du;
  }
  w.steer_kinematic_rad = steer;
  set_wheel_orientation(w, steer, roll);  // camber = the axle's roll
}

}  // namespace rig::model::vehicle
