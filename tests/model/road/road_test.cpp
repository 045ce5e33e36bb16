// Road plane: grade, bank, normal, friction, projection, derivatives, zero allocation.
#include <gtest/gtest.h>

#include <cmath>

#include "model/road/road_plane.h"
#include "tests/support/alloc_counter.h"

namespace rig::model::road {
namespace {

TEST(RoadPlane, TenPercentGradeRisesOneMetrePerTenMetres) {
  const RoadPlane road({grade_percent_to_rad(10.0), 0.0, 0.8});
  EXPECT_NEAR(road.params().grade_rad, std::atan(0.1), 1e-15);
  EXPECT_NEAR(road.height_m(10.0, 3.0), 1.0, 1e-12);
  EXPECT_NEAR(road.height_m(-5.0, 0.0), -0.5, 1e-12);
  EXPECT_EQ(road.friction(12.0, -4.0), 0.8);
  const Eigen::Vector3d& n = road.normal(0, 0);
  EXPECT_NEAR(n.norm(), 1.0, 1e-15);
  EXPECT_NEAR(n.dot(Eigen::Vector3d(1.0, 0.0, 0.1)), 0.0, 1e-15);  // normal to the slope line
  EXPECT_NEAR(n.z(), std::cos(std::atan(0.1)), 1e-15);
  // on a grade of angle a, gravity's component along the road is g sin(a)
  EXPECT_NEAR(-n.x(), std::sin(std::atan(0.1)), 1e-15);
}

TEST(RoadPlane, BankGradientNormalAndProjection) {
  const RoadPlane road({0.05, 0.1, 1.0});
  const double x = 3.0, y = -2.0, e = 1e-6;
  const Eigen::Vector2d g = road.height_gradient(x, y);
  EXPECT_NEAR(g.x(), (road.height_m(x + e, y) - road.height_m(x - e, y)) / (2 * e), 1e-9);
  EXPECT_NEAR(g.y(), (road.height_m(x, y + e) - road.height_m(x, y - e)) / (2 * e), 1e-9);
  EXPECT_NEAR(road.height_m(0.0, 1.0), std::tan(0.1), 1e-15);  // left side raised
  const Eigen::Vector3d p(x, y, 2.0);
  const Eigen::Vector3d c = road.project(p);
  EXPECT_NEAR(c.z(), road.height_m(c.x(), c.y()), 1e-12);  // on the plane
  EXPECT_NEAR((p - c).norm(), road.distance_m(p), 1e-12);
  EXPECT_NEAR((p - c).normalized().dot(road.normal(x, y)), 1.0, 1e-12);
  const Eigen::Vector3d below(0, 0, -0.1);
  EXPECT_LT(road.distance_m(below), 0.0);
}

TEST(RoadPlane, QueriesAllocateNothing) {
  const RoadPlane road({0.1, 0.02, 0.9});
  double sum = 0;
  Eigen::internal::set_is_malloc_allowed(false);
  const rig::test::AllocationCounter counter;
  for (int i = 0; i < 100; ++i) {
    const Eigen::Vector3d p(i, -i, 1.0);
    sum += road.height_m(i, i) + road.normal(i, i).x() + road.project(p).z() +
           road.height_gradient(i, 0).y() + road.friction(0, 0);
  }
  const auto n = counter.count();
  Eigen::internal::set_is_malloc_allowed(true);
  EXPECT_EQ(n, 0u);
  EXPECT_TRUE(std::isfinite(sum));
}

}  // namespace
}  // namespace rig::model::road
