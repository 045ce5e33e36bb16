#include "model/kinematics/kinematic_table.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace rig::model::kinematics {
namespace {

/// 1-D weights along one grid direction, folded into an in-range stencil.
void axis_weights(double x_min, double step, int count, Interpolation method, double x, int& base,
                  int& taps, double w[4], double dw[4]) {
  for (int i = 0; i < 4; ++i) w[i] = dw[i] = 0.0;
  if (count <= 1) {  // a single grid line: constant in this direction
    base = 0;
    taps = 1;
    w[0] = 1.0;
    return;
  }
  const double x_max = x_min + step * (count - 1);
  const bool clamped = x < x_min || x > x_max;  // clamped extrapolation: hold the border value
  const double xc = std::clamp(x, x_min, x_max);
  const double t = (xc - x_min) / step;
  const int k = std::clamp(static_cast<int>(std::floor(t)), 0, count - 2);
  const double f = t - k;
  const double scale = clamped ? 0.0 : 1.0 / step;  // d f / d x
  if (method == Interpolation::kBilinear) {
    base = k;
    taps = 2;
    w[0] = 1.0 - f;
    w[1] = f;
    dw[0] = -scale;
    dw[1] = scale;
    return;
  }
  // Catmull-Rom on nodes k-1 .. k+2 (Keys, a = -1/2)
  const double f2 = f * f, f3 = f2 * f;
  double cw[4] = {0.5 * (-f3 + 2 * f2 - f), 0.5 * (3 * f3 - 5 * f2 + 2),
                  0.5 * (-3 * f3 + 4 * f2 + f), 0.5 * (f3 - f2)};
  double cd[4] = {0.5 * (-3 * f2 + 4 * f - 1), 0.5 * (9 * f2 - 10 * f), 0.5 * (-9 * f2 + 8 * f + 1),
                  0.5 * (3 * f2 - 2 * f)};
  for (double& d : cd) d *= scale;
  // missing neighbours extrapolated linearly: p_-1 = 2 p_0 - p_1, p_n = 2 p_(n-1) - p_(n-2)
  if (k - 1 < 0) {
    cw[1] += 2 * cw[0], cw[2] -= cw[0], cd[1] += 2 * cd[0], cd[2] -= cd[0];
    cw[0] = cd[0] = 0;
  }
  if (k + 2 > count - 1) {
    cw[2] += 2 * cw[3], cw[1] -= cw[3], cd[2] += 2 * cd[3], cd[1] -= cd[3];
    cw[3] = cd[3] = 0;
  }
  const int first = std::max(k - 1, 0);
  const int last = std::min(k + 2, count - 1);
  base = first;
  taps = last - first + 1;
  for (int i = 0; i < taps; ++i) {
    w[i] = cw[first - (k - 1) + i];
    dw[i] = cd[first - (k - 1) + i];
  }
}

}  // namespace

TableWeights table_weights(const Grid2D& grid, Interpolation method, double z, double u) noexcept {
  TableWeights tw;
  tw.method = method;
  axis_weights(grid.z_min, grid.z_step, grid.z_count, method, z, tw.z_base, tw.z_taps, tw.wz,
               tw.dwz);
  axis_weights(grid.u_min, grid.u_step, grid.u_count, method, u, tw.u_base, tw.u_taps, tw.wu,
               tw.dwu);
  return tw;
}

KinematicTable::KinematicTable(const Grid2D& grid, std::vector<double> values)
    : grid_(grid), values_(std::move(values)) {
  if (grid.z_count < 1 || grid.u_count < 1)
    throw std::invalid_argument("kinematic table: grid needs at least one node per direction");
  if ((grid.z_count > 1 && !(grid.z_step > 0)) || (grid.u_count > 1 && !(grid.u_step > 0)))
    throw std::invalid_argument("kinematic table: grid steps must be positive");
  if (values_.size() !=
      static_cast<std::size_t>(grid.z_count) * static_cast<std::size_t>(grid.u_count))
    throw std::invalid_argument("kinematic table: value count does not match the grid");
}

TableValue KinematicTable::evaluate(double z, double u, Interpolation method) const noexcept {
  return evaluate(table_weights(grid_, method, z, u));
}

TableValue KinematicTable::evaluate(const TableWeights& w) const noexcept {
  TableValue r;
  for (int i = 0; i < w.z_taps; ++i) {
    const double* row = values_.data() + (w.z_base + i) * grid_.u_count + w.u_base;
    double v = 0, dv = 0;
    for (int j = 0; j < w.u_taps; ++j) {
      v += w.wu[j] * row[j];
      dv += w.dwu[j] * row[j];
    }
    r.value += w.wz[i] * v;
    r.d_dz += w.dwz[i] * v;
    r.d_du += w.wz[i] * dv;
  }
  return r;
}

}  // namespace rig::model::kinematics
