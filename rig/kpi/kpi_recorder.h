#pragma once
/// @file
/// The KPI room's sink: records, on the dispatcher thread, each `[[kpi]]`'s signals over its
/// time window from the snapshots (every cycle that reached the non-RT side), and after the run
/// computes the KPIs for the summary JSON's `kpis` list.

#include <string>
#include <vector>

#include "io/snapshot_sink.h"
#include "rig/kpi/kpi_spec.h"
#include "rig/kpi/series.h"

namespace rig::kpi {

struct KpiResult {
  std::string name;
  std::string unit;
  double value = 0.0;  ///< NaN if the run gave no answer (null in JSON, not passed)
  std::optional<double> min, max;
  bool passed = false;  ///< min <= value <= max for the bounded sides
};

/// Evaluates one KPI over its recorded series.
KpiResult evaluate(const KpiSpec& spec, const Series& series);

/// `[{"name": ..., "value": ..., "unit": ..., "limits": {"min": x|null, "max": x|null},
/// "passed": bool}, ...]`
std::string kpis_json(const std::vector<KpiResult>& results);

class KpiRecorder final : public io::SnapshotSink {
 public:
  explicit KpiRecorder(std::vector<KpiSpec> specs);
  void start(const io::RunInfo& info) override;
  void consume(const io::Snapshot& snapshot, std::uint64_t dropped_before) override;
  void stop() override {}
  /// After the run: every KPI, in file order.
  [[nodiscard]] std::vector<KpiResult> results() const;

 private:
  std::vector<KpiSpec> specs_;
  std::vector<Series> series_;
};

}  // namespace rig::kpi
