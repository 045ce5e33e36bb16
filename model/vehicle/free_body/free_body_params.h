#pragma once
/// @file
/// Constant parameters of the generic free bodies (issue 17 item 4, paper sec. 1.2): a suspended
/// cab, an elastically suspended engine, a driver's seat, each attached to the chassis by mounts.
/// Plain data, SI units; filled by io/config/free_body_config from `[[free_body]]`.

#include <array>
#include <string>
#include <vector>

#include "model/report.h"

namespace rig::model::vehicle {

/// At most this many free bodies per vehicle, and mounts per body.
inline constexpr int kMaxFreeBodies = kMaxFreeBodiesPerUnit;
inline constexpr int kMaxMounts = 4;

enum class FreeBodyKind {
  kCab,     ///< 6 DOF on four mounts
  kEngine,  ///< 6 DOF on three mounts; the engine torque reacts on them
  kSeat,    ///< 1 DOF: the driver's mass on a vertical spring and damper
};

/// One mount: a three-axis spring-damper with symmetric stops, its axes the chassis axes turned
/// by `orientation_rad` (roll, pitch, yaw; Rz Ry Rx as the chassis). Deflection d (mount axes)
/// is the body point's displacement from the chassis point relative to the design position.
/// Per axis: F = -k d - c d' - F_stop, F_stop = k_stop e (1 + e / margin) sign(d) for
/// e = |d| - clearance > 0 (a progressive rubber buffer whose rate rises from k_stop at contact
/// to 3 k_stop after `margin` of buffer travel, FreeBodyParams::through_margin_m).
struct MountParams {
  std::array<double, 3> body_point_m{};     ///< body axes, from the body's CG
  std::array<double, 3> chassis_point_m{};  ///< chassis axes, from the chassis CG
  std::array<double, 3> orientation_rad{};  ///< roll, pitch, yaw of the mount axes
  std::array<double, 3> stiffness_npm{};
  std::array<double, 3> damping_nspm{};
  std::array<double, 3> stop_clearance_m{0.01, 0.01, 0.01};
  std::array<double, 3> stop_stiffness_npm{};
};

struct FreeBodyParams {
  std::string name;  ///< unique per vehicle (outputs)
  FreeBodyKind kind = FreeBodyKind::kCab;
  double mass_kg = 0;
  std::array<double, 3> inertia_kgm2{};  ///< Ixx, Iyy, Izz about its CG, principal (cab, engine)
  /// Design position of its CG, chassis axes from the chassis CG (the seat: where the driver's
  /// mass sits with the spring unloaded, straight above the seat's chassis point).
  std::array<double, 3> position_m{};
  /// cab 4, engine 3, seat 1 (its z axis only: stiffness, damping and stop along road z).
  std::vector<MountParams> mounts;
  /// A mount deflected this far beyond its stop clearance: the body is through its stops, a
  /// vehicle fault (FaultKind::kFreeBodyStops) [m].
  double through_margin_m = 0.01;
  /// The engine: its crankshaft axis in body axes (unit); the drive torque reacts about it.
  std::array<double, 3> crankshaft_axis{1, 0, 0};
};

}  // namespace rig::model::vehicle
