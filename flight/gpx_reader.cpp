#include "flight/gpx_reader.h"

#include "flight/track_input.h"
#include "flight/track_time.h"
#include "flight/xml_track_util.h"

namespace skylit::flight {

using detail::fail;

std::vector<Track> read_gpx(std::istream& in, const std::string& name) {
  detail::XmlDocument xml;
  detail::load_xml(in, name, xml);
  const pugi::xml_node gpx = xml.doc.document_element();
  if (detail::local_name(gpx) != "gpx") fail(name, "not a GPX file (root element is not <gpx>)");
  std::vector<Track> tracks;
  for (pugi::xml_node trk = gpx.first_child(); trk; trk = trk.next_sibling()) {
    if (detail::local_name(trk) != "trk") continue;
    Track track;
    track.format = TrackFormat::gpx;
    track.id = detail::clean_name(detail::trimmed_text(detail::child_named(trk, "name")));
    for (pugi::xml_node seg = trk.first_child(); seg; seg = seg.next_sibling()) {
      if (detail::local_name(seg) != "trkseg") continue;
      for (pugi::xml_node pt = seg.first_child(); pt; pt = pt.next_sibling()) {
        if (detail::local_name(pt) != "trkpt") continue;
        const std::size_t line = detail::line_of(xml, pt);
        Fix fix;
        if (!detail::parse_number(pt.attribute("lat").value(), fix.lat_deg) ||
            !detail::parse_number(pt.attribute("lon").value(), fix.lon_deg))
          fail(name, line, "trkpt without numeric lat and lon attributes");
        detail::check_coordinates(name, line, fix.lat_deg, fix.lon_deg);
        const pugi::xml_node time = detail::child_named(pt, "time");
        if (!time) fail(name, line, "trkpt without <time>");
        const auto t = parse_iso8601(detail::trimmed_text(time));
        if (!t) fail(name, line, "trkpt <time> " + detail::quoted(detail::trimmed_text(time)) + " is not an ISO 8601 time with a zone");
        fix.time_s = *t;
        if (const pugi::xml_node ele = detail::child_named(pt, "ele")) {
          double metres;
          if (!detail::parse_number(ele.child_value(), metres)) fail(name, line, "trkpt <ele> is not a number");
          fix.stated = Altitude{metres, AltitudeDatum::geoid_msl};
        }
        double v;
        if (const pugi::xml_node speed = detail::child_named(pt, "speed"); speed && detail::parse_number(speed.child_value(), v))
          fix.ground_speed_mps = v;
        if (const pugi::xml_node course = detail::child_named(pt, "course"); course && detail::parse_number(course.child_value(), v))
          fix.track_deg = v;
        detail::append_fix(track, std::move(fix), name, line);
      }
    }
    if (!track.fixes.empty()) tracks.push_back(std::move(track));
  }
  detail::require_fixes(tracks, name, "no <trk>/<trkseg>/<trkpt>");
  return tracks;
}

}  // namespace skylit::flight
