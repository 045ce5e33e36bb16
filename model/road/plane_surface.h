#pragma once
/// @file
/// A tilted plane as a surface: z = grade x + bank y (the `[road] kind = "plane"` with grade or
/// bank: a real slope under gravity straight down, unlike the `[model] road_*` plane whose grade
/// and bank tilt gravity; model/road/road.h).

#include "model/road/surface.h"

namespace rig::model::road {

class PlaneSurface final : public Surface {
 public:
  /// grade: tan of the uphill slope in +x; bank: tan of the uphill slope in +y [-].
  PlaneSurface(double grade, double bank) noexcept : grade_(grade), bank_(bank) {}

  [[nodiscard]] SurfaceHeight height(double x_m, double y_m,
                                     SurfaceHint& /*hint*/) const noexcept override {
    return {grade_ * x_m + bank_ * y_m, grade_, bank_};
  }

 private:
  double grade_;
  double bank_;
};

}  // namespace rig::model::road
