#include "model/vehicle/differential/differential_tree.h"

#include <algorithm>
#include <vector>

namespace rig::model::vehicle::differential {
namespace {

/// The configured differentials plus an open one across each driven axle not named.
std::vector<DifferentialParams> all_differentials(const VehicleParams& p) {
  std::vector<DifferentialParams> all = p.drivetrain.differentials;
  for (int a = 0; a < static_cast<int>(p.axles.size()); ++a) {
    if (!p.axles[static_cast<std::size_t>(a)].driven) continue;
    const bool named = std::any_of(all.begin(), all.end(),
                                   [a](const DifferentialParams& d) { return d.axle == a; });
    if (named) continue;
    DifferentialParams open;
    open.axle = a;
    all.push_back(open);
  }
  return all;
}

bool contains(const std::vector<int>& axles, int axle) {
  return std::find(axles.begin(), axles.end(), axle) != axles.end();
}

}  // namespace

int differential_count(const VehicleParams& p) noexcept {
  const auto& ds = p.drivetrain.differentials;
  if (ds.empty()) return 0;
  int count = static_cast<int>(ds.size());
  for (int a = 0; a < static_cast<int>(p.axles.size()); ++a) {
    const bool named =
        std::any_of(ds.begin(), ds.end(), [a](const DifferentialParams& d) { return d.axle == a; });
    if (p.axles[static_cast<std::size_t>(a)].driven && !named) ++count;
  }
  return count;
}

DifferentialTree build_tree(const VehicleParams& p) {
  DifferentialTree t;
  for (int i = 0; i < 2 * static_cast<int>(p.axles.size()); ++i) {
    if (p.axles[static_cast<std::size_t>(i / 2)].driven)
      t.wheel[static_cast<std::size_t>(t.leaf_count++)] = i;
  }
  const std::vector<DifferentialParams> all = all_differentials(p);
  t.count = static_cast<int>(all.size());
  t.g = LeafMatrix::Zero(t.leaf_count, t.count);
  t.input_row = DiffMatrix::Zero(t.count, t.count);
  t.side = SideMatrix::Zero(t.leaf_count, t.count);
  for (int j = 0; j < t.count; ++j) {
    const DifferentialParams& d = all[static_cast<std::size_t>(j)];
    t.params[static_cast<std::size_t>(j)] = d;
    for (int i = 0; i < t.leaf_count; ++i) {
      const int wheel = t.wheel[static_cast<std::size_t>(i)];
      const int axle = wheel / 2;
      int side = 0;
      if (d.axle >= 0) {
        if (axle == d.axle) side = wheel % 2 == 0 ? 1 : -1;  // a: left, b: right
      } else if (contains(d.side_a_axles, axle)) {
        side = 1;
      } else if (contains(d.side_b_axles, axle)) {
        side = -1;
      }
      t.side(i, j) = side;
      t.g(i, j) = side > 0 ? 1.0 - d.split : side < 0 ? -d.split : 0.0;
    }
  }
  // the input of j: the speed of its leaves' sides without the terms of j and its descendants,
  // i.e. the G entries of the differentials above it (whose leaves strictly contain j's)
  for (int j = 0; j < t.count; ++j) {
    int leaf = 0;
    while (t.side(leaf, j) == 0) ++leaf;
    const auto leaves_of = [&](int k) { return (t.side.col(k).array() != 0).count(); };
    for (int k = 0; k < t.count; ++k) {
      if (k != j && t.side(leaf, k) != 0 && leaves_of(k) > leaves_of(j))
        t.input_row(j, k) = t.g(leaf, k);
    }
  }
  return t;
}

}  // namespace rig::model::vehicle::differential
