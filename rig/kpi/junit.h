#pragma once
/// @file
/// The KPIs as JUnit XML, so that CI servers show each maneuver as a test suite and each KPI as
/// a test case (`rig run --junit FILE`, `rig sweep`'s DIR/junit.xml). The shape is the common
/// (Ant) JUnit schema's, the strictest one CI servers read:
///
///   <testsuites name tests failures errors time>
///     <testsuite id package name timestamp hostname tests failures errors time>  one per run
///       <properties><property name value/>...</properties>   config, each --set, stop reason
///       <testcase name classname time>                       one per KPI
///         <failure message type="kpi">...</failure>          outside its limits, or no value
///         <error message type="run">...</error>              the run itself failed (exit 1)
///       </testcase>
///       <system-out>one line per KPI</system-out>
///       <system-err>the run's failure, if any</system-err>
///     </testsuite>
///   </testsuites>
///
/// timestamp is ISO 8601 without a zone (UTC), time in seconds.

#include <string>
#include <utility>
#include <vector>

#include "rig/kpi/kpi_recorder.h"

namespace rig::kpi {

/// One run: a <testsuite>.
struct JunitSuite {
  std::string name;       ///< the suite (a maneuver file's stem, a sweep's run id)
  std::string package;    ///< the testcases' classname prefix ("rig" or the sweep's name)
  std::string timestamp;  ///< the run's start, "YYYY-MM-DDTHH:MM:SS" (UTC)
  std::string hostname;
  double time_s = 0.0;  ///< the run's wall time
  std::vector<std::pair<std::string, std::string>> properties;
  std::vector<KpiResult> kpis;
  std::string run_error;  ///< "" if the run ended as asked; else every KPI is an <error>
};

/// `<testsuites>` holding one `<testsuite>` per run, with the XML declaration.
std::string junit_xml(const std::vector<JunitSuite>& suites, const std::string& name = "rig");

/// "0.431 s outside [-, 0.35]", "0.2 s within [-, 0.25]", or "no value (...)".
std::string kpi_verdict(const KpiResult& k);

/// "YYYY-MM-DDTHH:MM:SS" of a CLOCK_REALTIME time in ns (UTC), and this machine's host name.
std::string junit_timestamp(long long realtime_ns);
std::string host_name();

}  // namespace rig::kpi
