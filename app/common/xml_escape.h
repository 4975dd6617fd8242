// Text for XML and HTML outputs (the bench's and the sphere fit's SVG plots, the tile
// viewer's page): & < > " as entities, so titles and labels cannot break the markup.
#pragma once

#include <string>

namespace skylit::app {

std::string xml_escape(const std::string& text);

}  // namespace skylit::app
