// The .xodr reader: the hand-written test file's numbers read back exactly, each geometry ending
// where the file's next one starts (those starts were computed independently: closed forms,
// the clothoid series, Simpson's rule), heights at known (x, y) of the file's roads against
// hand values, and every malformed input as a `file:line:` error or a warning.
#include "io/config/opendrive_file.h"

#include <cmath>
#include <fstream>
#include <functional>
#include <numbers>

#include <gtest/gtest.h>

#include "io/config/config_error.h"
#include "model/road/opendrive_surface.h"

namespace rig::io::config {
namespace {

using model::road::OpenDriveGeometryKind;

const std::filesystem::path kTrack =
    std::filesystem::path(RIG_SOURCE_DIR) / "tests/io/config/opendrive/test_track.xodr";

std::filesystem::path write_file(const std::string& name, const std::string& text) {
  auto path = std::filesystem::temp_directory_path() / name;
  std::ofstream(path) << text;
  return path;
}

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "(no error)";
}

/// A file with one road whose plan view is `geometries` (and `more` after the plan view).
std::string road_file(const std::string& geometries, const std::string& more = "") {
  return "<?xml version=\"1.0\"?>\n<OpenDRIVE>\n<header revMajor=\"1\" revMinor=\"7\"/>\n"
         "<road id=\"7\" length=\"10\" junction=\"-1\">\n<planView>\n" +
         geometries + "</planView>\n" + more + "</road>\n</OpenDRIVE>\n";
}

const std::string kLine10 =
    "<geometry s=\"0\" x=\"0\" y=\"0\" hdg=\"0\" length=\"10\"><line/></geometry>\n";

TEST(OpenDriveFile, ReadsTheTestTrackAsWritten) {
  const OpenDriveFile file = load_opendrive_file(kTrack);
  ASSERT_EQ(file.roads.size(), 2u);
  EXPECT_TRUE(file.warnings.empty()) << file.warnings.front();
  const auto& track = file.roads[0];
  EXPECT_EQ(track.id, "1");
  EXPECT_EQ(track.length_m, 225.0);
  ASSERT_EQ(track.plan_view.size(), 7u);
  const OpenDriveGeometryKind kinds[] = {
      OpenDriveGeometryKind::kLine,       OpenDriveGeometryKind::kSpiral,
      OpenDriveGeometryKind::kArc,        OpenDriveGeometryKind::kSpiral,
      OpenDriveGeometryKind::kParamPoly3, OpenDriveGeometryKind::kPoly3,
      OpenDriveGeometryKind::kLine};
  for (std::size_t i = 0; i < 7; ++i) EXPECT_EQ(track.plan_view[i].kind, kinds[i]) << i;
  EXPECT_EQ(track.plan_view[2].x_m, 69.7311226663308);
  EXPECT_EQ(track.plan_view[2].curvature_1pm, 0.02);
  EXPECT_EQ(track.plan_view[3].curv_start_1pm, 0.02);
  EXPECT_EQ(track.plan_view[4].dv, -0.00002);
  EXPECT_FALSE(track.plan_view[4].p_normalized);
  EXPECT_EQ(track.plan_view[5].d, 0.00002);
  ASSERT_EQ(track.elevation.size(), 4u);
  EXPECT_EQ(track.elevation[2].a, 1.8);
  EXPECT_EQ(track.elevation[2].c, -0.0005);
  ASSERT_EQ(track.superelevation.size(), 5u);
  EXPECT_EQ(track.superelevation[1].b, 0.0016666666666666668);
  EXPECT_EQ(&select_road(file, ""), &file.roads[0]);
  EXPECT_EQ(&select_road(file, "2"), &file.roads[1]);
  EXPECT_EQ(message_of([&] { (void)select_road(file, "9"); }),
            kTrack.string() + ":8: no <road> with id \"9\" (the file has \"1\", \"2\")");
}

TEST(OpenDriveFile, EachGeometryEndsWhereTheFileStartsTheNext) {
  const OpenDriveFile file = load_opendrive_file(kTrack);
  const auto& plan = file.roads[0].plan_view;
  for (std::size_t i = 0; i + 1 < plan.size(); ++i) {
    int element = 0;
    const auto end = model::road::OpenDriveReferenceLine({plan[i]}).pose(
        plan[i].s_m + plan[i].length_m, element);
    EXPECT_NEAR(end.x_m, plan[i + 1].x_m, 1e-9) << "geometry " << i;
    EXPECT_NEAR(end.y_m, plan[i + 1].y_m, 1e-9) << "geometry " << i;
    EXPECT_NEAR(end.hdg_rad, plan[i + 1].hdg_rad, 1e-12) << "geometry " << i;
  }
}

TEST(OpenDriveFile, HeightsOfTheFilesRoadsAtKnownPoints) {
  const OpenDriveFile file = load_opendrive_file(kTrack);
  const model::road::OpenDriveSurface tilted(select_road(file, "2"), {});
  // road "2": from (10, 5) at heading 0.3; z = 1 + 0.05 s + t tan(0.04)
  model::road::SurfaceHint hint;
  const double x = 50, y = 20;
  const double s = 40 * std::cos(0.3) + 15 * std::sin(0.3);
  const double t = -40 * std::sin(0.3) + 15 * std::cos(0.3);
  EXPECT_NEAR(tilted.height(x, y, hint).z_m, 1 + 0.05 * s + t * std::tan(0.04), 1e-12);
  // road "1" on its arc (centre 50 m left of the arc's start at heading 0.3): the point 47 m
  // from the centre at the angle of s = 90 is t = 3 left of it; z = 0.0005 (90 - 40)^2 +
  // 3 tan(0.05)
  const model::road::OpenDriveSurface track(select_road(file, "1"), {});
  const double cx = 69.7311226663308 - 50 * std::sin(0.3);
  const double cy = 2.9807694262868845 + 50 * std::cos(0.3);
  const double phi = 0.3 + 20.0 / 50.0;
  const double px = cx + 47 * std::sin(phi), py = cy - 47 * std::cos(phi);
  model::road::SurfaceHint h2;
  EXPECT_NEAR(track.height(px, py, h2).z_m, 0.0005 * 2500 + 3 * std::tan(0.05), 1e-9);
}

TEST(OpenDriveFile, MalformedXmlIsAnErrorAtItsLine) {
  const auto f = write_file("bad1.xodr",
                            "<?xml version=\"1.0\"?>\n<OpenDRIVE>\n<road id=\"1\"\n"
                            "  length=\"1\">\n<planView></road>\n</OpenDRIVE>\n");
  EXPECT_EQ(message_of([&] { (void)load_opendrive_file(f); }),
            f.string() + ":5: not well-formed XML: Start-end tags mismatch");
  const auto g = write_file("bad2.xodr", "just text\n");
  EXPECT_EQ(message_of([&] { (void)load_opendrive_file(g); }),
            g.string() + ":1: not well-formed XML: No document element found");
  const auto h = write_file("bad3.xodr", "<?xml version=\"1.0\"?>\n<OpenSCENARIO/>\n");
  EXPECT_EQ(message_of([&] { (void)load_opendrive_file(h); }),
            h.string() +
                ":2: not an OpenDRIVE file: the root element is <OpenSCENARIO>, not "
                "<OpenDRIVE>");
  const auto missing = std::filesystem::temp_directory_path() / "no_such_road.xodr";
  EXPECT_NE(message_of([&] { (void)load_opendrive_file(missing); }).find("no_such_road.xodr:1:"),
            std::string::npos);
}

struct BadCase {
  std::string name;
  std::string text;
  std::string message;  // after "FILE:"
};

TEST(OpenDriveFile, BadContentIsAnErrorAtTheElementsLine) {
  const std::vector<BadCase> cases{
      {"no_road", "<OpenDRIVE>\n<header/>\n</OpenDRIVE>\n", "1: <OpenDRIVE> has no <road>"},
      {"no_plan", "<OpenDRIVE>\n<road id=\"1\" length=\"1\">\n</road>\n</OpenDRIVE>\n",
       "2: <road> has no <planView>"},
      {"no_id", "<OpenDRIVE>\n<road length=\"1\">\n</road>\n</OpenDRIVE>\n",
       "2: <road> has no attribute id"},
      {"missing_hdg",
       road_file("<geometry s=\"0\" x=\"0\" y=\"0\" length=\"1\"><line/></geometry>\n"),
       "6: <geometry> has no attribute hdg"},
      {"text_number",
       road_file("<geometry s=\"0\" x=\"0\" y=\"one\" hdg=\"0\" length=\"1\"><line/>"
                 "</geometry>\n"),
       "6: <geometry> y = \"one\" is not a number"},
      {"nan",
       road_file("<geometry s=\"0\" x=\"nan\" y=\"0\" hdg=\"0\" length=\"1\"><line/>"
                 "</geometry>\n"),
       "6: <geometry> x = \"nan\" is not a finite number"},
      {"trailing",
       road_file("<geometry s=\"0\" x=\"1.5m\" y=\"0\" hdg=\"0\" length=\"1\"><line/>"
                 "</geometry>\n"),
       "6: <geometry> x = \"1.5m\" is not a number"},
      {"negative_length",
       road_file("<geometry s=\"0\" x=\"0\" y=\"0\" hdg=\"0\" length=\"-1\">"
                 "<line/></geometry>\n"),
       "6: <geometry> length = -1 is outside [0, 1e+07]"},
      {"two_shapes",
       road_file("<geometry s=\"0\" x=\"0\" y=\"0\" hdg=\"0\" length=\"1\"><line/>"
                 "<arc curvature=\"0.1\"/></geometry>\n"),
       "6: <geometry> has 2 shapes: expected one"},
      {"no_shape",
       road_file("<geometry s=\"0\" x=\"0\" y=\"0\" hdg=\"0\" length=\"1\">"
                 "</geometry>\n"),
       "6: <geometry> has no shape: expected one of <line>, <arc>, <spiral>, <poly3>, "
       "<paramPoly3>"},
      {"tight_arc",
       road_file("<geometry s=\"0\" x=\"0\" y=\"0\" hdg=\"0\" length=\"1\">\n"
                 "<arc curvature=\"20\"/></geometry>\n"),
       "7: <arc> curvature = 20 is outside [-10, 10]"},
      {"spiral_attr",
       road_file("<geometry s=\"0\" x=\"0\" y=\"0\" hdg=\"0\" length=\"1\">\n"
                 "<spiral curvStart=\"0\"/></geometry>\n"),
       "7: <spiral> has no attribute curvEnd"},
      {"prange",
       road_file("<geometry s=\"0\" x=\"0\" y=\"0\" hdg=\"0\" length=\"1\">\n<paramPoly3 "
                 "aU=\"0\" bU=\"1\" cU=\"0\" dU=\"0\" aV=\"0\" bV=\"0\" cV=\"0\" dV=\"0\" "
                 "pRange=\"meters\"/></geometry>\n"),
       "7: <paramPoly3> pRange = \"meters\": expected \"arcLength\" or \"normalized\""},
      {"no_tangent",
       road_file("<geometry s=\"0\" x=\"0\" y=\"0\" hdg=\"0\" length=\"1\">\n"
                 "<paramPoly3 aU=\"0\" bU=\"0\" cU=\"1\" dU=\"0\" aV=\"0\" bV=\"0\" "
                 "cV=\"0\" dV=\"0\" pRange=\"normalized\"/></geometry>\n"),
       "7: <paramPoly3> has no tangent at p = 0 (u' = v' = 0)"},
      {"geometry_order",
       road_file("<geometry s=\"5\" x=\"0\" y=\"0\" hdg=\"0\" length=\"5\"><line/></geometry>\n"
                 "<geometry s=\"0\" x=\"0\" y=\"0\" hdg=\"0\" length=\"5\"><line/></geometry>\n"),
       "7: <geometry> s = 0 before the previous geometry's s = 5: geometries go in increasing s"},
      {"elevation_order",
       road_file(kLine10,
                 "<elevationProfile>\n<elevation s=\"5\" a=\"0\" b=\"0\" c=\"0\" d=\"0\"/>\n"
                 "<elevation s=\"2\" a=\"0\" b=\"0\" c=\"0\" d=\"0\"/>\n"
                 "</elevationProfile>\n"),
       "10: <elevation> s = 2 before the previous record's s = 5: records go in increasing s"},
      {"superelevation_attr",
       road_file(kLine10,
                 "<lateralProfile>\n<superelevation s=\"0\" a=\"0\" b=\"0\" c=\"0\"/>\n"
                 "</lateralProfile>\n"),
       "9: <superelevation> has no attribute d"},
      {"duplicate_id",
       "<OpenDRIVE>\n<road id=\"1\" length=\"1\"><planView>" + kLine10 +
           "</planView></road>\n<road id=\"1\" length=\"1\"><planView>" + kLine10 +
           "</planView></road>\n</OpenDRIVE>\n",
       "4: <road> id \"1\" is already the id of the road at line 2"},
      {"zero_length_only",
       road_file("<geometry s=\"0\" x=\"0\" y=\"0\" hdg=\"0\" length=\"0\"><line/></geometry>\n"),
       "5: <planView> has no <geometry> of positive length"},
  };
  for (const BadCase& c : cases) {
    const auto f = write_file("bad_" + c.name + ".xodr", c.text);
    EXPECT_EQ(message_of([&] { (void)load_opendrive_file(f); }), f.string() + ":" + c.message)
        << c.name;
  }
}

TEST(OpenDriveFile, ARoadTheModelRefusesIsAnErrorAtItsLine) {
  const auto f =
      write_file("too_long.xodr",
                 road_file("<geometry s=\"0\" x=\"0\" y=\"0\" hdg=\"0\" length=\"2000000\"><line/>"
                           "</geometry>\n"));
  const OpenDriveFile file = load_opendrive_file(f);  // a well-formed file ...
  EXPECT_EQ(message_of([&] { (void)make_opendrive_surface(file, "7", {}); }),
            f.string() +
                ":4: road 7: the reference line is too long for its curvature: 2000201 "
                "projection samples of at most 1000000 (one every 1.000000 m)");
}

TEST(OpenDriveFile, TolerableFlawsAreWarnings) {
  const auto f = write_file(
      "warn.xodr",
      road_file("<geometry s=\"0\" x=\"0\" y=\"0\" hdg=\"0\" length=\"4\"><line/></geometry>\n"
                "<geometry s=\"4\" x=\"4\" y=\"0\" hdg=\"0\" length=\"0\"><line/></geometry>\n"
                "<geometry s=\"4\" x=\"4.5\" y=\"0\" hdg=\"0.01\" length=\"4\">\n"
                "<paramPoly3 aU=\"0\" bU=\"1\" cU=\"0\" dU=\"0\" aV=\"0\" bV=\"0\" cV=\"0\" "
                "dV=\"0\"/></geometry>\n",
                "<lateralProfile>\n<shape s=\"0\" t=\"0\" a=\"0\" b=\"0\" c=\"0\" d=\"0\"/>\n"
                "</lateralProfile>\n"));
  const OpenDriveFile file = load_opendrive_file(f);
  const std::string p = f.string();
  ASSERT_EQ(file.warnings.size(), 5u);
  EXPECT_EQ(file.warnings[0], p + ":7: <geometry> of length 0: skipped");
  EXPECT_EQ(file.warnings[1],
            p + ":9: <paramPoly3> has no pRange: taken as \"normalized\" (p in [0, 1])");
  EXPECT_EQ(file.warnings[2], p + ":8: <geometry> at s = 4 starts 0.5 m and 0.01 rad from the end "
                                  "of the previous one (s off by 0 m); its own start is used");
  EXPECT_EQ(file.warnings[3],
            p + ":12: road 7: <shape> is not applied (contact uses the superelevation)");
  EXPECT_EQ(file.warnings[4],
            p + ":4: road 7: length = 10 but the plan view ends at s = 8 (which is used)");
}

}  // namespace
}  // namespace rig::io::config
