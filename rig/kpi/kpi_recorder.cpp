#include "rig/kpi/kpi_recorder.h"

#include <cmath>
#include <utility>

#include "rig/json_text.h"
#include "rig/kpi/steering_kpis.h"

namespace rig::kpi {

KpiResult evaluate(const KpiSpec& spec, const Series& s) {
  KpiResult r{spec.name, spec.unit, 0.0, spec.min, spec.max, false};
  switch (spec.kind) {
    case KpiKind::kPeakAbs:
      r.value = peak_abs(s.y);
      break;
    case KpiKind::kLoopWidth:
      r.value = loop_width(s.x, s.y, spec.at);
      break;
    case KpiKind::kGradient:
      r.value = gradient(s.x, s.y, spec.at, spec.band);
      break;
    case KpiKind::kResidualFraction:
      r.value = residual_fraction(s.time_s, s.y, spec.from_s, spec.to_s);
      break;
  }
  r.passed =
      std::isfinite(r.value) && (!r.min || r.value >= *r.min) && (!r.max || r.value <= *r.max);
  return r;
}

std::string kpis_json(const std::vector<KpiResult>& results) {
  std::string j = "[";
  for (std::size_t i = 0; i < results.size(); ++i) {
    const KpiResult& r = results[i];
    j += std::string(i == 0 ? "\n    " : ",\n    ") + "{\"name\": " + json_string(r.name) +
         ", \"value\": " + json_number(r.value, "%.9g") + ", \"unit\": " + json_string(r.unit) +
         ", \"limits\": {\"min\": " + (r.min ? json_number(*r.min, "%.9g") : "null") +
         ", \"max\": " + (r.max ? json_number(*r.max, "%.9g") : "null") +
         "}, \"passed\": " + (r.passed ? "true" : "false") + "}";
  }
  return j + (results.empty() ? "]" : "\n  ]");
}

KpiRecorder::KpiRecorder(std::vector<KpiSpec> specs)
    : specs_(std::move(specs)), series_(specs_.size()) {}

void KpiRecorder::start(const io::RunInfo& /*info*/) {
  for (auto& s : series_) s = Series{};
}

void KpiRecorder::consume(const io::Snapshot& snapshot, std::uint64_t /*dropped_before*/) {
  const double t = snapshot.timing.sim_time_s;
  const io::signals::CycleView view{snapshot.signals, snapshot.report};
  for (std::size_t k = 0; k < specs_.size(); ++k) {
    const KpiSpec& spec = specs_[k];
    // half a period of slack: the window's ends are sampled
    if (t < spec.from_s - 5e-4 || t > spec.to_s + 5e-4) continue;
    Series& s = series_[k];
    s.time_s.push_back(t);
    s.y.push_back(spec.signal.value(view));
    if (spec.kind == KpiKind::kLoopWidth || spec.kind == KpiKind::kGradient)
      s.x.push_back(spec.versus.value(view));
  }
}

std::vector<KpiResult> KpiRecorder::results() const {
  std::vector<KpiResult> out;
  for (std::size_t k = 0; k < specs_.size(); ++k) out.push_back(evaluate(specs_[k], series_[k]));
  return out;
}

}  // namespace rig::kpi
