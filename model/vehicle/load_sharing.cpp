#include "model/vehicle/load_sharing.h"

#include <stdexcept>
#include <string>

#include <Eigen/LU>

#include "model/vehicle/leaf_balance_geometry.h"

namespace rig::model::vehicle {
namespace {

void check_group(const VehicleParams& p, const LoadSharingParams& g, const AxleShares& s,
                 const std::string& what) {
  const auto n = static_cast<int>(p.axles.size());
  if (g.axle_count < 2 || g.first_axle < 0 || g.first_axle + g.axle_count > n)
    throw std::invalid_argument(what + "needs two or more of the vehicle's axles");
  if (g.kind == LoadSharingKind::kLeafBalance) {  // two leaf-sprung rigid axles
    if (g.axle_count != 2) throw std::invalid_argument(what + "a leaf balance carries two axles");
    for (int a = g.first_axle; a < g.first_axle + 2; ++a)
      if (s[static_cast<std::size_t>(a)].group >= 0)
        throw std::invalid_argument(what + "axle " + std::to_string(a + 1) +
                                    " is in another group already");
    try {
      (void)leaf_balance_geometry(p.axles[static_cast<std::size_t>(g.first_axle)],
                                  p.axles[static_cast<std::size_t>(g.first_axle) + 1], g.pivot_x_m);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(what + e.what());
    }
    return;
  }
  for (int a = g.first_axle; a < g.first_axle + g.axle_count; ++a) {
    if (p.axles[static_cast<std::size_t>(a)].kind != AxleKind::kIndependent)
      throw std::invalid_argument(what + "axle " + std::to_string(a + 1) +
                                  " is rigid: load sharing acts on independent axles only");
    if (s[static_cast<std::size_t>(a)].group >= 0)
      throw std::invalid_argument(what + "axle " + std::to_string(a + 1) +
                                  " is in another group already");
  }
  if (g.kind == LoadSharingKind::kWalkingBeam) {
    const double x1 = p.axles[static_cast<std::size_t>(g.first_axle)].position_x_m;
    const double x2 = p.axles[static_cast<std::size_t>(g.first_axle) + 1].position_x_m;
    if (g.axle_count != 2 || !(g.pivot_x_m < x1 && g.pivot_x_m > x2))
      throw std::invalid_argument(what +
                                  "a walking beam carries two axles, its pivot between them");
  }
}

}  // namespace

AxleShares axle_shares(const VehicleParams& p) {
  AxleShares s{};
  for (std::size_t gi = 0; gi < p.load_sharing.size(); ++gi) {
    const LoadSharingParams& g = p.load_sharing[gi];
    check_group(p, g, s, "vehicle: load sharing group " + std::to_string(gi + 1) + ": ");
    double rate = 0, x = 0;
    for (int j = 0; j < g.axle_count; ++j) {
      const AxleParams& a =
          p.axles[static_cast<std::size_t>(g.first_axle) + static_cast<std::size_t>(j)];
      AxleShare& sh = s[static_cast<std::size_t>(g.first_axle) + static_cast<std::size_t>(j)];
      sh = {static_cast<int>(gi), g.first_axle, g.axle_count, 1.0 / g.axle_count, 0, 0};
      rate += a.spring_stiffness_npm;
    }
    if (g.kind == LoadSharingKind::kWalkingBeam) {  // the lever about the pivot
      const double x1 = p.axles[static_cast<std::size_t>(g.first_axle)].position_x_m;
      const double x2 = p.axles[static_cast<std::size_t>(g.first_axle) + 1].position_x_m;
      s[static_cast<std::size_t>(g.first_axle)].weight = (g.pivot_x_m - x2) / (x1 - x2);
      s[static_cast<std::size_t>(g.first_axle) + 1].weight = (x1 - g.pivot_x_m) / (x1 - x2);
    }
    if (g.kind == LoadSharingKind::kLeafBalance) {  // W_1 share_1 a_1 = W_2 share_2 a_2
      const auto f = static_cast<std::size_t>(g.first_axle);
      const LeafBalanceGeometry lb = leaf_balance_geometry(p.axles[f], p.axles[f + 1], g.pivot_x_m);
      const double front = lb.rear_share * lb.rear_arm_m, rear = lb.front_share * lb.front_arm_m;
      s[f].weight = front / (front + rear);
      s[f + 1].weight = rear / (front + rear);
    }
    for (int j = 0; j < g.axle_count; ++j) {
      const auto k = static_cast<std::size_t>(g.first_axle) + static_cast<std::size_t>(j);
      x += s[k].weight * p.axles[k].position_x_m;
    }
    for (int j = 0; j < g.axle_count; ++j) {
      AxleShare& sh = s[static_cast<std::size_t>(g.first_axle) + static_cast<std::size_t>(j)];
      sh.group_rate_npm = rate;
      sh.group_x_m = x;
    }
  }
  return s;
}

Eigen::Vector2d static_heave_pitch(const VehicleParams& p, const AxleShares& shares,
                                   double& support_load_n) {
  const double g = p.road.gravity_mps2;
  const auto& c = p.chassis;
  double sk = 0, skx = 0, skxx = 0;  // per spring unit: an axle on its own, or a group
  for (std::size_t i = 0; i < p.axles.size(); ++i) {
    const AxleShare& sh = shares[i];
    if (sh.group >= 0 && static_cast<int>(i) != sh.first_axle) continue;  // counted once
    const double k = 2 * (sh.group >= 0 ? sh.group_rate_npm : p.axles[i].spring_stiffness_npm);
    const double x = sh.group >= 0 ? sh.group_x_m : p.axles[i].position_x_m;
    sk += k;
    skx += k * x;
    skxx += k * x * x;
  }
  // the free bodies' weights rest on the chassis (their mounts): the springs carry them too
  double body_weight = 0, body_moment = 0;
  for (const FreeBodyParams& b : p.free_bodies) {
    body_weight += b.mass_kg * g;
    body_moment += b.mass_kg * g * b.position_m[0];
  }
  const double weight = c.mass_kg * g + c.payload_n + body_weight;
  const double moment = c.payload_n * c.payload_x_m + body_moment;
  support_load_n = 0;
  if (!c.supported) {
    Eigen::Matrix2d a2;
    a2 << sk, -skx, skx, -skxx;
    return a2.lu().solve(Eigen::Vector2d(weight, moment));
  }
  Eigen::Matrix3d a3;  // heave, pitch and the support force (VehicleFramework's constructor)
  a3 << sk, -skx, 1, skx, -skxx, c.support_x_m, 1, -c.support_x_m, 0;
  const Eigen::Vector3d x = a3.lu().solve(Eigen::Vector3d(weight, moment, 0));
  support_load_n = x(2);
  return x.head<2>();
}

}  // namespace rig::model::vehicle
