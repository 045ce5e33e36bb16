#pragma once
/// @file
/// Reads an ASAM OpenCRG file (.crg, OpenCRG 1.2) into model::road::CrgData: the header sections
/// $CT, $ROAD_CRG (reference line, u and v axes), $KD_Definition (format and channels: reference
/// line phi / x / y / banking / slope, long sections by number or at v), $ROAD_CRG_OPTS (border
/// modes, offsets, smoothing; the tools' WARN_/LOG_/CHECK_/REFLINE_SEARCH_ options are read and
/// not needed), $ROAD_CRG_MODS (GRID_NAN_MODE/OFFSET, SCALE_Z_GRID/SLOPE/BANKING, REFPOINT_*),
/// $ROAD_CRG_MPRO (ignored), and the payload in LRFI, LDFI, KRBI or KDBI. A $ROAD_CRG_FILE
/// reference (resolved relative to the referencing file) supplies the grid; the referencing
/// file's own $ROAD_CRG_OPTS / $ROAD_CRG_MODS sections, empty ones too, replace the referenced
/// file's. Every error is a ConfigError `file:line: what is wrong`. Load time only.

#include <cstddef>
#include <filesystem>

#include "model/road/crg_data.h"

namespace rig::io::config {

/// The largest .crg file read (a measured road of some kilometres at centimetre cells).
inline constexpr std::size_t kMaxCrgFileBytes = std::size_t{256} << 20;

/// Loads `file` (following its $ROAD_CRG_FILE reference, at most 8 deep).
model::road::CrgData load_crg_file(const std::filesystem::path& file);

}  // namespace rig::io::config
