#include "app/tiles/web_assets.h"

#include <stdexcept>
#include <string>

namespace skylit::app::tiles {

std::string_view web_asset(std::string_view name) {
  for (std::size_t k = 0; k < detail::kWebAssetCount; ++k)
    if (!name.empty() && name == detail::kWebAssets[k].name) return detail::kWebAssets[k].text;
  throw std::out_of_range("no embedded web asset named '" + std::string(name) + "' (app/tiles/web/ is embedded at build time)");
}

}  // namespace skylit::app::tiles
