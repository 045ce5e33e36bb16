#pragma once
/// @file
/// An OpenCRG grid as a road surface, evaluated as OpenCRG specifies (crgEvalxy2z of the OpenCRG
/// C API): (x, y) -> (u, v) on the reference line (model/road/crg_reference_line.h), then
///   z(u, v) = bilinear(z_grid; u, v) + z_ref(u) + banking(u) v_clamped (+ border offsets)
/// with z_ref the integrated slope channel (z_ref,i = z_ref,i-1 + slope_i du, from
/// REFERENCE_LINE_START_Z) and banking, both linear between cross sections, v clamped to the
/// grid's width for the banking term. Off the grid the $ROAD_CRG_OPTS border modes apply
/// (model/road/crg_data.h; BORDER_MODE 1: z = the offsets, not moved by a placement), then
/// BORDER_SMOOTH_UBEG/UEND. NaN cells are filled once, at
/// construction, by GRID_NAN_MODE. The gradient is that of the evaluated (piecewise bilinear)
/// surface, exact: dz/dx = dz/du du/dx + dz/dv dv/dx.
///
/// Placement (model/road/placement.h): the grid's point (u, v) goes to (x, y, z) of the road
/// frame with the reference line's heading there; without one (and without REFPOINT_*
/// modifiers in the file) the surface sits where its file puts it. Constant after construction;
/// height() is noexcept and allocation-free; SurfaceHint.i is the reference-line segment, .j the
/// long-section cell of the probe's last query.

#include <vector>

#include "model/road/crg_data.h"
#include "model/road/crg_reference_line.h"
#include "model/road/placement.h"
#include "model/road/surface.h"

namespace rig::model::road {

class CrgSurface final : public Surface {
 public:
  /// `placement.given` false: the file's REFPOINT_* modifiers if it has them, else the file's
  /// own position. Expects data the loaders checked (>= 2 x 2 cells, ascending v, each cross
  /// section with a valid cell and NaN only at its ends).
  explicit CrgSurface(const CrgData& data, const Placement& placement = {});

  [[nodiscard]] SurfaceHeight height(double x_m, double y_m,
                                     SurfaceHint& hint) const noexcept override;

  /// The height and its gradient over (u, v) at grid coordinates (u, v), before placement.
  struct UvHeight {
    double z_m = 0;
    double dz_du = 0;
    double dz_dv = 0;
    /// BORDER_MODE 1 gave the height: the offset itself, in the road frame too (a placed patch
    /// surrounded by z = offset, as OpenCRG returns it).
    bool absolute = false;
  };
  [[nodiscard]] UvHeight at_uv(double u_m, double v_m, int& v_cell) const noexcept;

  /// (x, y) of the road frame of grid point (u, v), and the inverse transform's pieces (tests).
  void world_point(double u_m, double v_m, double& x_m, double& y_m) const noexcept;
  [[nodiscard]] const CrgReferenceLine& reference_line() const noexcept { return line_; }
  [[nodiscard]] double u_first_m() const noexcept { return u_first_m_; }
  [[nodiscard]] double u_last_m() const noexcept { return u_last_m_; }
  [[nodiscard]] double v_first_m() const noexcept { return v_.front(); }
  [[nodiscard]] double v_last_m() const noexcept { return v_.back(); }

 private:
  /// A coordinate on one axis of the grid after the border mode: cell, fraction in it, the
  /// fraction's derivative over the coordinate, and whether (and how) it was outside.
  struct AxisPoint {
    int cell = 0;
    double frac = 0;
    double dfrac = 0;
    double mapped = 0;   ///< the coordinate mapped into the grid (repeat, reflect) or as given
    double dmapped = 1;  ///< d mapped / d coordinate (+-1; 0 where it is held)
    bool outside = false;
  };
  [[nodiscard]] AxisPoint u_axis(double u_m) const noexcept;
  /// u_axis of a point the reference line placed between two cross sections (no search).
  [[nodiscard]] AxisPoint u_axis(const CrgStation& s) const noexcept;
  [[nodiscard]] UvHeight evaluate(const AxisPoint& u, const AxisPoint& v) const noexcept;
  [[nodiscard]] AxisPoint v_axis(double v_m, int& v_cell) const noexcept;
  [[nodiscard]] int v_cell_of(double v_m, int v_cell) const noexcept;
  void add_reference_terms(const AxisPoint& u, const AxisPoint& v, UvHeight& h) const noexcept;
  void smooth(const AxisPoint& u, UvHeight& h) const noexcept;
  void fill_nans(const CrgData& data);
  void place(const CrgData& data, const Placement& placement);

  CrgReferenceLine line_;
  CrgOptions options_;
  double u_first_m_ = 0;
  double u_last_m_ = 0;
  double du_m_ = 1;
  double inv_du_ = 1;
  std::vector<double> v_;
  std::vector<double> inv_dv_cell_;  ///< 1 / the width of each long-section cell
  bool v_equal_ = true;              ///< equally spaced long sections: cell by multiplication
  double dv_m_ = 1;
  double inv_dv_ = 1;
  int nv_ = 0;
  int nu_ = 0;
  std::vector<float> z_;       ///< the grid, NaN cells filled, SCALE_Z_GRID applied
  std::vector<double> z_ref_;  ///< reference line height per cross section
  std::vector<double> bank_;   ///< banking per cross section
  bool smoothing_ = false;     ///< BORDER_SMOOTH_UBEG or _UEND given
  // placement: p_file = R(-rot) (p_world - t) + p_ref, z_world = z_file + dz
  double cos_ = 1;
  double sin_ = 0;
  double tx_m_ = 0;
  double ty_m_ = 0;
  double ref_x_m_ = 0;
  double ref_y_m_ = 0;
  double dz_m_ = 0;
};

}  // namespace rig::model::road
