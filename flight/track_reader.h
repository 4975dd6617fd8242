// Reading any supported track file: the format from the extension (.igc, .gpx, .kml,
// .csv) or, when the extension says nothing, from the first bytes; then the format's
// reader (flight/igc_reader.h, gpx_reader.h, kml_reader.h, csv_reader.h, each with its
// policy). Every failure is one line naming the file.
#pragma once

#include <istream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "flight/track.h"

namespace skylit::flight {

// The format the first bytes show: "<gpx"/"<kml" root (after an XML declaration and
// comments), IGC's A or H record first, or a CSV header with lat and lon. nullopt if none.
std::optional<TrackFormat> sniff_track_format(std::string_view head);

// From the extension (case-insensitive); nullopt for any other.
std::optional<TrackFormat> format_from_extension(const std::string& path);

// The format's reader over a stream (buffers and fuzzers need no file).
std::vector<Track> read_track(std::istream& in, TrackFormat format, const std::string& name);

// Opens, detects and reads. Throws std::runtime_error when the file cannot be read,
// std::invalid_argument for its content.
std::vector<Track> read_track_file(const std::string& path);

}  // namespace skylit::flight
