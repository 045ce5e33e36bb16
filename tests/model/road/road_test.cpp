// The road plane: gravity tilted by grade and bank, height and normal, split friction, zero
// allocation.
#include <gtest/gtest.h>

#include <cmath>

#include "model/road/road.h"
#include "tests/support/alloc_counter.h"

namespace rig::model::road {
namespace {

TEST(Road, TenPercentGradeTiltsGravityByAtanOfTheGrade) {
  const Road road({0.1, 0.0, 0.8, -1.0, 9.81, nullptr, nullptr});
  const Eigen::Vector3d& g = road.gravity_mps2();
  // on a grade of angle a = atan(0.1): g sin(a) down the slope (-x), g cos(a) into the road
  EXPECT_NEAR(g.x(), -9.81 * 0.1 / std::sqrt(1.01), 1e-14);
  EXPECT_EQ(g.y(), 0.0);
  EXPECT_NEAR(g.z(), -9.81 / std::sqrt(1.01), 1e-14);
  EXPECT_NEAR(g.norm(), 9.81, 1e-14);
  EXPECT_EQ(road.height_m(10.0, 3.0), 0.0);  // the vehicle's frame is the road's
  EXPECT_EQ(road.normal(10.0, 3.0), Eigen::Vector3d::UnitZ());
  EXPECT_EQ(road.friction(false), 0.8);
  EXPECT_EQ(road.friction(true), 0.8);  // no split
}

TEST(Road, BankTiltsGravityToTheLowSideAndSplitMuActsOnTheRight) {
  const Road road({0.0, 0.05, 1.0, 0.2, 9.81, nullptr, nullptr});
  const Eigen::Vector3d& g = road.gravity_mps2();
  // uphill in +y: gravity pulls towards -y by g sin(atan(0.05))
  EXPECT_NEAR(g.y(), -9.81 * 0.05 / std::sqrt(1.0025), 1e-14);
  EXPECT_NEAR(g.z(), -9.81 / std::sqrt(1.0025), 1e-14);
  EXPECT_NEAR(g.norm(), 9.81, 1e-14);
  EXPECT_EQ(road.friction(false), 1.0);
  EXPECT_EQ(road.friction(true), 0.2);
}

TEST(Road, QueriesAllocateNothing) {
  const Road road({0.1, 0.02, 0.9, 0.3, 9.81, nullptr, nullptr});
  double sum = 0;
  Eigen::internal::set_is_malloc_allowed(false);
  const rig::test::AllocationCounter counter;
  for (int i = 0; i < 100; ++i) {
    sum += road.height_m(i, -i) + road.normal(i, i).z() + road.gravity_mps2().x() +
           road.friction(i % 2 == 1);
  }
  const auto n = counter.count();
  Eigen::internal::set_is_malloc_allowed(true);
  EXPECT_EQ(n, 0u);
  EXPECT_TRUE(std::isfinite(sum));
}

}  // namespace
}  // namespace rig::model::road
