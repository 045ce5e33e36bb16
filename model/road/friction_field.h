#pragma once
/// @file
/// Friction over the road: the mu scale the tires take at (x, y) of the road frame (1 = the tire
/// data as given, as `road_friction`). Friction zones (model/road/friction_zones.h) are one
/// implementation. Constant after construction; queries noexcept and allocation-free.

namespace rig::model::road {

class FrictionField {
 public:
  FrictionField() = default;
  FrictionField(const FrictionField&) = delete;
  FrictionField& operator=(const FrictionField&) = delete;
  virtual ~FrictionField() = default;

  /// mu at (x, y) [m]: the field's value where it defines one, else base_mu (the road's own).
  [[nodiscard]] virtual double mu(double x_m, double y_m, double base_mu) const noexcept = 0;
};

}  // namespace rig::model::road
