#pragma once
/// @file
/// One stage of the sequential modified implicit Euler step (eq. 8): a force element or a
/// subsystem that is advanced by h using the newest states of the others.

namespace rig::model::solver {

/// Which Jacobians a stepper uses.
enum class JacobianMode {
  kAnalyticOrFiniteDifference,  ///< the block's analytic ones if it has them, else differences
  kFiniteDifference,            ///< always forward differences (prototyping, checks)
};

/// A block stepper seen by the Engine: advance() performs its line of eq. (8).
class Stage {
 public:
  Stage() = default;
  Stage(const Stage&) = delete;
  Stage& operator=(const Stage&) = delete;
  virtual ~Stage() = default;
  /// Advances the block's states from t to t + h. No allocation, no exceptions.
  virtual void advance(double h) noexcept = 0;
};

}  // namespace rig::model::solver
