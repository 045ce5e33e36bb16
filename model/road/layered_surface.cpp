#include "model/road/layered_surface.h"

#include <algorithm>
#include <utility>

namespace rig::model::road {

LayeredSurface::LayeredSurface(std::shared_ptr<const Surface> base,
                               std::vector<std::shared_ptr<const Surface>> overlays)
    : base_(std::move(base)), overlays_(std::move(overlays)) {
  std::erase(overlays_, nullptr);
}

SurfaceHeight LayeredSurface::height(double x_m, double y_m, SurfaceHint& hint) const noexcept {
  SurfaceHeight sum = base_ ? base_->height(x_m, y_m, hint) : SurfaceHeight{};
  for (const auto& overlay : overlays_) {
    SurfaceHint own;
    const SurfaceHeight h = overlay->height(x_m, y_m, own);
    sum.z_m += h.z_m;
    sum.dz_dx += h.dz_dx;
    sum.dz_dy += h.dz_dy;
  }
  return sum;
}

std::shared_ptr<const Surface> with_overlay(std::shared_ptr<const Surface> base,
                                            std::shared_ptr<const Surface> overlay) {
  if (!overlay) return base;
  return std::make_shared<LayeredSurface>(
      std::move(base), std::vector<std::shared_ptr<const Surface>>{std::move(overlay)});
}

}  // namespace rig::model::road
