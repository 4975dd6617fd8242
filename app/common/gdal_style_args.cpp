#include "app/common/gdal_style_args.h"

#include <array>
#include <string_view>
#include <utility>

namespace skylit::app {

std::vector<std::string> normalise_gdal_style_args(int argc, char** argv) {
  static constexpr std::array<std::pair<std::string_view, std::string_view>, 9> kMap{{
      {"-of", "--of"},
      {"-co", "--co"},
      {"-compute_edges", "--compute-edges"},
      {"-az", "--azimuth"},
      {"-alt", "--altitude"},
      {"-alg", "--alg"},
      {"-combined", "--combined"},
      {"-multidirectional", "--multidirectional"},
      {"-igor", "--igor"},
  }};
  std::vector<std::string> out;
  out.reserve(argc);
  for (int i = 0; i < argc; ++i) {
    std::string_view a = argv[i];
    std::string mapped(a);
    for (const auto& [from, to] : kMap)
      if (a == from) mapped = to;
    out.push_back(std::move(mapped));
  }
  return out;
}

}  // namespace skylit::app
