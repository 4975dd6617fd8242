#include "terrain/object_id.h"

#include <atomic>

namespace skylit::terrain {

std::uint64_t ObjectId::next() {
  static std::atomic<std::uint64_t> counter{0};
  return counter.fetch_add(1, std::memory_order_relaxed) + 1;
}

}  // namespace skylit::terrain
