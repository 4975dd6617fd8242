#include "gpu/loaded_objects.h"

#include <dlfcn.h>
#include <link.h>

namespace skylit::gpu {
namespace {

std::set<std::string> mapped_now() {
  std::set<std::string> paths;
  dl_iterate_phdr(
      [](dl_phdr_info* info, std::size_t, void* out) {
        if (info->dlpi_name && *info->dlpi_name) static_cast<std::set<std::string>*>(out)->insert(info->dlpi_name);
        return 0;
      },
      &paths);
  return paths;
}

}  // namespace

LoadedObjects::LoadedObjects() : paths_(mapped_now()) {}

void LoadedObjects::keep_the_new_loaded() const {
  for (const std::string& path : mapped_now())
    if (!paths_.contains(path)) dlopen(path.c_str(), RTLD_LAZY | RTLD_NOLOAD | RTLD_NODELETE);
}

}  // namespace skylit::gpu
