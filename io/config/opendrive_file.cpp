#include "io/config/opendrive_file.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include <pugixml.hpp>

#include "io/config/config_error.h"
#include "io/config/input_file.h"
#include "model/road/opendrive_reference_line.h"

namespace rig::io::config {

namespace {

using model::road::OpenDriveGeometry;
using model::road::OpenDriveGeometryKind;
using model::road::OpenDrivePolynomial;
using model::road::OpenDriveRoad;

/// OpenDRIVE files of whole road networks are larger than configurations.
constexpr std::size_t kMaxOpenDriveBytes = std::size_t{64} << 20;  // 64 MiB
/// A radius below 0.1 m is no road (and would need millions of projection samples).
constexpr double kMaxCurvature_1pm = 10.0;
constexpr double kGap_m = 1e-3;
constexpr double kKink_rad = 1e-3;

std::string format(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

/// Element lines from pugixml's offsets, messages and strict attribute numbers.
class Reader {
 public:
  Reader(std::filesystem::path file, const std::string& text)
      : file_(std::move(file)), size_(text.size()) {
    line_starts_.push_back(0);
    for (std::size_t i = 0; i < text.size(); ++i) {
      if (text[i] == '\n') line_starts_.push_back(i + 1);
    }
  }

  [[nodiscard]] int line_at(std::ptrdiff_t offset) const {
    if (offset < 0) return 1;
    // an error at the end of the text is on its last line, not after its final newline
    const std::size_t at = std::min(static_cast<std::size_t>(offset), size_ > 0 ? size_ - 1 : 0);
    const auto it = std::upper_bound(line_starts_.begin(), line_starts_.end(), at);
    return static_cast<int>(it - line_starts_.begin());
  }
  [[nodiscard]] int line(const pugi::xml_node& node) const { return line_at(node.offset_debug()); }
  [[nodiscard]] std::string where(const pugi::xml_node& node) const {
    return file_.string() + ":" + std::to_string(line(node));
  }
  [[nodiscard]] ConfigError error(const pugi::xml_node& node, const std::string& what) const {
    return ConfigError(where(node) + ": <" + node.name() + "> " + what);
  }
  void warn(const pugi::xml_node& node, const std::string& what) {
    warnings.push_back(where(node) + ": " + what);
  }

  /// A required attribute that is a finite number.
  [[nodiscard]] double number(const pugi::xml_node& node, const char* name) const {
    const pugi::xml_attribute a = node.attribute(name);
    if (!a) throw error(node, std::string("has no attribute ") + name);
    std::string_view text = a.value();
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front())) != 0)
      text.remove_prefix(1);
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back())) != 0)
      text.remove_suffix(1);
    if (text.starts_with('+')) text.remove_prefix(1);  // xsd:double allows a leading '+'
    double v = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || end != text.data() + text.size() || text.empty())
      throw error(node, std::string(name) + " = \"" + a.value() + "\" is not a number");
    if (!std::isfinite(v))
      throw error(node, std::string(name) + " = \"" + a.value() + "\" is not a finite number");
    return v;
  }
  [[nodiscard]] double number_in(const pugi::xml_node& node, const char* name, double min,
                                 double max) const {
    const double v = number(node, name);
    if (!(v >= min && v <= max))
      throw error(node, std::string(name) + " = " + format(v) + " is outside [" + format(min) +
                            ", " + format(max) + "]");
    return v;
  }

  std::vector<std::string> warnings;

 private:
  std::filesystem::path file_;
  std::size_t size_ = 0;
  std::vector<std::size_t> line_starts_;
};

/// The zero-tangent check of a paramPoly3: |(u'(p), v'(p))| > 0 along it (else no heading).
void check_param_poly3(const Reader& r, const pugi::xml_node& node, const OpenDriveGeometry& g) {
  const double p_end = g.p_normalized ? 1.0 : g.length_m;
  for (int k = 0; k <= 64; ++k) {
    const double p = p_end * k / 64.0;
    const double du = g.bu + p * (2.0 * g.cu + p * 3.0 * g.du);
    const double dv = g.bv + p * (2.0 * g.cv + p * 3.0 * g.dv);
    if (std::hypot(du, dv) <= 1e-9)
      throw r.error(node, "has no tangent at p = " + format(p) + " (u' = v' = 0)");
  }
}

void read_shape(Reader& r, const pugi::xml_node& shape, OpenDriveGeometry& g) {
  const std::string_view name = shape.name();
  if (name == "line") {
    g.kind = OpenDriveGeometryKind::kLine;
  } else if (name == "arc") {
    g.kind = OpenDriveGeometryKind::kArc;
    g.curvature_1pm = r.number_in(shape, "curvature", -kMaxCurvature_1pm, kMaxCurvature_1pm);
  } else if (name == "spiral") {
    g.kind = OpenDriveGeometryKind::kSpiral;
    g.curv_start_1pm = r.number_in(shape, "curvStart", -kMaxCurvature_1pm, kMaxCurvature_1pm);
    g.curv_end_1pm = r.number_in(shape, "curvEnd", -kMaxCurvature_1pm, kMaxCurvature_1pm);
  } else if (name == "poly3") {
    g.kind = OpenDriveGeometryKind::kPoly3;
    g.a = r.number(shape, "a");
    g.b = r.number(shape, "b");
    g.c = r.number(shape, "c");
    g.d = r.number(shape, "d");
  } else {
    g.kind = OpenDriveGeometryKind::kParamPoly3;
    double* const coefficients[] = {&g.au, &g.bu, &g.cu, &g.du, &g.av, &g.bv, &g.cv, &g.dv};
    const char* const names[] = {"aU", "bU", "cU", "dU", "aV", "bV", "cV", "dV"};
    for (std::size_t i = 0; i < 8; ++i) *coefficients[i] = r.number(shape, names[i]);
    const pugi::xml_attribute range = shape.attribute("pRange");
    const std::string_view value = range.value();
    if (!range) {
      r.warn(shape, "<paramPoly3> has no pRange: taken as \"normalized\" (p in [0, 1])");
    } else if (value != "normalized" && value != "arcLength") {
      throw r.error(shape, "pRange = \"" + std::string(value) +
                               "\": expected \"arcLength\" or \"normalized\"");
    }
    g.p_normalized = value != "arcLength";
    check_param_poly3(r, shape, g);
  }
}

OpenDriveGeometry read_geometry(Reader& r, const pugi::xml_node& node) {
  OpenDriveGeometry g;
  g.s_m = r.number_in(node, "s", 0.0, 1e9);
  g.x_m = r.number(node, "x");
  g.y_m = r.number(node, "y");
  g.hdg_rad = r.number(node, "hdg");
  g.length_m = r.number_in(node, "length", 0.0, 1e7);
  pugi::xml_node shape;
  int shapes = 0;
  for (const pugi::xml_node child : node.children()) {
    const std::string_view name = child.name();
    if (name == "line" || name == "arc" || name == "spiral" || name == "poly3" ||
        name == "paramPoly3") {
      shape = child;
      ++shapes;
    }
  }
  if (shapes != 1) {
    throw r.error(node, shapes == 0 ? "has no shape: expected one of <line>, <arc>, <spiral>, "
                                      "<poly3>, <paramPoly3>"
                                    : "has " + std::to_string(shapes) + " shapes: expected one");
  }
  read_shape(r, shape, g);
  return g;
}

/// Records (<elevation>, <superelevation>) under `parent`, in increasing s.
std::vector<OpenDrivePolynomial> read_records(Reader& r, const pugi::xml_node& parent,
                                              const char* name) {
  std::vector<OpenDrivePolynomial> out;
  for (const pugi::xml_node node : parent.children(name)) {
    if (out.size() == kMaxOpenDriveRecords)
      throw r.error(node, "more than " + std::to_string(kMaxOpenDriveRecords) + " records");
    OpenDrivePolynomial p;
    p.s_m = r.number_in(node, "s", 0.0, 1e9);
    p.a = r.number(node, "a");
    p.b = r.number(node, "b");
    p.c = r.number(node, "c");
    p.d = r.number(node, "d");
    if (!out.empty() && p.s_m < out.back().s_m)
      throw r.error(node, "s = " + format(p.s_m) + " before the previous record's s = " +
                              format(out.back().s_m) + ": records go in increasing s");
    out.push_back(p);
  }
  return out;
}

double wrap(double angle) { return std::remainder(angle, 2.0 * std::numbers::pi); }

/// Gaps and kinks between consecutive geometries of positive length (warnings: each geometry's
/// own start is used).
void check_continuity(Reader& r, const std::vector<OpenDriveGeometry>& plan,
                      const std::vector<pugi::xml_node>& nodes) {
  std::size_t previous = plan.size();
  for (std::size_t i = 0; i < plan.size(); ++i) {
    if (plan[i].length_m == 0) continue;
    if (previous == plan.size()) {
      previous = i;
      continue;
    }
    const OpenDriveGeometry& a = plan[previous];
    const OpenDriveGeometry& b = plan[i];
    previous = i;
    int element = 0;
    const auto end = model::road::OpenDriveReferenceLine({a}).pose(a.s_m + a.length_m, element);
    const auto start = model::road::OpenDriveReferenceLine({b}).pose(b.s_m, element);
    const double gap = std::hypot(start.x_m - end.x_m, start.y_m - end.y_m);
    const double kink = std::abs(wrap(start.hdg_rad - end.hdg_rad));
    const double s_gap = b.s_m - (a.s_m + a.length_m);
    if (gap > kGap_m || kink > kKink_rad || std::abs(s_gap) > kGap_m) {
      r.warn(nodes[i], "<geometry> at s = " + format(b.s_m) + " starts " + format(gap) + " m and " +
                           format(kink) + " rad from the end of the previous one (s off by " +
                           format(s_gap) + " m); its own start is used");
    }
  }
}

std::vector<OpenDriveGeometry> read_plan_view(Reader& r, const pugi::xml_node& road) {
  const pugi::xml_node plan = road.child("planView");
  if (!plan) throw r.error(road, "has no <planView>");
  std::vector<OpenDriveGeometry> out;
  std::vector<pugi::xml_node> nodes;
  for (const pugi::xml_node node : plan.children("geometry")) {
    if (out.size() == kMaxOpenDriveRecords)
      throw r.error(node, "more than " + std::to_string(kMaxOpenDriveRecords) + " geometries");
    OpenDriveGeometry g = read_geometry(r, node);
    if (!out.empty() && g.s_m < out.back().s_m)
      throw r.error(node, "s = " + format(g.s_m) + " before the previous geometry's s = " +
                              format(out.back().s_m) + ": geometries go in increasing s");
    if (g.length_m == 0) r.warn(node, "<geometry> of length 0: skipped");
    out.push_back(g);
    nodes.push_back(node);
  }
  if (std::none_of(out.begin(), out.end(), [](const auto& g) { return g.length_m > 0; }))
    throw r.error(plan, "has no <geometry> of positive length");
  check_continuity(r, out, nodes);
  return out;
}

OpenDriveRoad read_road(Reader& r, const pugi::xml_node& node) {
  OpenDriveRoad road;
  const pugi::xml_attribute id = node.attribute("id");
  if (!id) throw r.error(node, "has no attribute id");
  road.id = id.value();
  road.length_m = r.number_in(node, "length", 0.0, 1e9);
  road.plan_view = read_plan_view(r, node);
  road.elevation = read_records(r, node.child("elevationProfile"), "elevation");
  const pugi::xml_node lateral = node.child("lateralProfile");
  road.superelevation = read_records(r, lateral, "superelevation");
  for (const char* ignored : {"shape", "crossfall"}) {
    if (lateral.child(ignored))
      r.warn(lateral.child(ignored), std::string("road ") + road.id + ": <" + ignored +
                                         "> is not applied (contact uses the superelevation)");
  }
  const OpenDriveGeometry& last = road.plan_view.back();
  const double end = last.s_m + last.length_m;
  if (std::abs(end - road.length_m) > kGap_m) {
    r.warn(node, "road " + road.id + ": length = " + format(road.length_m) +
                     " but the plan view ends at s = " + format(end) + " (which is used)");
  }
  return road;
}

}  // namespace

OpenDriveFile load_opendrive_file(const std::filesystem::path& file) {
  const std::string text = read_input_file(file, kMaxOpenDriveBytes);
  Reader r(file, text);
  pugi::xml_document doc;
  const pugi::xml_parse_result parsed = doc.load_buffer(text.data(), text.size());
  if (!parsed) {
    throw ConfigError(file.string() + ":" + std::to_string(r.line_at(parsed.offset)) +
                      ": not well-formed XML: " + parsed.description());
  }
  const pugi::xml_node root = doc.document_element();
  if (std::string_view(root.name()) != "OpenDRIVE") {
    throw ConfigError(r.where(root) + ": not an OpenDRIVE file: the root element is <" +
                      root.name() + ">, not <OpenDRIVE>");
  }
  OpenDriveFile out;
  out.path = file;
  for (const pugi::xml_node node : root.children("road")) {
    if (out.roads.size() == kMaxOpenDriveRecords)
      throw r.error(node, "more than " + std::to_string(kMaxOpenDriveRecords) + " roads");
    OpenDriveRoad road = read_road(r, node);
    for (std::size_t i = 0; i < out.roads.size(); ++i) {
      if (out.roads[i].id == road.id)
        throw r.error(node, "id \"" + road.id + "\" is already the id of the road at line " +
                                std::to_string(out.road_lines[i]));
    }
    out.roads.push_back(std::move(road));
    out.road_lines.push_back(r.line(node));
  }
  if (out.roads.empty()) throw r.error(root, "has no <road>");
  out.warnings = std::move(r.warnings);
  return out;
}

const model::road::OpenDriveRoad& select_road(const OpenDriveFile& file, std::string_view road_id) {
  if (road_id.empty()) return file.roads.front();
  for (const auto& road : file.roads) {
    if (road.id == road_id) return road;
  }
  std::string ids;
  for (std::size_t i = 0; i < file.roads.size() && i < 20; ++i)
    ids += (i == 0 ? "" : ", ") + ("\"" + file.roads[i].id + "\"");
  if (file.roads.size() > 20) ids += ", ...";
  throw ConfigError(file.path.string() + ":" + std::to_string(file.road_lines.front()) +
                    ": no <road> with id \"" + std::string(road_id) + "\" (the file has " + ids +
                    ")");
}

std::shared_ptr<const model::road::OpenDriveSurface> make_opendrive_surface(
    const OpenDriveFile& file, std::string_view road_id, const model::road::Placement& placement) {
  const OpenDriveRoad& road = select_road(file, road_id);
  const auto index = static_cast<std::size_t>(&road - file.roads.data());
  try {
    return std::make_shared<const model::road::OpenDriveSurface>(road, placement);
  } catch (const std::invalid_argument& e) {
    throw ConfigError(file.path.string() + ":" + std::to_string(file.road_lines[index]) +
                      ": road " + road.id + ": " + e.what());
  }
}

}  // namespace rig::io::config
