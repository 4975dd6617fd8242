// Replays every file of the given folders through a fuzz target's entry point, without
// libFuzzer: the corpus as a regression test that any compiler (CI's g++) can build.
// Fails when a folder holds no file, so a lost corpus cannot pass unnoticed.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  for (int a = 1; a < argc; ++a) {
    std::size_t count = 0;
    for (const auto& entry : fs::recursive_directory_iterator(argv[a])) {
      if (!entry.is_regular_file()) continue;
      std::ifstream in(entry.path(), std::ios::binary);
      const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
      ++count;
    }
    std::printf("%s: %zu inputs replayed\n", argv[a], count);
    if (count == 0) return 1;
  }
  return argc > 1 ? 0 : 2;
}
