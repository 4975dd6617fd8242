#include "flight/xml_track_util.h"

#include <algorithm>
#include <charconv>
#include <cctype>
#include <cmath>

#include "flight/track_input.h"

namespace skylit::flight::detail {
namespace {

std::size_t line_at(const std::string& text, std::ptrdiff_t offset) {
  if (offset < 0) return 0;
  const auto end = text.begin() + std::min<std::ptrdiff_t>(offset, static_cast<std::ptrdiff_t>(text.size()));
  return 1 + static_cast<std::size_t>(std::count(text.begin(), end, '\n'));
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

}  // namespace

void load_xml(std::istream& in, const std::string& name, XmlDocument& out) {
  out.text = read_bounded(in, name);
  if (trim(out.text).empty()) fail(name, "empty file");
  // parse_default without entity expansion beyond XML's own: pugixml never fetches
  // external entities, so a hostile file cannot make us read other files.
  const pugi::xml_parse_result r = out.doc.load_buffer(out.text.data(), out.text.size(), pugi::parse_default);
  if (!r) fail(name, line_at(out.text, r.offset), std::string("not well-formed XML: ") + r.description());
}

std::string_view local_name(const pugi::xml_node& node) {
  const std::string_view n = node.name();
  const auto colon = n.find(':');
  return colon == std::string_view::npos ? n : n.substr(colon + 1);
}

pugi::xml_node child_named(const pugi::xml_node& node, std::string_view local) {
  for (pugi::xml_node c = node.first_child(); c; c = c.next_sibling())
    if (c.type() == pugi::node_element && local_name(c) == local) return c;
  return {};
}

std::size_t line_of(const XmlDocument& xml, const pugi::xml_node& node) { return line_at(xml.text, node.offset_debug()); }

std::string trimmed_text(const pugi::xml_node& node) { return std::string(trim(node.child_value())); }

bool parse_number(std::string_view text, double& value) {
  text = trim(text);
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return ec == std::errc() && ptr == text.data() + text.size() && !text.empty() && std::isfinite(value);
}

}  // namespace skylit::flight::detail
