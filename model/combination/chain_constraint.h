#pragma once
/// @file
/// The constraints of a chain of units (unit i and unit i+1 joined by joint i) over the stacked
/// coordinates Y = [y_0; y_1; ...] of the CoupledStepper (eq. 47 with a vector lambda).

#include <vector>

#include "model/combination/joint.h"
#include "model/solver/constraint_coupling.h"

namespace rig::model::combination {

class ChainConstraint final : public solver::ConstraintFunction {
 public:
  /// joints[i] couples unit i (leading) and unit i+1; unit_sizes: coordinate counts.
  ChainConstraint(const std::vector<JointParams>& joints,
                  const std::vector<Eigen::Index>& unit_sizes);

  [[nodiscard]] Eigen::Index size() const noexcept override { return rows_; }
  void evaluate(const Eigen::Ref<const Eigen::VectorXd>& y, Eigen::Ref<Eigen::VectorXd> g,
                Eigen::Ref<Eigen::MatrixXd> dg_dy) const noexcept override;

  [[nodiscard]] int joint_count() const noexcept { return static_cast<int>(joints_.size()); }
  [[nodiscard]] const Joint& joint(int i) const noexcept {
    return joints_[static_cast<std::size_t>(i)];
  }
  /// First row of joint i in g and lambda.
  [[nodiscard]] Eigen::Index row(int i) const noexcept {
    return rows_of_[static_cast<std::size_t>(i)];
  }
  /// First coordinate of unit i in Y.
  [[nodiscard]] Eigen::Index offset(int unit) const noexcept {
    return offsets_[static_cast<std::size_t>(unit)];
  }

 private:
  std::vector<Joint> joints_;
  std::vector<Eigen::Index> offsets_, rows_of_;
  Eigen::Index rows_ = 0;
};

}  // namespace rig::model::combination
