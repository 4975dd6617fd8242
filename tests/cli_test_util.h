// Runs the built skylit binary through the shell for end-to-end CLI tests.
#pragma once

#include "terrain_test_util.h"

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace skylit::testing {

struct Run {
  int status;       // exit code, −1 if the process did not exit normally
  std::string out;  // stdout (and stderr when merged)
};

inline Run run_skylit(const std::string& args, bool merge_stderr = false) {
  const std::string cmd = std::string(SKYLIT_BINARY) + " " + args + (merge_stderr ? " 2>&1" : " 2>/dev/null");
  FILE* pipe = popen(cmd.c_str(), "r");
  if (!pipe) return {-1, ""};
  std::string out;
  std::array<char, 4096> buf{};
  std::size_t n;
  while ((n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0) out.append(buf.data(), n);
  const int raw = pclose(pipe);
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, out};
}

inline int count_lines(const std::string& s) {
  int lines = 0;
  for (char c : s) lines += c == '\n';
  return lines;
}

// Expects `skylit shade ARGS -q` to fail cleanly: exit 1 (bad input) or 2 (bad usage),
// exactly one line starting "skylit: error:" that contains `needle`, and no file left
// behind in `dir`.
inline void expect_clean_shade_failure(const terrain::testing::ScratchDir& dir, const std::string& args,
                                       const std::string& needle) {
  const auto before = dir.listing();
  const auto r = run_skylit("shade " + args + " -q", true);
  EXPECT_TRUE(r.status == 1 || r.status == 2) << args << "\n" << r.out;
  EXPECT_EQ(count_lines(r.out), 1) << r.out;
  EXPECT_EQ(r.out.rfind("skylit: error: ", 0), 0u) << r.out;
  EXPECT_NE(r.out.find(needle), std::string::npos) << "expected '" << needle << "' in: " << r.out;
  EXPECT_EQ(dir.listing(), before) << "a failed run left files behind";
}

}  // namespace skylit::testing
