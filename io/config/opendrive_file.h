#pragma once
/// @file
/// Reads an ASAM OpenDRIVE file (`.xodr`, XML, parsed with pugixml) into plain data
/// (model/road/opendrive_road.h): for each <road> its id, length, <planView> geometries (line,
/// arc, spiral, poly3, paramPoly3), <elevationProfile> and <lateralProfile> <superelevation>
/// records. Lanes, junctions, objects and signals are not read (contact needs none of them).
///
/// Bad input is a ConfigError `file:line: what is wrong` (the line of the element; XML syntax
/// errors at pugixml's offset): a missing or non-numeric attribute, a non-finite number, a
/// geometry without exactly one shape, lengths <= 0, records out of order, a road without a
/// plan view. Tolerated with a warning (the model uses each geometry's own start): gaps and
/// kinks between geometries beyond 1 mm / 1 mrad, a <road length> differing from the plan
/// view's, a lateral <shape> (not applied).

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "model/road/opendrive_road.h"
#include "model/road/opendrive_surface.h"
#include "model/road/placement.h"

namespace rig::io::config {

struct OpenDriveFile {
  std::filesystem::path path;
  std::vector<model::road::OpenDriveRoad> roads;  ///< in the file's order, at least one
  std::vector<int> road_lines;                    ///< the line of each <road>
  std::vector<std::string> warnings;              ///< `file:line: ...`, for `rig: warning:`
};

/// The most geometries, elevation or superelevation records per road, and roads per file.
inline constexpr std::size_t kMaxOpenDriveRecords = 1'000'000;

/// Reads and checks every road of `file` (a regular file of at most 16 MiB).
OpenDriveFile load_opendrive_file(const std::filesystem::path& file);

/// The road with id `road_id` ("": the file's first). Throws ConfigError naming the file's
/// road ids if there is none.
const model::road::OpenDriveRoad& select_road(const OpenDriveFile& file, std::string_view road_id);

/// The surface of the road `road_id` ("": the first) placed by `placement` (given = false:
/// where the file puts it). What the model refuses (a road too long for its curvature: over a
/// million projection samples) is a ConfigError at the road's line.
std::shared_ptr<const model::road::OpenDriveSurface> make_opendrive_surface(
    const OpenDriveFile& file, std::string_view road_id, const model::road::Placement& placement);

}  // namespace rig::io::config
