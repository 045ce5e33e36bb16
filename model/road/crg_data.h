#pragma once
/// @file
/// An OpenCRG road surface as plain data (ASAM OpenCRG 1.2, "OpenCRG data format"): a curved
/// regular grid of heights z(u, v) along a reference line, the reference line's channels, and the
/// file's evaluation options and modifiers. io/config/crg_file.h fills it from a .crg file,
/// model/road/iso8608.h generates one; model/road/crg_surface.h evaluates it. Plain data: no
/// invariants beyond what the loaders check (sizes, ascending v, no NaN in reference channels).

#include <cstddef>
#include <limits>
#include <vector>

#include "model/road/placement.h"

namespace rig::model::road {

/// $ROAD_CRG_OPTS BORDER_MODE_U / BORDER_MODE_V: the height beyond the grid's ends / sides.
/// (0, "return NaN", is refused by the loaders: a tire cannot stand on NaN.)
enum class CrgBorderMode {
  kZero = 1,      ///< z = the border offset(s)
  kKeepLast = 2,  ///< the last cross section (u) / long section (v) continued (the default)
  kRepeat = 3,    ///< the grid repeated
  kReflect = 4,   ///< the grid mirrored at its ends
};

/// $ROAD_CRG_MODS GRID_NAN_MODE: what NaN cells (only at a cross section's left or right end)
/// become. (0, "keep NaN", is refused by the loaders.)
enum class CrgNanMode {
  kSetZero = 1,   ///< GRID_NAN_OFFSET
  kKeepLast = 2,  ///< the nearest valid value of the cross section + GRID_NAN_OFFSET (default)
};

/// $ROAD_CRG_OPTS that change the evaluation (the others - WARN_*, LOG_*, CHECK_*,
/// REFLINE_SEARCH_* - concern the OpenCRG tools' messages and searches and are read, not used).
struct CrgOptions {
  CrgBorderMode border_u = CrgBorderMode::kKeepLast;
  CrgBorderMode border_v = CrgBorderMode::kKeepLast;
  double border_offset_u_m = 0;  ///< added beyond the u ends (kZero, kKeepLast)
  double border_offset_v_m = 0;  ///< added beyond the sides (kZero, kKeepLast)
  double smooth_ubeg_m = 0;      ///< BORDER_SMOOTH_UBEG: heights faded in over this length
  double smooth_uend_m = 0;      ///< BORDER_SMOOTH_UEND: faded out over this length
};

/// $ROAD_CRG_MODS: data modifiers applied once when the surface is built.
struct CrgModifiers {
  CrgNanMode nan_mode = CrgNanMode::kKeepLast;
  double nan_offset_m = 0;   ///< GRID_NAN_OFFSET
  double scale_z_grid = 1;   ///< SCALE_Z_GRID: the grid's heights
  double scale_slope = 1;    ///< SCALE_SLOPE: the slope channel
  double scale_banking = 1;  ///< SCALE_BANKING: the banking channel
  /// REFPOINT_*: the file's own placement (given = false: none). A configuration's placement
  /// replaces it.
  Placement refpoint{};
};

struct CrgData {
  /// u of the first cross section and the spacing of the cross sections [m] (nu = z rows).
  double u_first_m = 0;
  double u_increment_m = 1;
  /// v of each long section [m], strictly ascending (right to left); equal or variable spacing.
  std::vector<double> v_m;
  /// Heights [m] of the grid, row-major: z_m[i * v_m.size() + j] at (u_i, v_j). NaN cells only at
  /// a cross section's ends (the loaders check it); float32 as in the file format.
  std::vector<float> z_m;

  /// Reference line heading [rad] per cross section; entry 0 is unused (heading i leads from
  /// point i-1 to point i, OpenCRG's convention). Empty: a straight line at start_phi_rad.
  std::vector<double> heading_rad;
  /// Reference line points [m] (both or neither); used when there is no heading channel.
  std::vector<double> ref_x_m;
  std::vector<double> ref_y_m;
  /// Banking (cross slope, dz/dv) [-] per cross section; empty: the constant start_bank.
  std::vector<double> banking;
  /// Slope (dz/du) [-] per cross section, entry i for the step from i-1 to i (entry 0 unused);
  /// empty: the constant start_slope.
  std::vector<double> slope;

  double start_x_m = 0;  ///< REFERENCE_LINE_START_X/Y/PHI/Z
  double start_y_m = 0;
  double start_phi_rad = 0;
  double start_z_m = 0;
  double start_slope = 0;  ///< REFERENCE_LINE_START_S (constant slope without a channel)
  double start_bank = 0;   ///< REFERENCE_LINE_START_B (constant banking without a channel)
  /// REFERENCE_LINE_END_X/Y/Z; NaN: not given. Given, the integrated line is corrected to end
  /// there (the closure error spread linearly over u, as OpenCRG distributes it).
  double end_x_m = std::numeric_limits<double>::quiet_NaN();
  double end_y_m = std::numeric_limits<double>::quiet_NaN();
  double end_z_m = std::numeric_limits<double>::quiet_NaN();

  CrgOptions options{};
  CrgModifiers mods{};

  [[nodiscard]] std::size_t nu() const { return v_m.empty() ? 0 : z_m.size() / v_m.size(); }
  [[nodiscard]] std::size_t nv() const { return v_m.size(); }
  [[nodiscard]] double u_last_m() const {
    return u_first_m + u_increment_m * static_cast<double>(nu() - 1);
  }
};

}  // namespace rig::model::road
