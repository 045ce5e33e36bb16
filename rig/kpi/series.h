#pragma once
/// @file
/// A recorded time series of catalogue signals: what the KPIs are computed from.

#include <cstddef>
#include <vector>

namespace rig::kpi {

struct Series {
  std::vector<double> time_s;
  std::vector<double> y;    ///< the KPI's signal
  std::vector<double> x;    ///< its versus signal (empty if none)
  std::vector<double> aux;  ///< a third signal (empty if none)
};

}  // namespace rig::kpi
