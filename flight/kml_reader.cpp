#include "flight/kml_reader.h"

#include <sstream>

#include "flight/track_input.h"
#include "flight/track_time.h"
#include "flight/xml_track_util.h"

namespace skylit::flight {
namespace {

using detail::fail;

// Nearest enclosing Placemark's <name>.
std::string placemark_name(pugi::xml_node node) {
  for (; node; node = node.parent())
    if (detail::local_name(node) == "Placemark") return detail::trimmed_text(detail::child_named(node, "name"));
  return {};
}

std::optional<AltitudeDatum> altitude_datum(const detail::XmlDocument& xml, const pugi::xml_node& track,
                                            const std::string& name) {
  pugi::xml_node mode = detail::child_named(track, "altitudeMode");
  const std::string m = mode ? detail::trimmed_text(mode) : "clampToGround";
  if (m == "absolute") return AltitudeDatum::geoid_msl;
  if (m == "relativeToGround") return AltitudeDatum::above_ground;
  if (m == "clampToGround") return std::nullopt;
  fail(name, detail::line_of(xml, mode), "altitudeMode " + detail::quoted(m) + " is not absolute, relativeToGround or clampToGround");
}

Track read_one(const detail::XmlDocument& xml, const pugi::xml_node& gx_track, const std::string& name) {
  Track track;
  track.format = TrackFormat::kml;
  track.id = detail::clean_name(placemark_name(gx_track));
  const std::optional<AltitudeDatum> datum = altitude_datum(xml, gx_track, name);
  std::vector<pugi::xml_node> whens, coords;
  for (pugi::xml_node c = gx_track.first_child(); c; c = c.next_sibling()) {
    if (detail::local_name(c) == "when") whens.push_back(c);
    else if (detail::local_name(c) == "coord") coords.push_back(c);
  }
  if (whens.size() != coords.size())
    fail(name, detail::line_of(xml, gx_track),
         "gx:Track has " + std::to_string(whens.size()) + " <when> but " + std::to_string(coords.size()) + " <gx:coord>");
  for (std::size_t k = 0; k < whens.size(); ++k) {
    const std::size_t line = detail::line_of(xml, coords[k]);
    Fix fix;
    const auto t = parse_iso8601(detail::trimmed_text(whens[k]));
    if (!t) fail(name, detail::line_of(xml, whens[k]), "<when> " + detail::quoted(detail::trimmed_text(whens[k])) + " is not an ISO 8601 time with a zone");
    fix.time_s = *t;
    std::istringstream words(detail::trimmed_text(coords[k]));
    std::string lon, lat, alt, extra;
    words >> lon >> lat >> alt >> extra;
    double altitude = 0.0;
    if (!detail::parse_number(lon, fix.lon_deg) || !detail::parse_number(lat, fix.lat_deg) ||
        (!alt.empty() && !detail::parse_number(alt, altitude)) || !extra.empty())
      fail(name, line, "<gx:coord> " + detail::quoted(detail::trimmed_text(coords[k])) + " is not 'lon lat [alt]'");
    detail::check_coordinates(name, line, fix.lat_deg, fix.lon_deg);
    if (datum) {
      if (alt.empty()) fail(name, line, "<gx:coord> has no altitude but altitudeMode needs one");
      fix.stated = Altitude{altitude, *datum};
    } else {
      fix.stated = Altitude{0.0, AltitudeDatum::above_ground};
    }
    detail::append_fix(track, std::move(fix), name, line);
  }
  return track;
}

// Every gx:Track under root, in document order. Iterative: a deeply nested (hostile)
// file must not overflow the stack.
void collect(const detail::XmlDocument& xml, const pugi::xml_node& root, const std::string& name,
             std::vector<Track>& out) {
  pugi::xml_node n = root.first_child();
  while (n) {
    const bool is_track = n.type() == pugi::node_element && detail::local_name(n) == "Track";
    if (is_track) {
      Track t = read_one(xml, n, name);
      if (!t.fixes.empty()) out.push_back(std::move(t));
    }
    if (!is_track && n.first_child()) {
      n = n.first_child();
      continue;
    }
    while (n && n != root && !n.next_sibling()) n = n.parent();
    if (!n || n == root) break;
    n = n.next_sibling();
  }
}

}  // namespace

std::vector<Track> read_kml(std::istream& in, const std::string& name) {
  detail::XmlDocument xml;
  detail::load_xml(in, name, xml);
  if (detail::local_name(xml.doc.document_element()) != "kml") fail(name, "not a KML file (root element is not <kml>)");
  std::vector<Track> tracks;
  collect(xml, xml.doc.document_element(), name, tracks);
  detail::require_fixes(tracks, name, "no <gx:Track> with <when> and <gx:coord>");
  return tracks;
}

}  // namespace skylit::flight
