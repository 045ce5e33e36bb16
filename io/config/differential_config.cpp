#include "io/config/differential_config.h"

#include <algorithm>
#include <string>

#include "model/report.h"

namespace rig::io::config {
namespace {

using model::vehicle::AxleParams;
using model::vehicle::differential::DifferentialKind;
using model::vehicle::differential::DifferentialParams;

/// An axle number (1-based in the file) of a driven axle, as a 0-based index.
int driven_axle(StrictTable& t, const toml::node& n, std::string_view key,
                const std::vector<AxleParams>& axles) {
  const auto v = n.value<long long>();
  if (!n.is_integer() || !v)
    throw t.error_at(n, key, "expected an axle number (1 = the first [[axle]])");
  if (*v < 1 || *v > static_cast<long long>(axles.size()))
    throw t.error_at(
        n, key,
        "axle " + std::to_string(*v) + " does not exist (1.." + std::to_string(axles.size()) + ")");
  if (!axles[static_cast<std::size_t>(*v - 1)].driven)
    throw t.error_at(n, key, "axle " + std::to_string(*v) + " is not driven");
  return static_cast<int>(*v - 1);
}

/// One side of `between`: an axle number or a list of them.
std::vector<int> read_side(StrictTable& t, const toml::node& n,
                           const std::vector<AxleParams>& axles) {
  std::vector<int> side;
  if (const toml::array* list = n.as_array()) {
    t.check_length("between", *list, axles.size());
    for (const toml::node& e : *list) side.push_back(driven_axle(t, e, "between", axles));
    if (side.empty()) throw t.error_at(n, "between", "a side needs at least one axle");
  } else {
    side.push_back(driven_axle(t, n, "between", axles));
  }
  std::sort(side.begin(), side.end());
  if (std::adjacent_find(side.begin(), side.end()) != side.end())
    throw t.error_at(n, "between", "an axle is named twice");
  return side;
}

void read_between(StrictTable& t, const std::vector<AxleParams>& axles, DifferentialParams& d) {
  const toml::node& n = t.node("between");
  const toml::array* list = n.as_array();
  if (list == nullptr || list->size() != 2)
    throw t.error("between", "expected two sides, e.g. between = [1, 2] or [[1], [2, 3]]");
  d.side_a_axles = read_side(t, *list->get(0), axles);
  d.side_b_axles = read_side(t, *list->get(1), axles);
  for (const int a : d.side_a_axles)
    if (std::find(d.side_b_axles.begin(), d.side_b_axles.end(), a) != d.side_b_axles.end())
      throw t.error("between", "axle " + std::to_string(a + 1) + " is on both sides");
  d.split = t.number_in("split", 0.5, 0.01, 0.99);
}

DifferentialKind read_kind(StrictTable& t) {
  const std::string k = t.choice("kind", "open", {"open", "locked", "viscous", "limited_slip"});
  if (k == "locked") return DifferentialKind::kLocked;
  if (k == "viscous") return DifferentialKind::kViscous;
  if (k == "limited_slip") return DifferentialKind::kLimitedSlip;
  return DifferentialKind::kOpen;
}

DifferentialParams read_one(StrictTable t, const std::vector<AxleParams>& axles) {
  DifferentialParams d;
  if (t.has("axle") == t.has("between"))
    throw t.error("needs exactly one of axle = N (across an axle) or between = [A, B]");
  if (t.has("axle")) {
    d.axle = driven_axle(t, t.node("axle"), "axle", axles);
    if (t.has("split")) throw t.error("split", "applies to a differential between axles");
  } else {
    read_between(t, axles, d);
  }
  d.kind = read_kind(t);
  if (d.kind == DifferentialKind::kViscous) d.viscous_nmspr = t.number_in("viscous_nmspr", 1, 1e6);
  if (d.kind == DifferentialKind::kLimitedSlip) {
    d.preload_nm = t.number_in("preload_nm", 0.0, 0, 1e5);
    d.bias_ratio = t.number_in("bias_ratio", 1.0, 1, 20);
    if (d.preload_nm == 0 && d.bias_ratio == 1)
      throw t.error("preload_nm",
                    "a limited-slip differential needs preload_nm > 0 or "
                    "bias_ratio > 1 (else it is open)");
  }
  d.lockable = t.boolean("lockable", false);
  t.finish();
  return d;
}

std::vector<int> axles_of(const DifferentialParams& d) {
  if (d.axle >= 0) return {d.axle};
  std::vector<int> all = d.side_a_axles;
  all.insert(all.end(), d.side_b_axles.begin(), d.side_b_axles.end());
  std::sort(all.begin(), all.end());
  return all;
}

/// Every side of more than one axle is another between-differential's axles; one root spans
/// every driven axle; no axle is named across twice; no group feeds two differentials.
void check_tree(StrictTable& t, const std::vector<DifferentialParams>& ds,
                const std::vector<AxleParams>& axles) {
  std::vector<int> driven;
  for (int a = 0; a < static_cast<int>(axles.size()); ++a)
    if (axles[static_cast<std::size_t>(a)].driven) driven.push_back(a);
  std::vector<std::vector<int>> groups;  // the between-differentials' axle sets
  std::vector<int> across;
  for (const DifferentialParams& d : ds) {
    if (d.axle >= 0) {
      if (std::find(across.begin(), across.end(), d.axle) != across.end())
        throw t.error("differential",
                      "axle " + std::to_string(d.axle + 1) + " has two differentials across it");
      across.push_back(d.axle);
    } else {
      if (std::find(groups.begin(), groups.end(), axles_of(d)) != groups.end())
        throw t.error("differential", "two differentials between the same axles");
      groups.push_back(axles_of(d));
    }
  }
  if (driven.size() > 1 && std::find(groups.begin(), groups.end(), driven) == groups.end())
    throw t.error("differential",
                  "the driven axles need one differential between all of them "
                  "(e.g. between = [1, 2]), the root of the drive train");
  std::vector<std::vector<int>> fed;
  std::vector<int> fed_axles;
  for (const DifferentialParams& d : ds) {
    for (std::vector<int> side : {d.side_a_axles, d.side_b_axles}) {
      if (side.size() == 1) {
        if (std::find(fed_axles.begin(), fed_axles.end(), side[0]) != fed_axles.end())
          throw t.error("differential",
                        "axle " + std::to_string(side[0] + 1) + " is a side of two differentials");
        fed_axles.push_back(side[0]);
      }
      if (side.size() < 2) continue;
      if (std::find(groups.begin(), groups.end(), side) == groups.end())
        throw t.error("differential",
                      "no differential is between the axles of a side of more "
                      "than one axle (add one between them)");
      if (std::find(fed.begin(), fed.end(), side) != fed.end())
        throw t.error("differential", "a group of axles is a side of two differentials");
      fed.push_back(side);
    }
  }
  if (fed.size() + 1 != groups.size() && !groups.empty())
    throw t.error("differential",
                  "every differential between axles but the root must be a "
                  "side of another");
  const std::size_t implicit = driven.size() - across.size();
  if (ds.size() + implicit > static_cast<std::size_t>(model::kMaxDifferentials))
    throw t.error("differential", "at most " + std::to_string(model::kMaxDifferentials) +
                                      " differentials (with one across each driven axle)");
  const auto lsd = std::count_if(ds.begin(), ds.end(), [](const DifferentialParams& d) {
    return d.kind == DifferentialKind::kLimitedSlip;
  });
  if (lsd > 4) throw t.error("differential", "at most 4 limited-slip differentials");
}

}  // namespace

std::vector<DifferentialParams> read_differentials(StrictTable& t,
                                                   const std::vector<AxleParams>& axles) {
  std::vector<DifferentialParams> ds;
  if (!t.has("differential")) return ds;
  for (StrictTable& d : t.tables("differential", model::kMaxDifferentials))
    ds.push_back(read_one(std::move(d), axles));
  if (std::none_of(axles.begin(), axles.end(), [](const AxleParams& a) { return a.driven; }))
    throw t.error("differential", "a vehicle without driven axles has no differentials");
  check_tree(t, ds, axles);
  return ds;
}

}  // namespace rig::io::config
