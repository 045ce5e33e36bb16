// The leaf spring's cost probe for callgrind (repeatable whatever the machine's load): N warm
// evaluations along the 1 ms load history, inside measured_steps(), so that
//   valgrind --tool=callgrind --toggle-collect='measured_steps*' leaf_spring_cost N
// counts exactly those instructions (divide by N).
#include <cstdio>
#include <cstdlib>

#include <Eigen/LU>

#include "model/vehicle/leaf_spring/leaf_spring.h"
#include "tests/model/vehicle/leaf_spring/load_history.h"
#include "tests/model/vehicle/leaf_spring/van_leaf_params.h"

namespace ls = rig::model::vehicle::leaf_spring;

/// The measured region (not inlined, so that callgrind can toggle on it).
__attribute__((noinline)) double measured_steps(const ls::LeafSpring& leaf, ls::LeafState& s,
                                                const ls::SeatPose& stat, long n, long& its) {
  double sum = 0;
  for (long k = 0; k < n; ++k) {
    const ls::LeafForces f =
        leaf.evaluate(rig::test::leaf_history_pose(stat, static_cast<int>(k % 10000)), s);
    sum += f.on_axle(1);
    its += f.iterations;
  }
  return sum;
}

int main(int argc, char** argv) {
  const long n = argc > 1 ? std::atol(argv[1]) : 10000;
  const ls::LeafSpring leaf(rig::test::van_rear_leaf());
  ls::LeafState s = leaf.free_state();
  ls::SeatPose stat = ls::SeatPose::Zero();
  for (int k = 0; k < 50; ++k) {
    const ls::LeafForces f = leaf.evaluate(stat, s);
    stat -= f.d_on_axle_d_seat.lu().solve(
        f.on_axle + Eigen::Vector3d(0.0, rig::test::kVanLeafStaticLoadN, 0.0));
  }
  long its = 0;
  const double sum = measured_steps(leaf, s, stat, n, its);
  std::printf("%ld evaluations, %ld Newton iterations, mean F_z %.3f N\n", n, its,
              n > 0 ? sum / static_cast<double>(n) : 0.0);
  return 0;
}
