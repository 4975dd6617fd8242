// `skylit shade --max-error E` end to end: bad input, the note when knobs are explicit,
// and the check: on a crop of a real DEM that did not build the front
// (mt_st_helens; the front used big_tujunga, slovenia and the synthetic scene), the
// chosen setting's RMSE against `--exact` is at most E.
#include "cli_test_util.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>

namespace skylit::testing {
namespace {

namespace fs = std::filesystem;

// A scratch folder per test, removed after it.
class CliMaxError : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("skylit_max_error_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  const fs::path& temp_dir() const { return dir_; }

 private:
  fs::path dir_;
};

TEST_F(CliMaxError, BadInputIsOneLineAndNoFile) {
  const fs::path out = temp_dir() / "bad.tif";
  for (const std::string arg : {"0", "-0.1", "abc", "nan"}) {
    const skylit::testing::Run r = run_skylit("shade --synthetic --size 32 -p svf --max-error " + arg + " -o " + out.string(), true);
    EXPECT_NE(r.status, 0) << arg;
    EXPECT_EQ(count_lines(r.out), 1) << arg << ": " << r.out;
    EXPECT_FALSE(fs::exists(out)) << arg;
  }
  const skylit::testing::Run r = run_skylit("shade --synthetic --size 32 -p horizon --max-error 0.01 -o " + out.string(), true);
  EXPECT_NE(r.status, 0);
  EXPECT_EQ(count_lines(r.out), 1) << r.out;
  EXPECT_NE(r.out.find("svf, skyview or shaded"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(CliMaxError, ChoiceLineAndExplicitKnobsWinWithANote) {
  const fs::path out = temp_dir() / "note.tif";
  skylit::testing::Run r = run_skylit("shade --synthetic --size 32 -p svf --max-error 0.05 --overwrite -o " + out.string(), true);
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("--max-error 0.05: W"), std::string::npos) << r.out;
  r = run_skylit("shade --synthetic --size 32 -p svf --max-error 0.05 --azimuths 7 --overwrite -o " + out.string(), true);
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("note: --azimuths given explicitly"), std::string::npos) << r.out;
  r = run_skylit("shade --synthetic --size 32 -p svf --max-error 1e-9 --overwrite -o " + out.string(), true);
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("no setting on the front meets it"), std::string::npos) << r.out;
}

double rmse(const OutputRaster& a, const OutputRaster& b) {
  double s = 0;
  int n = 0;
  for (std::size_t k = 0; k < a.v.size(); ++k)
    if (std::isfinite(a.v[k]) && std::isfinite(b.v[k])) s += (a.v[k] - b.v[k]) * (a.v[k] - b.v[k]), ++n;
  return n ? std::sqrt(s / n) : NAN;
}

TEST_F(CliMaxError, MeasuredErrorOnARealDemMeetsTheTarget) {
  const fs::path dem = fs::path(SKYLIT_SHARED_DIR) / "dem" / "mt_st_helens_usgs30_utm10n.tif";
  SKYLIT_REQUIRE(terrain::testing::missing_file(dem.string()));
  const fs::path d = temp_dir(), crop = d / "crop.tif";
  ASSERT_EQ(std::system(("gdal_translate -q -srcwin 100 150 96 96 " + dem.string() + " " + crop.string()).c_str()), 0);
  struct Case { std::string product; std::vector<double> targets; };
  for (const Case& c : {Case{"svf", {0.02, 0.005}}, Case{"skyview", {0.01}}}) {
    const fs::path exact = d / (c.product + "_exact.tif");
    ASSERT_EQ(run_skylit("shade " + crop.string() + " -q -p " + c.product + " --exact --backend reference --overwrite -o " +
                         exact.string()).status, 0);
    const OutputRaster truth = read_output(exact.string());
    for (double e : c.targets) {
      const fs::path out = d / (c.product + "_" + std::to_string(e) + ".tif");
      const skylit::testing::Run r = run_skylit("shade " + crop.string() + " -p " + c.product + " --max-error " + std::to_string(e) +
                               " --backend reference --overwrite -o " + out.string(), true);
      ASSERT_EQ(r.status, 0) << r.out;
      ASSERT_EQ(r.out.find("no setting"), std::string::npos) << r.out;
      const double err = rmse(read_output(out.string()), truth);
      EXPECT_LE(err, e) << c.product << " E " << e << ": " << r.out;
      std::printf("%s E %g: measured RMSE %g\n", c.product.c_str(), e, err);
    }
  }
  fs::remove_all(d);
}

}  // namespace
}  // namespace skylit::testing
