#pragma once
/// @file
/// A 2-D regular-grid table f(z, u) of hub travel z and rack travel u (eq. 29) with bilinear or
/// bicubic (Catmull-Rom) interpolation and analytic partials d/dz, d/du.
///
/// Extrapolation policy (clamped): outside the grid the coordinate is clamped to the grid's range,
/// so the value is held at the border and the partial in that direction is zero. Bump/rebound
/// stops keep the hub travel inside the table in practice; the clamp only makes an out-of-range
/// query well defined.
///
/// Bicubic = separable Catmull-Rom (Keys' cubic convolution, a = -1/2): C1, reproduces
/// polynomials up to degree 2 in each direction exactly in interior cells; at the borders the
/// missing neighbour is extrapolated linearly (p_-1 = 2 p_0 - p_1), which keeps linear functions
/// exact everywhere. A single grid line (n = 1) in a direction means "constant in it".
///
/// Construction allocates (std::vector); evaluation never does.

#include <cstddef>
#include <vector>

namespace rig::model::kinematics {

enum class Interpolation { kBilinear, kBicubic };

/// A regular grid: n_z x n_u nodes, z_k = z_min + k dz, u_l = u_min + l du.
struct Grid2D {
  double z_min = 0, z_step = 1;  ///< hub travel grid [m]
  int z_count = 1;
  double u_min = 0, u_step = 1;  ///< rack travel grid [m]
  int u_count = 1;
  [[nodiscard]] double z_max() const noexcept { return z_min + z_step * (z_count - 1); }
  [[nodiscard]] double u_max() const noexcept { return u_min + u_step * (u_count - 1); }
};

/// Value and partial derivatives of a table at one point.
struct TableValue {
  double value = 0;
  double d_dz = 0;  ///< partial by hub travel
  double d_du = 0;  ///< partial by rack travel
};

/// Interpolation weights of one query point: computed once and applied to several tables on the
/// same grid (the five functions of eq. 29).
struct TableWeights {
  int z_base = 0, u_base = 0;  ///< first node of the 4x4 (bicubic) or 2x2 (bilinear) stencil
  int z_taps = 1, u_taps = 1;  ///< 2 or 4 (1 for a single grid line)
  double wz[4] = {1, 0, 0, 0}, dwz[4] = {0, 0, 0, 0};  ///< weights and d/dz of the weights
  double wu[4] = {1, 0, 0, 0}, dwu[4] = {0, 0, 0, 0};
  Interpolation method = Interpolation::kBilinear;
};

/// Weights at (z, u) for the grid (clamped extrapolation).
[[nodiscard]] TableWeights table_weights(const Grid2D& grid, Interpolation method, double z,
                                         double u) noexcept;

/// A table of node values f(z_k, u_l), stored z-major: values[k * u_count + l].
class KinematicTable {
 public:
  KinematicTable() = default;
  /// @param values z_count * u_count node values, z-major (values[k * u_count + l]).
  KinematicTable(const Grid2D& grid, std::vector<double> values);

  [[nodiscard]] const Grid2D& grid() const noexcept { return grid_; }
  [[nodiscard]] double node(int k, int l) const noexcept {
    return values_[static_cast<std::size_t>(k) * static_cast<std::size_t>(grid_.u_count) +
                   static_cast<std::size_t>(l)];
  }
  /// Value and partials at (z, u).
  [[nodiscard]] TableValue evaluate(double z, double u, Interpolation method) const noexcept;
  /// Value and partials with precomputed weights (same grid).
  [[nodiscard]] TableValue evaluate(const TableWeights& w) const noexcept;

 private:
  Grid2D grid_;
  std::vector<double> values_ = std::vector<double>(1, 0.0);  ///< default: f = 0 (1x1 grid)
};

}  // namespace rig::model::kinematics
