#pragma once
/// @file
/// One OpenDRIVE road as plain data, as io/config/opendrive_file reads it from a `.xodr` (ASAM
/// OpenDRIVE 1.4-1.8): the plan view (the reference line's geometry elements) and the elevation
/// and superelevation polynomials along it. What contact needs, nothing of lanes or junctions.
/// model/road/opendrive_reference_line.h evaluates the plan view, opendrive_surface.h the height.

#include <string>
#include <vector>

namespace rig::model::road {

enum class OpenDriveGeometryKind { kLine, kArc, kSpiral, kPoly3, kParamPoly3 };

/// One <geometry> of <planView>: it starts at station s at (x, y) with heading hdg (from +x,
/// counter-clockwise) and runs `length` [m] along the reference line.
struct OpenDriveGeometry {
  OpenDriveGeometryKind kind = OpenDriveGeometryKind::kLine;
  double s_m = 0;
  double x_m = 0;
  double y_m = 0;
  double hdg_rad = 0;
  double length_m = 0;
  double curvature_1pm = 0;               ///< arc: constant curvature (> 0: turning left)
  double curv_start_1pm = 0;              ///< spiral: curvature at the start ...
  double curv_end_1pm = 0;                ///< ... and at the end, linear in s between (a clothoid)
  double a = 0, b = 0, c = 0, d = 0;      ///< poly3: v(u) = a + b u + c u^2 + d u^3 (local u/v)
  double au = 0, bu = 0, cu = 0, du = 0;  ///< paramPoly3: u(p) = au + bu p + cu p^2 + du p^3
  double av = 0, bv = 0, cv = 0, dv = 0;  ///< paramPoly3: v(p)
  bool p_normalized = true;  ///< paramPoly3 pRange: p in [0, 1] (true) or [0, length] (false)
};

/// A cubic in ds = s - s_m, valid from s_m until the next record: <elevation> (a [m], the
/// height) or <superelevation> (a [rad], the roll angle about the s-axis).
struct OpenDrivePolynomial {
  double s_m = 0;
  double a = 0, b = 0, c = 0, d = 0;
};

struct OpenDriveRoad {
  std::string id;
  double length_m = 0;  ///< the <road length> attribute (the plan view's own end is used)
  std::vector<OpenDriveGeometry> plan_view;         ///< increasing s, at least one
  std::vector<OpenDrivePolynomial> elevation;       ///< increasing s; none: height 0
  std::vector<OpenDrivePolynomial> superelevation;  ///< increasing s; none: level
};

}  // namespace rig::model::road
