#include "rig/kpi/kpi_spec.h"

#include <algorithm>

namespace rig::kpi {
namespace {

struct KindName {
  const char* name;
  KpiKind kind;
  bool needs_versus;
};
constexpr KindName kKinds[] = {{"peak_abs", KpiKind::kPeakAbs, false},
                               {"loop_width", KpiKind::kLoopWidth, true},
                               {"gradient", KpiKind::kGradient, true},
                               {"residual_fraction", KpiKind::kResidualFraction, false}};

const io::signals::Entry& output(io::config::StrictTable& t, const io::signals::Catalogue& cat,
                                 std::string_view key, std::string& name) {
  name = t.string(key);
  return cat.lookup(t, key, name);
}

/// The unit a kind gives if the table names none: "N m per m/s^2" for a gradient.
std::string derived_unit(KpiKind kind, const std::string& y, const std::string& x) {
  switch (kind) {
    case KpiKind::kGradient:
      return y + "/(" + x + ")";
    case KpiKind::kResidualFraction:
      return "1";
    default:
      return y;
  }
}

KpiSpec read_kpi(io::config::StrictTable& t, const io::signals::Catalogue& cat) {
  KpiSpec k;
  k.location = t.location("name");
  k.name = t.string("name");
  if (k.name.empty()) throw t.error("name", "'name' must not be empty");
  if (!t.has("kind"))
    throw t.error("kind", "'kind' is required (peak_abs, loop_width, gradient, residual_fraction)");
  const std::string kind =
      t.choice("kind", "", {"peak_abs", "loop_width", "gradient", "residual_fraction"});
  const auto* kn = std::find_if(std::begin(kKinds), std::end(kKinds),
                                [&](const KindName& n) { return kind == n.name; });
  k.kind = kn->kind;
  const io::signals::Entry& y = output(t, cat, "signal", k.signal_name);
  k.signal = y.binding;
  std::string x_unit;
  if (kn->needs_versus) {
    if (!t.has("versus"))
      throw t.error("versus", "kind = \"" + kind + "\" needs 'versus' (the x signal)");
    const io::signals::Entry& x = output(t, cat, "versus", k.versus_name);
    k.versus = x.binding;
    x_unit = x.unit;
    k.at = t.number("at", 0.0);
  }
  if (k.kind == KpiKind::kGradient) k.band = t.number_in("band", 1e-300, 1e300);
  k.from_s = t.number_in("from_s", 0.0, 0.0, 1e9);
  k.to_s = t.number_in("to_s", 1e300, 0.0, 1e300);
  if (!(k.from_s < k.to_s)) throw t.error("to_s", "'to_s' must be greater than 'from_s'");
  if (k.kind == KpiKind::kResidualFraction && (!t.has("from_s") || !t.has("to_s")))
    throw t.error("to_s", "kind = \"residual_fraction\" needs 'from_s' (the reference) and 'to_s'");
  if (t.has("min")) k.min = t.number("min");
  if (t.has("max")) k.max = t.number("max");
  if (k.min && k.max && *k.min > *k.max) throw t.error("max", "'min' must not exceed 'max'");
  k.unit = t.string("unit", derived_unit(k.kind, y.unit, x_unit));
  t.finish();
  return k;
}

}  // namespace

std::vector<KpiSpec> read_kpis(io::config::StrictTable& top, const io::signals::Catalogue& cat) {
  std::vector<KpiSpec> out;
  if (!top.has("kpi")) return out;
  for (auto& t : top.tables("kpi", 64)) {
    KpiSpec k = read_kpi(t, cat);
    for (const auto& other : out) {
      if (other.name == k.name)
        throw t.error("name",
                      "duplicate kpi name '" + k.name + "' (first at " + other.location + ")");
    }
    out.push_back(std::move(k));
  }
  return out;
}

}  // namespace rig::kpi
