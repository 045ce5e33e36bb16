#pragma once
/// @file
/// M_VI -= h^2 dq/dy K^-1 (eq. 8) for a K^-1 of 3 x 3 diagonal blocks and then the identity
/// (MechanicalBlock::kinematics_block3_size): a chassis' rotation and Euler-rate blocks, the
/// hub travels' ones. The general product spends most of its work on K's zeros (about 11 k
/// instructions per step for the 40 t combination's two frameworks).
///
/// The same arithmetic as Eigen's GEMM (Release, SSE2, no FMA) of the product: it accumulates
/// each entry as 0 + sum_k dq(i, k) K(k, j) in k order and then adds alpha times it; dropping
/// K's exact zeros from that sum does not change it, nor does a factor of 1. The sums below keep
/// that order (0.0 + the first product, then the others). Bit for bit equal on random matrices
/// (solver_test) and in every run compared but one: on iso8608-class-c-80kmh (the sedan on a
/// rough road) the roll rate differs by at most 8 ulp (5e-20 rad/s) in 6 of 6000 steps and is
/// identical again after - a rounding-level difference whose case in Eigen's kernel is not
/// pinned down.

#include <Eigen/Core>

namespace rig::model::solver {

/// m += alpha (dq_dy K^-1), with K^-1 = diag(B_0, B_1, ..., I) (3 x 3 blocks B over the first
/// `blocks3` rows and columns).
template <typename Matrix>
void subtract_dq_dy_k_inv(Eigen::Index blocks3, double alpha, const Matrix& dq_dy,
                          const Matrix& k_inv, Matrix& m) noexcept {
  const Eigen::Index n = m.rows();
  for (Eigen::Index b = 0; b < blocks3; b += 3) {
    for (Eigen::Index j = b; j < b + 3; ++j) {
      const double k0 = k_inv(b, j), k1 = k_inv(b + 1, j), k2 = k_inv(b + 2, j);
      for (Eigen::Index i = 0; i < n; ++i) {
        double acc = 0.0;
        acc += dq_dy(i, b) * k0;
        acc += dq_dy(i, b + 1) * k1;
        acc += dq_dy(i, b + 2) * k2;
        m(i, j) += acc * alpha;
      }
    }
  }
  for (Eigen::Index j = blocks3; j < n; ++j) {
    for (Eigen::Index i = 0; i < n; ++i) m(i, j) += (0.0 + dq_dy(i, j)) * alpha;
  }
}

/// y += alpha K^-1 z (eq. 6's prediction, eq. 8's y(k+1)) for the same K^-1: Eigen's
/// column-major GEMV sums each entry as 0 + sum_j K(i, j) z(j) in j order and adds it times
/// alpha; the sums below keep that order without K's zeros (solver_test
/// KinematicsProduct.VectorEqualsTheGeneralProductBitForBit). For dynamic sizes only: Eigen sums
/// a fixed-size product in another order.
template <typename Matrix, typename Vector>
void add_k_inv_times(Eigen::Index blocks3, double alpha, const Matrix& k_inv, const Vector& z,
                     Vector& y) noexcept {
  const Eigen::Index n = y.size();
  for (Eigen::Index b = 0; b < blocks3; b += 3) {
    for (Eigen::Index i = b; i < b + 3; ++i) {
      double acc = 0.0;
      acc += k_inv(i, b) * z(b);
      acc += k_inv(i, b + 1) * z(b + 1);
      acc += k_inv(i, b + 2) * z(b + 2);
      y(i) += acc * alpha;
    }
  }
  for (Eigen::Index i = blocks3; i < n; ++i) y(i) += (0.0 + z(i)) * alpha;
}

}  // namespace rig::model::solver
