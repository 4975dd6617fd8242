#include "flight/track_reader.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "flight/csv_reader.h"
#include "flight/gpx_reader.h"
#include "flight/igc_reader.h"
#include "flight/kml_reader.h"
#include "flight/track_input.h"

namespace skylit::flight {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

}  // namespace

std::optional<TrackFormat> format_from_extension(const std::string& path) {
  const std::string ext = lower(std::filesystem::path(path).extension().string());
  if (ext == ".igc") return TrackFormat::igc;
  if (ext == ".gpx") return TrackFormat::gpx;
  if (ext == ".kml") return TrackFormat::kml;
  if (ext == ".csv") return TrackFormat::csv;
  return std::nullopt;
}

std::optional<TrackFormat> sniff_track_format(std::string_view head) {
  if (head.starts_with("\xEF\xBB\xBF")) head.remove_prefix(3);
  const std::size_t first = head.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return std::nullopt;
  head.remove_prefix(first);
  if (head.front() == '<') {
    // The root element: the first '<' followed by a letter (skips <?xml ?> and <!-- -->).
    for (std::size_t p = head.find('<'); p != std::string_view::npos; p = head.find('<', p + 1)) {
      if (p + 1 < head.size() && std::isalpha(static_cast<unsigned char>(head[p + 1]))) {
        const std::string_view root = head.substr(p + 1, 3);
        if (root == "gpx") return TrackFormat::gpx;
        if (root == "kml") return TrackFormat::kml;
        return std::nullopt;
      }
    }
    return std::nullopt;
  }
  // A CSV header first: "Altitude,lat,lon" also starts with an A.
  const std::string first_line = lower(std::string(head.substr(0, head.find('\n'))));
  if (first_line.find(',') != std::string::npos && first_line.find("lat") != std::string::npos &&
      first_line.find("lon") != std::string::npos)
    return TrackFormat::csv;
  if (head.front() == 'A' || head.starts_with("HF")) return TrackFormat::igc;
  return std::nullopt;
}

std::vector<Track> read_track(std::istream& in, TrackFormat format, const std::string& name) {
  switch (format) {
    case TrackFormat::igc: return read_igc(in, name);
    case TrackFormat::gpx: return read_gpx(in, name);
    case TrackFormat::kml: return read_kml(in, name);
    case TrackFormat::csv: return read_csv(in, name);
  }
  throw std::invalid_argument(name + ": unknown track format");
}

std::vector<Track> read_track_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw std::runtime_error(path + ": is a directory, not a track file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open (" + std::strerror(errno) + ")");
  std::string head(detail::kSniffBytes, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  if (in.bad()) throw std::runtime_error(path + ": cannot read");
  if (head.empty()) throw std::invalid_argument(path + ": empty file");
  if (detail::looks_binary(head)) throw std::invalid_argument(path + ": binary content, not a track file");
  in.clear();
  in.seekg(0);
  const auto format = format_from_extension(path) ? format_from_extension(path) : sniff_track_format(head);
  if (!format)
    throw std::invalid_argument(path + ": not a track file this reads (IGC, GPX, KML gx:Track or CSV with time,lat,lon)");
  // GPX and KML are parsed whole: refuse a huge file before reading it.
  const bool xml = *format == TrackFormat::gpx || *format == TrackFormat::kml;
  if (xml && std::filesystem::file_size(path, ec) > detail::kMaxXmlBytes && !ec)
    throw std::invalid_argument(path + ": larger than " + std::to_string(detail::kMaxXmlBytes >> 20) +
                                " MiB, too large to parse as XML");
  return read_track(in, *format, path);
}

}  // namespace skylit::flight
