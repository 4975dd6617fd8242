// `skylit spheres-fit`: writes a valid sphere set with its errors, fails in one line
// without leaving files, and never overwrites without --overwrite.
#include "cli_test_util.h"
#include "terrain_test_util.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>

using skylit::testing::count_lines;
using skylit::testing::run_skylit;
using skylit::terrain::testing::ScratchDir;

namespace {

// Small sample counts: the test checks the command, not the fit's accuracy.
const std::string kQuick = " --samples 3000 --error-samples 30000 --error-rays 3000 ";

nlohmann::json read_json(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return nlohmann::json::parse(s.str());
}

void expect_one_line_failure(const ScratchDir& dir, const std::string& args, const std::string& needle) {
  const auto before = dir.listing();
  const auto r = run_skylit("spheres-fit " + args + " -q", true);
  EXPECT_TRUE(r.status == 1 || r.status == 2) << args << "\n" << r.out;
  EXPECT_EQ(count_lines(r.out), 1) << r.out;
  EXPECT_EQ(r.out.rfind("skylit: error: ", 0), 0u) << r.out;
  EXPECT_NE(r.out.find(needle), std::string::npos) << "expected '" << needle << "' in: " << r.out;
  EXPECT_EQ(dir.listing(), before) << "a failed run left files behind";
}

TEST(CliSpheresFit, FitsAProceduralAircraftAndAMeshFile) {
  ScratchDir dir;
  const std::string out = dir.file("balloon.json"), obj = dir.file("balloon.obj"), svg = dir.file("balloon.svg");
  const auto r = run_skylit("spheres-fit --aircraft balloon -k 4 -o " + out + kQuick + "--write-mesh " + obj + " --svg " + svg);
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("symmetric difference"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("1000 m below"), std::string::npos) << r.out;
  const auto j = read_json(out);
  EXPECT_EQ(j["name"], "balloon");
  ASSERT_EQ(j["spheres"].size(), 4u);
  for (const auto& s : j["spheres"]) EXPECT_GT(s["radius"].get<double>(), 0.0);
  EXPECT_GT(j["fit_error"]["volume_error"].get<double>(), 0.0);
  EXPECT_EQ(j["fit_error"]["volume_samples"].get<long long>(), 30000);
  EXPECT_NEAR(j["span_m"].get<double>(), 18.8, 0.1);
  std::ifstream pic(svg);
  std::string first;
  std::getline(pic, first);
  EXPECT_EQ(first.rfind("<svg", 0), 0u);

  // The written mesh fits as a file too, with the name from its stem.
  const std::string out2 = dir.file("from_file.json");
  ASSERT_EQ(run_skylit("spheres-fit " + obj + " -k 2 -o " + out2 + kQuick + "-q").status, 0);
  EXPECT_EQ(read_json(out2)["name"], "balloon");
  EXPECT_EQ(read_json(out2)["spheres"].size(), 2u);
}

TEST(CliSpheresFit, OverwriteOnlyWhenAsked) {
  ScratchDir dir;
  const std::string out = dir.file("set.json");
  ASSERT_EQ(run_skylit("spheres-fit --aircraft balloon -k 2 -o " + out + kQuick + "-q").status, 0);
  const auto again = run_skylit("spheres-fit --aircraft balloon -k 3 -o " + out + kQuick + "-q", true);
  EXPECT_EQ(again.status, 1);
  EXPECT_EQ(count_lines(again.out), 1) << again.out;
  EXPECT_NE(again.out.find("--overwrite"), std::string::npos) << again.out;
  EXPECT_EQ(read_json(out)["spheres"].size(), 2u);
  ASSERT_EQ(run_skylit("spheres-fit --aircraft balloon -k 3 -o " + out + kQuick + "--overwrite -q").status, 0);
  EXPECT_EQ(read_json(out)["spheres"].size(), 3u);
}

TEST(CliSpheresFit, BadInputFailsInOneLineAndLeavesNothing) {
  ScratchDir dir;
  const std::string out = " -o " + dir.file("out.json") + kQuick;
  std::ofstream(dir.file("open.obj")) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  std::ofstream(dir.file("bad.obj")) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n";
  expect_one_line_failure(dir, dir.file("open.obj") + out, "not closed");
  expect_one_line_failure(dir, dir.file("bad.obj") + out, "bad.obj:4: face index 7 outside 1..3");
  expect_one_line_failure(dir, dir.file("missing.obj") + out, "cannot read mesh");
  expect_one_line_failure(dir, "--aircraft zeppelin" + out, "unknown aircraft 'zeppelin'");
  expect_one_line_failure(dir, dir.file("open.obj") + " --aircraft glider" + out, "either a MESH file or --aircraft");
  expect_one_line_failure(dir, "--aircraft balloon -k 0" + out, "-k");
  expect_one_line_failure(dir, "--aircraft balloon -k 2 -o " + dir.file("no/such/dir/set.json") + kQuick, "cannot write");
}

}  // namespace
