#include "rig/kpi/kpi_recorder.h"

#include <cmath>
#include <limits>
#include <utility>

#include "rig/json_text.h"
#include "rig/kpi/steering_kpis.h"
#include "rig/kpi/step_response_kpis.h"

namespace rig::kpi {

namespace {

/// The value of one KPI kind over its series (NaN: no answer).
double value_of(const KpiSpec& spec, const Series& s) {
  switch (spec.kind) {
    case KpiKind::kPeakAbs:
      return peak_abs(s.y);
    case KpiKind::kLoopWidth:
      return loop_width(s.x, s.y, spec.at);
    case KpiKind::kGradient:
      return gradient(s.x, s.y, spec.at, spec.band);
    case KpiKind::kResidualFraction:
      return residual_fraction(s.time_s, s.y, spec.from_s, spec.to_s);
    case KpiKind::kResponseTime:
      return step_response(s.time_s, s.y, s.x, spec.steady_s, spec.fraction).response_time_s;
    case KpiKind::kPeakResponseTime:
      return step_response(s.time_s, s.y, s.x, spec.steady_s, 0.9).peak_response_time_s;
    case KpiKind::kOvershoot:
      return step_response(s.time_s, s.y, s.x, spec.steady_s, 0.9).overshoot;
    case KpiKind::kSteadyGain:
      return step_response(s.time_s, s.y, s.x, spec.steady_s, 0.9).steady_gain;
    case KpiKind::kUndersteerGradient:
      return understeer_gradient(s.time_s, s.y, s.x, s.aux, spec.circle);
    case KpiKind::kBrakingDistance:
    case KpiKind::kMeanDeceleration: {
      const auto from = brake_point(s.x, spec.threshold, s.y.size());
      if (!from) return std::numeric_limits<double>::quiet_NaN();
      return spec.kind == KpiKind::kBrakingDistance
                 ? braking_distance(s.time_s, s.y, *from, spec.stop_mps)
                 : mean_deceleration(s.time_s, s.y, *from);
    }
    case KpiKind::kLanesKept:
      return lanes_kept(spec.track, s.x, s.y, s.aux);
    case KpiKind::kConesHit:
      return cones_hit(spec.track, s.x, s.y, s.aux);
  }
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

KpiResult evaluate(const KpiSpec& spec, const Series& s) {
  KpiResult r{spec.name, spec.unit, value_of(spec, s), spec.min, spec.max, false};
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
    if (spec.records_versus) s.x.push_back(spec.versus.value(view));
    if (spec.records_aux) s.aux.push_back(spec.aux.value(view));
  }
}

std::vector<KpiResult> KpiRecorder::results() const {
  std::vector<KpiResult> out;
  for (std::size_t k = 0; k < specs_.size(); ++k) out.push_back(evaluate(specs_[k], series_[k]));
  return out;
}

}  // namespace rig::kpi
