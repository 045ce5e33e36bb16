#pragma once
/// @file
/// The sequential modified implicit Euler step of one vehicle (or any system of eqs. 1-3): the
/// sequential update of eq. (8) - force elements, then subsystems, then the framework, each
/// using the newest states of the others. A new subsystem is a new stage, not a change here.

#include <vector>

#include <Eigen/Core>

#include "model/solver/couplable_system.h"
#include "model/solver/stage.h"

namespace rig::model::solver {

/// Runs its stages in the order they were added, then the framework. The stages and the
/// framework are owned by the caller (the model), which also owns the blocks. Built once; step(),
/// begin_step() and finish_step() never allocate.
class SequentialStepper final : public CouplableSystem {
 public:
  /// @param framework the framework's stepper (usually a MechanicalStepper), advanced last.
  explicit SequentialStepper(CouplableSystem& framework);

  /// Adds a force-element or subsystem stage. Order matters: add force elements first, then
  /// subsystems (eq. 8). Construction time only (allocates).
  void add_stage(Stage& stage);

  /// One complete step without constraints.
  void step(double h) noexcept;

  // ---- CouplableSystem: the framework's view after the stages have run ----
  [[nodiscard]] Eigen::Index coordinate_size() const noexcept override;
  void begin_step(double h) noexcept override;
  [[nodiscard]] ConstVectorRef coordinates() const noexcept override;
  [[nodiscard]] ConstVectorRef speeds() const noexcept override;
  [[nodiscard]] ConstMatrixRef kinematics_inverse() const noexcept override;
  [[nodiscard]] ConstVectorRef unconstrained_rate() const noexcept override;
  void solve_mass(ConstMatrixRef b, MatrixRef x) const noexcept override;
  void solve_mass_leading(ConstMatrixRef b, MatrixRef x) const noexcept override;
  void finish_step(double h, ConstVectorRef extra_rate) noexcept override;

 private:
  CouplableSystem& framework_;
  std::vector<Stage*> stages_;
  Eigen::VectorXd zero_rate_;
};

}  // namespace rig::model::solver
