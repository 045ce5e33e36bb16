// The OpenCRG reader on ASAM's sample files (../shared/testdata/opencrg, read in place; the
// Belgian block from the repaired copy in the build tree): at every grid node the surface's
// height is the file's number (float32) plus the reference line's slope and banking terms, as
// this test reads the file itself (fixed-width fields, big-endian floats); between nodes the
// bilinear value; KDBI and KRBI copies written here read back the same; malformed files give
// `file:line: what`.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "io/config/config_error.h"
#include "io/config/crg_file.h"
#include "model/road/crg_surface.h"

namespace rig::io::config {
namespace {

namespace fs = std::filesystem;
using model::road::CrgData;
using model::road::CrgSurface;

const fs::path kSamples = RIG_OPENCRG_DIR;
const fs::path kBelgian = RIG_BELGIAN_BLOCK;

/// A sample as this test reads it: header lines, channel names, rows of numbers.
struct Table {
  std::vector<std::string> header;
  std::vector<std::string> channels;
  std::vector<std::vector<double>> rows;
  std::string format = "KRBI";
};

std::string slurp(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

/// Reads the header (up to the $$ record) and the payload with the format's fixed widths.
Table read_table(const fs::path& p) {
  const std::string text = slurp(p);
  Table t;
  std::size_t pos = 0;
  for (;;) {
    const std::size_t end = text.find('\n', pos);
    std::string line = text.substr(pos, end - pos);
    pos = end + 1;
    t.header.push_back(line);
    if (line.rfind("$$", 0) == 0) break;
    if (line.rfind("D:", 0) == 0) t.channels.push_back(line.substr(2, line.find(',') - 2));
    if (line.rfind("#:", 0) == 0) t.format = line.substr(2, 4);
  }
  const std::size_t n = t.channels.size();
  std::vector<double> values;
  if (t.format == "LRFI" || t.format == "LDFI") {
    const std::size_t width = t.format == "LRFI" ? 10 : 20;
    std::istringstream lines(text.substr(pos));
    std::string line;
    while (std::getline(lines, line)) {
      while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
      for (std::size_t f = 0; f * width < line.size(); ++f) {
        const std::string field = line.substr(f * width, width);
        values.push_back(field.find('*') != std::string::npos ? NAN : std::stod(field));
      }
    }
  } else {  // KRBI: big-endian floats
    for (std::size_t b = pos; b + 4 <= text.size(); b += 4) {
      std::uint32_t bits = 0;
      for (int k = 0; k < 4; ++k) bits = (bits << 8) | static_cast<unsigned char>(text[b + k]);
      float f = 0;
      std::memcpy(&f, &bits, 4);
      values.push_back(f);
    }
  }
  for (std::size_t r = 0; (r + 1) * n <= values.size(); ++r)
    t.rows.emplace_back(values.begin() + static_cast<long>(r * n),
                        values.begin() + static_cast<long>((r + 1) * n));
  while (!t.rows.empty() && std::all_of(t.rows.back().begin(), t.rows.back().end(),
                                        [](double v) { return std::isnan(v); }))
    t.rows.pop_back();  // KRBI padding
  return t;
}

int column(const Table& t, const std::string& name) {
  for (std::size_t c = 0; c < t.channels.size(); ++c) {
    if (t.channels[c] == name) return static_cast<int>(c);
  }
  return -1;
}

/// The height the file gives at node (i, j): the grid value (NaN cells: the nearest valid one of
/// the cross section, GRID_NAN_MODE 2), the reference line's integrated slope, banking * v.
double node_height(const Table& t, const CrgData& d, std::size_t i, std::size_t j) {
  std::vector<double> z;
  for (std::size_t c = 0; c < t.channels.size(); ++c) {
    if (t.channels[c].rfind("long section", 0) == 0) z.push_back(t.rows[i][c]);
  }
  std::size_t k = j;
  while (std::isnan(z[k]) && k > 0 && std::isnan(z[k - 1]) == std::isnan(z[k])) --k;
  if (std::isnan(z[k])) {
    k = j;
    while (std::isnan(z[k]) && k + 1 < z.size()) ++k;  // NaN on the right: the first valid
    if (std::isnan(z[k])) {
      k = j;
      while (std::isnan(z[k])) --k;  // NaN on the left: the last valid
    }
  }
  double ref = 0;
  const int slope = column(t, "reference line slope");
  for (std::size_t r = 1; slope >= 0 && r <= i; ++r) ref += t.rows[r][slope] * d.u_increment_m;
  const int bank = column(t, "reference line banking");
  const double b = bank >= 0 ? t.rows[i][bank] : 0.0;
  return static_cast<float>(z[k]) + ref + b * d.v_m[j];
}

/// Every node's height through the surface (at the surface's own point of the node), within
/// float32 rounding of the file's number; `step` thins a large grid.
void expect_nodes(const fs::path& file, const fs::path& table_file, std::size_t step) {
  const CrgData d = load_crg_file(file);
  const Table t = read_table(table_file);
  ASSERT_EQ(d.nu(), t.rows.size()) << file;
  const CrgSurface s(d);
  model::road::SurfaceHint hint;
  for (std::size_t i = 0; i < d.nu(); i += step) {
    for (std::size_t j = 0; j < d.nv(); j += step) {
      double x = 0;
      double y = 0;
      s.world_point(d.u_first_m + static_cast<double>(i) * d.u_increment_m, d.v_m[j], x, y);
      const double want = node_height(t, d, i, j);
      EXPECT_NEAR(s.height(x, y, hint).z_m, want, 1e-12 + 6e-8 * std::abs(want))
          << file.filename() << " node " << i << ", " << j;
    }
  }
}

TEST(CrgFile, EveryTextSampleHasTheFilesHeightsAtItsNodes) {
  for (const char* name :
       {"handmade_straight", "handmade_straight_minimalist", "handmade_straight_double",
        "handmade_vtest", "handmade_curved", "handmade_curved_minimalist", "handmade_arc",
        "handmade_circle", "handmade_banked", "handmade_sloped", "handmade_sloped_opts",
        "handmade_curved_banked_sloped", "handmade_platform"}) {
    const fs::path p = kSamples / (std::string(name) + ".crg");
    expect_nodes(p, p, 1);
  }
}

TEST(CrgFile, BelgianBlockBinaryHasTheFilesHeightsAtItsNodes) {
  const CrgData d = load_crg_file(kBelgian);
  EXPECT_EQ(d.nu(), 1001u);
  EXPECT_EQ(d.nv(), 341u);
  EXPECT_DOUBLE_EQ(d.u_first_m, 730.0);
  EXPECT_DOUBLE_EQ(d.v_m.front(), -1.7);
  EXPECT_NEAR(d.v_m.back(), 1.7, 1e-12);
  expect_nodes(kBelgian, kBelgian, 7);
}

TEST(CrgFile, BetweenNodesTheBilinearValue) {
  const fs::path p = kSamples / "handmade_curved.crg";
  const CrgData d = load_crg_file(p);
  const Table t = read_table(p);
  const CrgSurface s(d);
  model::road::SurfaceHint hint;
  for (std::size_t i = 0; i + 1 < d.nu(); i += 3) {
    for (std::size_t j = 0; j + 1 < d.nv(); ++j) {
      const double a = 0.37;
      const double b = 0.81;
      const double want =
          (1 - a) * (1 - b) * node_height(t, d, i, j) + a * (1 - b) * node_height(t, d, i + 1, j) +
          (1 - a) * b * node_height(t, d, i, j + 1) + a * b * node_height(t, d, i + 1, j + 1);
      double x = 0;
      double y = 0;
      s.world_point(static_cast<double>(i) + a, d.v_m[j] + b * (d.v_m[j + 1] - d.v_m[j]), x, y);
      EXPECT_NEAR(s.height(x, y, hint).z_m, want, 1e-9) << i << ", " << j;
    }
  }
}

// ---- binary copies written here

void write_binary(const Table& t, const std::string& format, const fs::path& out) {
  std::ofstream f(out, std::ios::binary);
  for (const std::string& line : t.header) {
    f << (line.rfind("#:", 0) == 0 ? "#:" + format : line) << "\n";
  }
  const std::size_t width = format == "KDBI" ? 8 : 4;
  std::size_t written = 0;
  auto put = [&](double v) {
    std::uint64_t bits = 0;
    if (width == 8) {
      std::memcpy(&bits, &v, 8);
    } else {
      const auto x = static_cast<float>(v);
      std::uint32_t b32 = 0;
      std::memcpy(&b32, &x, 4);
      bits = b32;
    }
    for (std::size_t k = 0; k < width; ++k)
      f.put(static_cast<char>((bits >> (8 * (width - 1 - k))) & 0xFF));
    written += width;
  };
  for (const auto& row : t.rows) {
    for (double v : row) put(v);
  }
  while (written % 80 != 0) put(NAN);  // the last record padded with NaN
}

TEST(CrgFile, KdbiAndKrbiCopiesReadBackTheSameGrid) {
  const fs::path p = kSamples / "handmade_curved_banked_sloped.crg";
  const Table t = read_table(p);
  const CrgData text = load_crg_file(p);
  for (const std::string format : {"KDBI", "KRBI"}) {
    const fs::path copy = fs::path(testing::TempDir()) / ("copy_" + format + ".crg");
    write_binary(t, format, copy);
    const CrgData bin = load_crg_file(copy);
    ASSERT_EQ(bin.z_m.size(), text.z_m.size()) << format;
    for (std::size_t k = 0; k < bin.z_m.size(); ++k) {
      if (std::isnan(text.z_m[k])) {
        EXPECT_TRUE(std::isnan(bin.z_m[k])) << format << " " << k;
      } else {
        EXPECT_EQ(bin.z_m[k], text.z_m[k]) << format << " " << k;
      }
    }
    for (std::size_t i = 1; i < text.nu(); ++i) {
      const double tol = format == "KDBI" ? 0.0 : 1e-8;
      EXPECT_NEAR(bin.heading_rad[i], text.heading_rad[i], tol);
      EXPECT_NEAR(bin.slope[i], text.slope[i], tol);
      EXPECT_NEAR(bin.banking[i], text.banking[i], tol);
    }
    expect_nodes(copy, p, 1);
  }
}

TEST(CrgFile, LdfiAndLrfiOfTheSameRoadAgree) {
  const CrgData real = load_crg_file(kSamples / "handmade_straight.crg");
  const CrgData dbl = load_crg_file(kSamples / "handmade_straight_double.crg");
  ASSERT_EQ(real.z_m.size(), dbl.z_m.size());
  for (std::size_t k = 0; k < real.z_m.size(); ++k) {
    if (!std::isnan(real.z_m[k])) {
      EXPECT_NEAR(real.z_m[k], dbl.z_m[k], 1e-7) << k;
    }
  }
  EXPECT_EQ(real.v_m, dbl.v_m);
}

TEST(CrgFile, OptionsAndModifiersOfTheSamples) {
  const CrgData platform = load_crg_file(kSamples / "handmade_platform.crg");
  // `grid_nan_mode = 2.000000000+e00`: ASAM's own way of writing 2
  EXPECT_EQ(platform.mods.nan_mode, model::road::CrgNanMode::kKeepLast);
  const CrgData opts = load_crg_file(kSamples / "handmade_sloped_opts.crg");
  EXPECT_EQ(opts.options.border_u, model::road::CrgBorderMode::kKeepLast);
  EXPECT_EQ(opts.options.border_offset_v_m, 0.0);
  const CrgData minimal = load_crg_file(kSamples / "handmade_straight_minimalist.crg");
  // only LONG_SECTION_V_INCREMENT: the long sections centred on the reference line
  EXPECT_EQ(minimal.v_m, (std::vector<double>{-1.5, -1.0, -0.5, 0.0, 0.5, 1.0, 1.5}));
}

// ---- file references and malformed files, written into a temporary folder

fs::path temp_folder(const std::string& name) {
  const fs::path dir = fs::path(testing::TempDir()) / ("crg_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void write_text(const fs::path& p, const std::string& text) {
  std::ofstream f(p, std::ios::binary);
  f << text;
}

/// The message of the ConfigError `file` raises ("" if none).
std::string error_of(const fs::path& file) {
  try {
    (void)load_crg_file(file);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(CrgFile, FileReferencesTakeTheGridAndReplaceOptionsAndModifiers) {
  const fs::path dir = temp_folder("ref");
  fs::create_directories(dir / "crg-txt");
  fs::create_directories(dir / "refs");
  fs::copy_file(kSamples / "handmade_curved_banked_sloped.crg",
                dir / "crg-txt" / "handmade_curved_banked_sloped.crg");
  for (const char* name : {"fileref.crg", "fileref_mods.crg", "fileref_opts.crg"})
    fs::copy_file(kSamples / name, dir / "refs" / name);
  const CrgData base = load_crg_file(dir / "crg-txt" / "handmade_curved_banked_sloped.crg");
  for (const char* name : {"fileref.crg", "fileref_mods.crg", "fileref_opts.crg"}) {
    const CrgData d = load_crg_file(dir / "refs" / name);
    EXPECT_EQ(d.nu(), base.nu()) << name;
    EXPECT_EQ(d.heading_rad[5], base.heading_rad[5]) << name;
  }
  // fileref_mods.crg: REFPOINT_* given (all 0): the refpoint at u = 0, v = 0 goes to the origin
  EXPECT_TRUE(load_crg_file(dir / "refs" / "fileref_mods.crg").mods.refpoint.given);
  EXPECT_FALSE(load_crg_file(dir / "refs" / "fileref.crg").mods.refpoint.given);
  write_text(dir / "refs" / "moved.crg",
             "$CT\nmoved\n$ROAD_CRG_FILE\n ../crg-txt/\nhandmade_curved_banked_sloped.crg\n$\n"
             "$ROAD_CRG_OPTS\nBORDER_MODE_U = 1\nBORDER_OFFSET_U = 0.25\n$\n"
             "$ROAD_CRG_MODS\nREFPOINT_U_FRACTION = 0.5\nREFPOINT_X = 100\nREFPOINT_Z = 2\n$\n");
  const CrgData moved = load_crg_file(dir / "refs" / "moved.crg");
  EXPECT_EQ(moved.options.border_u, model::road::CrgBorderMode::kZero);
  EXPECT_EQ(moved.options.border_offset_u_m, 0.25);
  EXPECT_DOUBLE_EQ(moved.mods.refpoint.u_m, 11.0);  // half of 0 .. 22 m
  const CrgSurface s(moved);
  model::road::SurfaceHint hint;
  EXPECT_NEAR(s.height(100.0, 0.0, hint).z_m, 2.0, 1e-12);
  EXPECT_EQ(s.height(50.0, 0.0, hint).z_m, 0.25);  // before u = 0: BORDER_MODE_U 1
}

struct BadFile {
  const char* what;
  std::string text;
  std::string message;  ///< expected in the error, after "NAME:"
};

/// A minimal LRFI file with `header` in $ROAD_CRG and `rows` of 1 + 3 channels.
std::string lrfi(const std::string& road, const std::string& channels, const std::string& rows) {
  return "$CT\nbad\n$ROAD_CRG\n" + road + "$\n$KD_Definition\n#:LRFI\n" + channels +
         "$\n$$$$$$$$$$\n" + rows;
}

const std::string kChannels =
    "D:reference line slope,m/m\nD:long section 1,m\nD:long section 2,m\nD:long section 3,m\n";
const std::string kRoad = "REFERENCE_LINE_INCREMENT = 1.0\nLONG_SECTION_V_INCREMENT = 0.5\n";
const std::string kRows =
    " 0.0000000 0.0000000 0.0000000 0.0000000\n"
    " 0.0100000 0.0100000 0.0200000 0.0300000\n";

TEST(CrgFile, MalformedFilesNameTheirLineAndFault) {
  const std::vector<BadFile> cases{
      {"a field that is not a number",
       lrfi(kRoad, kChannels, kRows + " 0.0000000 0.0x00000 0.0000000 0.0000000\n"),
       ":17: characters 11-20 (' 0.0x00000') are not a finite number"},
      {"a record with too few numbers", lrfi(kRoad, kChannels, kRows + " 0.0000000 0.0000000\n"),
       ":17: 2 numbers of 10 characters, expected 4"},
      {"NaN between valid heights",
       lrfi(kRoad, kChannels, kRows + " 0.0000000 0.0000000 *missing* 0.0000000\n"),
       ":17: NaN between valid heights"},
      {"a cross section of NaN only",
       lrfi(kRoad, kChannels, kRows + " 0.0000000 *missing* *missing* *missing*\n"),
       ":17: a cross section without a valid height"},
      {"an unknown section", "$CT\nx\n$ROAD_XYZ\n$\n", ":3: unknown section $ROAD_XYZ"},
      {"an unknown $ROAD_CRG key", lrfi(kRoad + "REFERENCE_LINE_LENGTH = 3\n", kChannels, kRows),
       ":6: $ROAD_CRG: unknown key REFERENCE_LINE_LENGTH"},
      {"no $KD_Definition", "$CT\nx\n$ROAD_CRG\nREFERENCE_LINE_INCREMENT = 1\n$\n$$$$\n",
       ":1: no $KD_Definition section"},
      {"END_U and the rows disagree", lrfi("REFERENCE_LINE_END_U = 5\n" + kRoad, kChannels, kRows),
       ":4: REFERENCE_LINE_START_U/END_U/INCREMENT make 6 cross sections, the data has 2 rows"},
      {"an unknown channel", lrfi(kRoad, kChannels + "D:reference line torsion,rad\n", kRows),
       ":13: unknown channel 'reference line torsion'"},
      {"numbered long sections without their spacing",
       lrfi("REFERENCE_LINE_INCREMENT = 1.0\n", kChannels, kRows),
       ":9: 'long section N' channels need LONG_SECTION_V_INCREMENT"},
      {"x without y", lrfi(kRoad, "D:reference line x,m\n" + kChannels, kRows),
       ":7: reference line x and y channels: give both or neither"},
      {"border mode 0 (NaN off the grid)",
       lrfi(kRoad, kChannels, kRows).replace(0, 4, "$ROAD_CRG_OPTS\nBORDER_MODE_V = 0\n$\n$CT\n"),
       ":2: BORDER_MODE_V = 0 gives NaN beyond the grid"},
      {"GRID_NAN_MODE 0 (NaN kept)",
       lrfi(kRoad, kChannels, kRows).replace(0, 4, "$ROAD_CRG_MODS\nGRID_NAN_MODE = 0\n$\n$CT\n"),
       ":2: GRID_NAN_MODE = 0 keeps NaN heights"},
      {"a missing referenced file", "$CT\nx\n$ROAD_CRG_FILE\n../nowhere/road.crg\n$\n",
       ":4: $ROAD_CRG_FILE '../nowhere/road.crg' not found"},
      {"no road data", "$CT\nx\n$ROAD_CRG\n" + kRoad + "$\n$KD_Definition\n" + kChannels + "$\n",
       ":1: no road data"},
  };
  const fs::path dir = temp_folder("bad");
  for (std::size_t n = 0; n < cases.size(); ++n) {
    const fs::path p = dir / ("bad" + std::to_string(n) + ".crg");
    write_text(p, cases[n].text);
    const std::string error = error_of(p);
    EXPECT_NE(error.find(p.string() + cases[n].message), std::string::npos)
        << cases[n].what << ": " << error;
  }
}

TEST(CrgFile, ABinaryPayloadThatLostBytesIsRefusedWithItsCause) {
  // the Belgian block as shipped: 6 CR bytes lost to a CR LF -> LF copy
  const std::string error = error_of(kSamples / "belgian_block.crg");
  EXPECT_NE(error.find("belgian_block.crg:401: the binary data is 1369435 bytes, not whole "
                       "80-byte records"),
            std::string::npos)
      << error;
  EXPECT_NE(error.find("CR LF into LF"), std::string::npos) << error;
}

TEST(CrgFile, AReferenceCycleEnds) {
  const fs::path dir = temp_folder("cycle");
  write_text(dir / "a.crg", "$CT\na\n$ROAD_CRG_FILE\nb.crg\n$\n");
  write_text(dir / "b.crg", "$CT\nb\n$ROAD_CRG_FILE\na.crg\n$\n");
  EXPECT_NE(error_of(dir / "a.crg").find(":3: $ROAD_CRG_FILE references nest deeper than 8"),
            std::string::npos)
      << error_of(dir / "a.crg");
}

}  // namespace
}  // namespace rig::io::config
