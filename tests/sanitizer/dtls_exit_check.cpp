// Puts a dynamic TLS block where GCC 12's LeakSanitizer misreads its bounds, then exits:
// the leak check at exit must run and find nothing (cmake/sanitizer_defaults.cpp). Without
// intercept_tls_get_addr=0 the exit fails: "Tracer caught signal 11".
//
// The block (32 bytes) comes from AddressSanitizer's 48-byte size class, whose chunks one
// thread takes in address order; 32-byte allocations are made until the next chunk of the
// class starts its user bytes 16 into a page, which the block then takes.
#include <dlfcn.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>

namespace {
void* kept[4096];  // reachable: the check must report no leak
}

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: dtls_exit_check MODULE\n");
    return 2;
  }
  void* module = dlopen(argv[1], RTLD_NOW);
  if (module == nullptr) {
    std::fprintf(stderr, "dtls_exit_check: %s\n", dlerror());
    return 2;
  }
  const auto dtls_block = reinterpret_cast<long* (*)()>(dlsym(module, "dtls_block"));
  if (dtls_block == nullptr) {
    std::fprintf(stderr, "dtls_exit_check: no dtls_block in %s\n", argv[1]);
    return 2;
  }
  constexpr std::uintptr_t kStride = 48, kPage = 4096, kHeader = 16;
  int n = 0;
  do {
    kept[n] = std::malloc(sizeof(long) * 4);
  } while ((reinterpret_cast<std::uintptr_t>(kept[n]) + kStride) % kPage != kHeader && ++n < 4096);
  const auto at = reinterpret_cast<std::uintptr_t>(dtls_block());
  if (at % kPage != kHeader) {
    std::fprintf(stderr, "dtls_exit_check: the TLS block is at %#lx, not 16 bytes into a page: the layout moved\n",
                 static_cast<unsigned long>(at));
    return 1;
  }
  std::printf("the TLS block is at %#lx, 16 bytes into a page, after %d allocations\n", static_cast<unsigned long>(at), n);
  return 0;
}
