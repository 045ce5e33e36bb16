#include "model/combination/chain_constraint.h"

#include <stdexcept>

namespace rig::model::combination {

ChainConstraint::ChainConstraint(const std::vector<JointParams>& joints,
                                 const std::vector<Eigen::Index>& unit_sizes) {
  if (unit_sizes.size() != joints.size() + 1)
    throw std::invalid_argument("combination: need one joint between each pair of units");
  Eigen::Index offset = 0;
  for (const Eigen::Index n : unit_sizes) {
    offsets_.push_back(offset);
    offset += n;
  }
  for (const JointParams& j : joints) {
    joints_.emplace_back(j);
    rows_of_.push_back(rows_);
    rows_ += joints_.back().size();
  }
}

void ChainConstraint::evaluate(const Eigen::Ref<const Eigen::VectorXd>& y,
                               Eigen::Ref<Eigen::VectorXd> g,
                               Eigen::Ref<Eigen::MatrixXd> dg_dy) const noexcept {
  dg_dy.setZero();
  JointEvaluation e;
  for (std::size_t i = 0; i < joints_.size(); ++i) {
    const Joint& j = joints_[i];
    const Eigen::Index oa = offsets_[i], ob = offsets_[i + 1], r = rows_of_[i];
    const int m = j.size();
    j.evaluate(y.segment<6>(oa), y.segment<6>(ob), e);
    g.segment(r, m) = e.g.head(m);
    // only the chassis columns: the joint is on the sprung masses
    dg_dy.block(r, oa, m, 6) = e.dg_dya.topRows(m);
    dg_dy.block(r, ob, m, 6) = e.dg_dyb.topRows(m);
  }
}

}  // namespace rig::model::combination
