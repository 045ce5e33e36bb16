#pragma once
/// @file
/// A base surface with overlays whose heights (and gradients) add to it: obstacles on an
/// OpenDRIVE road, on an OpenCRG grid, or on the plane z = 0 (no base). Itself a Surface, so
/// layers nest. The caller's hint is the base's; an overlay gets a hint of its own, fresh each
/// query (an overlay that caches, such as a grid, answers the same, only without its shortcut).

#include <memory>
#include <vector>

#include "model/road/surface.h"

namespace rig::model::road {

class LayeredSurface final : public Surface {
 public:
  /// base nullptr: the plane z = 0. Null overlays are skipped.
  LayeredSurface(std::shared_ptr<const Surface> base,
                 std::vector<std::shared_ptr<const Surface>> overlays);

  [[nodiscard]] SurfaceHeight height(double x_m, double y_m,
                                     SurfaceHint& hint) const noexcept override;

 private:
  std::shared_ptr<const Surface> base_;
  std::vector<std::shared_ptr<const Surface>> overlays_;
};

/// `base` with `overlay` on top: a LayeredSurface, or `base` itself when there is no overlay
/// (so a road without obstacles is its base, unchanged). Both null: null (the plane of today).
[[nodiscard]] std::shared_ptr<const Surface> with_overlay(std::shared_ptr<const Surface> base,
                                                          std::shared_ptr<const Surface> overlay);

}  // namespace rig::model::road
