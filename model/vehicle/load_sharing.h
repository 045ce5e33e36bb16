#pragma once
/// @file
/// Load-sharing bogies (issue 17 item 3): adjacent independent axles whose springs are connected
/// so that the bogie shares its load by a fixed split whatever the frame's pitch - a walking beam
/// (one beam per side pivoted on the frame, an axle at each end) or air-spring equalisation (each
/// side's air springs on one connected volume: the same pressure in all of them).
///
/// Both are, per side, one spring of rate k_g (the sum of the group's axles' spring rates, so
/// the bogie's heave rate is unchanged) acting at the weighted travel s_g = sum_j w_j s_j, whose
/// force is split by the shares w_i (sum 1): F_i = preload_i + w_i k_g s_g (virtual work: the
/// same w in both). Air springs of equal area: w_i = 1/N (equal pressure, equal force); a walking
/// beam pivoted at x_p between its axles at x_1 > x_2: the lever, w_1 = (x_p - x_2)/(x_1 - x_2),
/// w_2 = (x_1 - x_p)/(x_1 - x_2). The difference between the axles' travels is free (held by the
/// tires alone), as on the real beam or connected bags (the levelling valves' slow control of the
/// mean height is not modelled). Each axle keeps its own dampers, stops and anti-roll bar.
///
/// A leaf balance (two leaf-sprung rigid axles, a rocker between their leaves: leaf_balance.h)
/// takes part here by its static split only (the framework's preloads, the static heave and
/// pitch): w_1 : w_2 = rear_share a_2 : front_share a_1 (leaf_balance_geometry.h), its rate the
/// two axles' spring_stiffness_npm; its forces come from the leaves and rockers themselves.

#include <array>

#include <Eigen/Core>

#include "model/report.h"
#include "model/vehicle/vehicle_params.h"

namespace rig::model::vehicle {

inline constexpr std::size_t kMaxAxles = kMaxWheelsPerUnit / 2;

/// An axle's place in its load-sharing group.
struct AxleShare {
  int group = -1;             ///< index into VehicleParams::load_sharing; -1: on its own
  int first_axle = 0;         ///< the group's first axle
  int axle_count = 0;         ///< the group's axles
  double weight = 0;          ///< w_i
  double group_rate_npm = 0;  ///< k_g, per side
  double group_x_m = 0;       ///< sum_j w_j x_j: where the group's one spring acts on the frame
};
using AxleShares = std::array<AxleShare, kMaxAxles>;

/// The shares of every axle (all -1 without groups). Throws std::invalid_argument on a group that
/// is not a run of adjacent independent axles, overlaps another, or a walking beam that does not
/// have two axles with its pivot between them; a leaf balance not on two leaf-sprung axles with
/// the rocker's ends on either side of its pivot.
[[nodiscard]] AxleShares axle_shares(const VehicleParams& p);

/// The sprung mass's static heave and pitch on its springs (each axle on its own 2 k at its x, each
/// load-sharing group one spring of 2 k_g at group_x_m), and, for a supported unit
/// (ChassisParams::supported: held at design height at support_x_m), its support load.
[[nodiscard]] Eigen::Vector2d static_heave_pitch(const VehicleParams& p, const AxleShares& shares,
                                                 double& support_load_n);

}  // namespace rig::model::vehicle
