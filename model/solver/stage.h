#pragma once
/// @file
/// One stage of the sequential modified implicit Euler step (eq. 8): a force element or a
/// subsystem that is advanced by h using the newest states of the others.

namespace rig::model::solver {

/// Which Jacobians a stepper uses.
enum class JacobianMode {
  kAnalyticOrFiniteDifference,  ///< the block's analytic ones if it has them, else differences
  kFiniteDifference,            ///< always forward differences (prototyping, checks)
  kNone,  ///< mechanical blocks without stiff forces: no Jacobians, M_VI = M (explicit forces)
};

/// Where a mechanical block's forces q are evaluated in eq. (8).
enum class ForceEvaluation {
  /// At the predicted coordinates y(k) + h K^-1 z(k), eqs. (6-8): consistent with the
  /// linearized implicit Euler when the stiff Jacobians are given. The default.
  kPredictedCoordinates,
  /// At y(k), as the paper's own listing for the pendulums (sec. 3.4, p_dyn). With
  /// JacobianMode::kNone this is the symplectic (semi-implicit) Euler: for blocks whose forces
  /// are not stiff (gravity) it does not dissipate energy, where the predicted/implicit forms
  /// damp the motion by O(h) and shift the phase of nonlinear oscillations.
  kCurrentCoordinates,
};

/// A block stepper seen by the SequentialStepper: advance() performs its line of eq. (8).
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
