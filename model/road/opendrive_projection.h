#pragma once
/// @file
/// (x, y) -> (s, t) on an OpenDRIVE reference line: the foot of the perpendicular from the
/// point to the line (t > 0 to the left, OpenDRIVE's sense), in the file's own coordinates.
///
/// A query first runs Newton on s from the caller's hint (the probe's last station): it solves
/// (P - C(s)) . T(s) = 0, whose derivative is -|C'(s)| (1 - t kappa). The local foot found so is
/// the nearest point of the whole line whenever |t| is below the line's reach (Federer 1959,
/// Thm. 4.8: within the reach a point on a normal projects to its foot); the reach is estimated
/// at construction (the smallest radius of curvature, half the closest approach of parts of
/// the line more than pi times that apart along it, capped at 100 m). Otherwise (no hint, a
/// failed Newton, |t| beyond the reach) the nearest of the line's samples (at most 1 m apart,
/// found in a uniform grid) starts Newton again, and a golden-section search between its
/// neighbours is the last resort. So any hint gives the same answer, a good one only faster.
/// Constant after construction; queries noexcept and allocation-free.

#include <vector>

#include "model/road/opendrive_reference_line.h"
#include "model/road/surface.h"

namespace rig::model::road {

/// The foot of a point on the reference line.
struct Station {
  double s_m = 0;
  double t_m = 0;  ///< lateral offset, horizontal, > 0 to the left
  ReferencePose pose;
  bool found = false;  ///< false only for a non-finite point
};

class ReferenceLineProjection {
 public:
  /// Samples the line from 100 m before its start to 100 m after its end (the extensions are
  /// part of the line), at most 1 m apart; throws std::invalid_argument beyond a million
  /// samples (about 44 bytes each with the grid).
  explicit ReferenceLineProjection(const OpenDriveReferenceLine& line);

  /// The station of (x, y) [m] (file coordinates). hint.i is the element + 1 of the last query
  /// (-1: no idea), hint.s_m its station.
  [[nodiscard]] Station project(double x_m, double y_m, SurfaceHint& hint) const noexcept;

  /// The estimated reach [m]: below it the local foot is the global one.
  [[nodiscard]] double reach_m() const noexcept { return reach_; }
  [[nodiscard]] double sample_step_m() const noexcept { return step_; }

 private:
  struct Sample {
    double s = 0, x = 0, y = 0;
  };

  [[nodiscard]] bool newton(double x, double y, double s, int& element,
                            Station& out) const noexcept;
  [[nodiscard]] Station global(double x, double y, int& element) const noexcept;
  [[nodiscard]] Station golden(double x, double y, double s_lo, double s_hi,
                               int& element) const noexcept;
  [[nodiscard]] int nearest_sample(double x, double y) const noexcept;
  [[nodiscard]] int nearest_linear(double x, double y) const noexcept;
  void build_grid();
  void estimate_reach(double max_curvature_1pm);
  [[nodiscard]] int cell_x(double x) const noexcept;
  [[nodiscard]] int cell_y(double y) const noexcept;

  const OpenDriveReferenceLine& line_;
  double step_ = 1;
  double reach_ = 0;
  std::vector<Sample> samples_;  ///< in increasing s
  // uniform grid over the samples: cell (i, j) holds cell_samples_[cell_start_[c] ..
  // cell_start_[c + 1]) with c = j * nx_ + i
  double x0_ = 0, y0_ = 0, cell_m_ = 1;
  int nx_ = 1, ny_ = 1;
  std::vector<int> cell_start_;
  std::vector<int> cell_samples_;
};

}  // namespace rig::model::road
