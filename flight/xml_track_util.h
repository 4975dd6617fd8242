// What the GPX and KML readers share: parsing a bounded buffer with pugixml, element
// names without their namespace prefix, and the line of a node for error messages.
#pragma once

#include <pugixml.hpp>

#include <cstddef>
#include <istream>
#include <string>
#include <string_view>

namespace skylit::flight::detail {

struct XmlDocument {
  std::string text;  // the buffer the offsets point into
  pugi::xml_document doc;
};

// Reads (bounded, binary-checked) and parses; a parse error names the line.
void load_xml(std::istream& in, const std::string& name, XmlDocument& out);

// "gx:Track" → "Track".
std::string_view local_name(const pugi::xml_node& node);

// First child element with this local name (any prefix), or an empty node.
pugi::xml_node child_named(const pugi::xml_node& node, std::string_view local);

// 1-based line of a node in the buffer.
std::size_t line_of(const XmlDocument& xml, const pugi::xml_node& node);

// The element's text, trimmed.
std::string trimmed_text(const pugi::xml_node& node);

// A whole number as text ("1.5e3", " 42 ") → value; false if not a finite number.
bool parse_number(std::string_view text, double& value);

}  // namespace skylit::flight::detail
