#include "flight/sphere_set.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

namespace skylit::flight {
namespace {

using nlohmann::json;

[[noreturn]] void fail(const std::string& origin, const std::string& why) { throw SphereSetError(origin + ": " + why); }

double finite_number(const json& j, const std::string& what, const std::string& origin) {
  if (!j.is_number()) fail(origin, what + " is not a number");
  const double v = j.get<double>();
  if (!std::isfinite(v)) fail(origin, what + " is not finite");
  return v;
}

double optional_number(const json& obj, const char* key, const std::string& origin) {
  return obj.contains(key) ? finite_number(obj[key], std::string("\"") + key + "\"", origin) : 0.0;
}

}  // namespace

SphereSet parse_sphere_set(const std::string& text, const std::string& origin) {
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::exception& e) {  // syntax, and numbers beyond double (1e999)
    fail(origin, std::string("not valid JSON (") + e.what() + ")");
  }
  if (!doc.is_object()) fail(origin, "not a JSON object");
  SphereSet set;
  if (!doc.contains("name") || !doc["name"].is_string()) fail(origin, "missing \"name\" (a string)");
  set.name = doc["name"].get<std::string>();
  if (!doc.contains("spheres") || !doc["spheres"].is_array()) fail(origin, "missing \"spheres\" (an array)");
  const json& spheres = doc["spheres"];
  if (spheres.empty()) fail(origin, "\"spheres\" is empty");
  if (spheres.size() > kMaxSpheres)
    fail(origin, std::to_string(spheres.size()) + " spheres, more than the " + std::to_string(kMaxSpheres) + " allowed");
  set.spheres.reserve(spheres.size());
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    const json& s = spheres[i];
    const std::string at = "sphere " + std::to_string(i);
    if (!s.is_object()) fail(origin, at + " is not an object");
    if (!s.contains("centre") || !s["centre"].is_array() || s["centre"].size() != 3)
      fail(origin, at + ": missing \"centre\" ([x, y, z])");
    if (!s.contains("radius")) fail(origin, at + ": missing \"radius\"");
    BodySphere b;
    for (int k = 0; k < 3; ++k) b.centre[k] = finite_number(s["centre"][k], at + " centre", origin);
    b.radius = finite_number(s["radius"], at + " radius", origin);
    if (b.radius <= 0.0) fail(origin, at + ": radius " + std::to_string(b.radius) + " is not positive");
    set.spheres.push_back(b);
  }
  set.span_m = optional_number(doc, "span_m", origin);
  set.length_m = optional_number(doc, "length_m", origin);
  set.height_m = optional_number(doc, "height_m", origin);
  if (doc.contains("source") && doc["source"].is_string()) set.source = doc["source"].get<std::string>();
  if (doc.contains("fit_error")) {
    const json& f = doc["fit_error"];
    if (!f.is_object()) fail(origin, "\"fit_error\" is not an object");
    set.has_fit_error = true;
    set.fit_error.volume_error = optional_number(f, "volume_error", origin);
    set.fit_error.volume_error_se = optional_number(f, "volume_error_se", origin);
    set.fit_error.volume_samples = static_cast<long long>(optional_number(f, "volume_samples", origin));
    set.fit_error.solid_angle_error = optional_number(f, "solid_angle_error", origin);
    set.fit_error.solid_angle_rays = static_cast<long long>(optional_number(f, "solid_angle_rays", origin));
  }
  return set;
}

SphereSet read_sphere_set(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SphereSetError("cannot read sphere set '" + path + "'");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_sphere_set(text.str(), path);
}

std::string sphere_set_json(const SphereSet& set) {
  // Rounded to 0.1 mm: far below any fit error, and the shipped files stay readable.
  auto mm = [](double v) { return std::round(v * 1e4) / 1e4; };
  json doc;
  doc["name"] = set.name;
  doc["span_m"] = mm(set.span_m);
  doc["length_m"] = mm(set.length_m);
  doc["height_m"] = mm(set.height_m);
  doc["source"] = set.source;
  if (set.has_fit_error)
    doc["fit_error"] = {{"volume_error", set.fit_error.volume_error},
                        {"volume_error_se", set.fit_error.volume_error_se},
                        {"volume_samples", set.fit_error.volume_samples},
                        {"solid_angle_error", set.fit_error.solid_angle_error},
                        {"solid_angle_rays", set.fit_error.solid_angle_rays}};
  json spheres = json::array();
  for (const auto& s : set.spheres)
    spheres.push_back({{"centre", {mm(s.centre.x), mm(s.centre.y), mm(s.centre.z)}}, {"radius", mm(s.radius)}});
  doc["spheres"] = spheres;
  return doc.dump(1) + "\n";
}

std::vector<PlacedSphere> place(const SphereSet& set, const Pose& pose) {
  const glm::dmat3 r = body_to_enu(pose.attitude);
  std::vector<PlacedSphere> out;
  out.reserve(set.spheres.size());
  for (const auto& s : set.spheres) out.push_back({pose.position + r * s.centre, s.radius});
  return out;
}

}  // namespace skylit::flight
