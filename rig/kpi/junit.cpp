#include "rig/kpi/junit.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <ctime>

namespace rig::kpi {
namespace {

/// Text and attribute values: the five XML entities; other control characters are not allowed
/// in XML 1.0 and become spaces.
std::string xml(const std::string& s) {
  std::string out;
  for (const char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t' ? ' ' : c;
    }
  }
  return out;
}

std::string number(double v) {
  if (!std::isfinite(v)) return "none";
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

std::string seconds(double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.3f", std::isfinite(v) && v > 0 ? v : 0.0);
  return buf;
}

int failures(const JunitSuite& s) {
  if (!s.run_error.empty()) return 0;
  int n = 0;
  for (const auto& k : s.kpis) n += k.passed ? 0 : 1;
  return n;
}

int errors(const JunitSuite& s) {
  return s.run_error.empty() ? 0 : static_cast<int>(s.kpis.size());
}

std::string testcase(const JunitSuite& s, const KpiResult& k) {
  std::string j = "    <testcase name=\"" + xml(k.name) + "\" classname=\"" +
                  xml(s.package + "." + s.name) + "\" time=\"0\"";
  if (!s.run_error.empty())
    return j + ">\n      <error message=\"" + xml("run failed: " + s.run_error) +
           "\" type=\"run\">" + xml(kpi_verdict(k)) + "</error>\n    </testcase>\n";
  if (k.passed) return j + "/>\n";
  return j + ">\n      <failure message=\"" + xml(kpi_verdict(k)) + "\" type=\"kpi\">" +
         xml(k.name + " = " + kpi_verdict(k)) + "</failure>\n    </testcase>\n";
}

std::string testsuite(const JunitSuite& s, std::size_t id) {
  std::string j = "  <testsuite id=\"" + std::to_string(id) + "\" package=\"" + xml(s.package) +
                  "\" name=\"" + xml(s.name) + "\" timestamp=\"" + xml(s.timestamp) +
                  "\" hostname=\"" + xml(s.hostname.empty() ? "localhost" : s.hostname) +
                  "\" tests=\"" + std::to_string(s.kpis.size()) + "\" failures=\"" +
                  std::to_string(failures(s)) + "\" errors=\"" + std::to_string(errors(s)) +
                  "\" time=\"" + seconds(s.time_s) + "\">\n    <properties>\n";
  for (const auto& [name, value] : s.properties)
    j += "      <property name=\"" + xml(name) + "\" value=\"" + xml(value) + "\"/>\n";
  j += "    </properties>\n";
  std::string out;
  for (const auto& k : s.kpis) {
    j += testcase(s, k);
    out += k.name + " = " + kpi_verdict(k) + "\n";
  }
  return j + "    <system-out>" + xml(out) + "</system-out>\n    <system-err>" + xml(s.run_error) +
         "</system-err>\n  </testsuite>\n";
}

}  // namespace

std::string kpi_verdict(const KpiResult& k) {
  if (!std::isfinite(k.value)) return "no value (the run gave no answer)";
  return number(k.value) + " " + k.unit + (k.passed ? " within [" : " outside [") +
         (k.min ? number(*k.min) : "-") + ", " + (k.max ? number(*k.max) : "-") + "]";
}

std::string junit_xml(const std::vector<JunitSuite>& suites, const std::string& name) {
  std::size_t tests = 0;
  int fail = 0, err = 0;
  double time_s = 0.0;
  for (const auto& s : suites) {
    tests += s.kpis.size();
    fail += failures(s);
    err += errors(s);
    time_s += std::isfinite(s.time_s) ? s.time_s : 0.0;
  }
  std::string j = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"" + xml(name) +
                  "\" tests=\"" + std::to_string(tests) + "\" failures=\"" + std::to_string(fail) +
                  "\" errors=\"" + std::to_string(err) + "\" time=\"" + seconds(time_s) + "\">\n";
  for (std::size_t i = 0; i < suites.size(); ++i) j += testsuite(suites[i], i);
  return j + "</testsuites>\n";
}

std::string junit_timestamp(long long realtime_ns) {
  const auto t = static_cast<std::time_t>(realtime_ns / 1'000'000'000LL);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%S", &tm);
  return buf;
}

std::string host_name() {
  char buf[256] = {};
  if (::gethostname(buf, sizeof buf - 1) != 0 || buf[0] == '\0') return "localhost";
  return buf;
}

}  // namespace rig::kpi
