// The viewer's window (skylit-view) under Xvfb, as a person would see it: an aircraft's
// shadow lands where the sun's ray through it meets flat ground (against the ray's own
// arithmetic, through the frame's logged view-projection), a free camera flown into
// the ground stays above it (against bilinear heights of the scene computed here), the
// same script gives the same frames, and what cannot start says so in one line.
#include "cli_test_util.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "app/common/altitude_arg.h"
#include "app/common/lighting_args.h"
#include "app/common/synthetic_scene.h"
#include "app/shade/tracked_aircraft.h"
#include "shading/lighting.h"
#include "shading/sky/time_utc.h"
#include "shading/time_series.h"
#include "view/scene_view.h"

namespace skylit::testing {
namespace {

using terrain::testing::ScratchDir;

const std::string kTrack = std::string(SKYLIT_SOURCE_DIR) + "/data/tracks/sample_glider.igc";

std::string missing_xvfb() {
  return std::system("command -v xvfb-run >/dev/null 2>&1") == 0 ? "" : "xvfb-run (package xvfb) is not installed";
}

// skylit-view in a fresh Xvfb server: its own exit status and its stdout and stderr,
// merged (not xvfb-run's: as it cleans up after a client that exits at once it may fail
// with a line of its own). `env`: variables for it; `args` without single quotes.
skylit::testing::Run run_view(const std::string& args, const std::string& env = "") {
  ScratchDir dir;
  const std::string out = dir.file("out.txt"), status = dir.file("status.txt");
  const skylit::testing::Run server =
      run_shell(env + " xvfb-run -a -s '-screen 0 1280x1024x24' sh -c '" + std::string(SKYLIT_VIEW_BINARY) + " " +
                args + " > " + out + " 2>&1; echo $? > " + status + "' 2>&1");
  std::ifstream text(out), code(status);
  skylit::testing::Run r{-1, std::string(std::istreambuf_iterator<char>(text), std::istreambuf_iterator<char>())};
  if (!(code >> r.status)) r = {server.status, r.out + server.out};  // the viewer never ran
  return r;
}

// skylit-view with no display: what must fail before a window opens.
skylit::testing::Run run_view_without_display(const std::string& args) {
  return run_shell("env -u DISPLAY -u WAYLAND_DISPLAY " + std::string(SKYLIT_VIEW_BINARY) + " " + args + " 2>&1");
}

std::string write_text(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
  return path;
}

struct CameraRow {
  int frame = 0;
  double time = 0;
  glm::dvec3 eye{0.0};
  int width = 0, height = 0;
  double shading_ms = 0;
  int horizons_computed = 0;
  long stale_texels = 0;  // shading still waiting for the refresh after a brush edit
  int sun_swept = 0;       // the sun's far slopes swept this frame, not kept from an earlier one
  glm::dmat4 view_proj{1.0};
};

std::vector<CameraRow> read_camera_log(const std::string& path) {
  std::ifstream f(path);
  std::string line;
  std::getline(f, line);  // header
  std::vector<CameraRow> rows;
  while (std::getline(f, line)) {
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream in(line);
    CameraRow r;
    in >> r.frame >> r.time >> r.eye.x >> r.eye.y >> r.eye.z >> r.width >> r.height >> r.shading_ms >> r.horizons_computed >> r.stale_texels >> r.sun_swept;
    for (int c = 0; c < 4; ++c)
      for (int k = 0; k < 4; ++k) in >> r.view_proj[c][k];
    if (in) rows.push_back(r);
  }
  return rows;
}

double luma(const OutputRaster& img, int i, int j) { return (img.at(0, i, j) + img.at(1, i, j) + img.at(2, i, j)) / 3.0; }

TEST(ViewWindow, AircraftShadowLandsWhereTheSunRayMeetsTheGround) {
  SKYLIT_REQUIRE(missing_xvfb());
  ScratchDir dir;
  // Where the sample track's aircraft is 60 s in, placed by the same CRS as the scene.
  const terrain::HeightField scene = app::make_georeferenced_scene(512, 1);
  const app::shade::TrackedAircraft on_scene(kTrack, "balloon", app::parse_altitude_arg("gnss"), scene);
  const double t = on_scene.start() + 60.0;
  const glm::dvec3 at = on_scene.pose_at(0, t)->position;
  const double easting = scene.georef.geotransform[0] + (at.x / scene.dx(0) + 0.5) * scene.georef.geotransform[1];
  const double northing = scene.georef.geotransform[3] + (-at.y / scene.dy + 0.5) * scene.georef.geotransform[5];

  // Flat ground at 500 m, 5 m texels, 3.2 km around the aircraft (its shadow lies 1.2 km
  // away: checked below).
  const int side = 640;
  const double dx = 5.0, ground = 500.0;
  terrain::testing::RasterSpec spec;
  spec.width = spec.height = side;
  spec.values.assign(static_cast<std::size_t>(side) * side, ground);
  spec.gt = {easting - 0.5 * side * dx, dx, 0, northing + 0.5 * side * dx, 0, -dx};
  spec.epsg = 32632;
  const std::string dem = terrain::testing::make_raster(dir.file("flat.tif"), spec);
  terrain::HeightField flat(side, side, dx);
  for (float& h : flat.heights) h = static_cast<float>(ground);
  flat.georef = terrain::testing::epsg_georef(32632, spec.gt);

  // The spheres' centre and the sun at t; the shadow: the ray from it away from the sun
  // meets z = 500.
  const app::shade::TrackedAircraft air(kTrack, "balloon", app::parse_altitude_arg("gnss"), flat);
  glm::dvec3 centre(0.0);
  const auto spheres = air.spheres_at(t);
  ASSERT_FALSE(spheres.empty());
  for (const auto& s : spheres) centre += s.centre / static_cast<double>(spheres.size());
  shading::LightingRequest request;
  request.time = shading::format_instant({t});
  request.sky = "preetham";
  const glm::dvec3 sun = shading::resolve_lighting(request, app::dem_place(flat)).lighting.sun.direction;
  ASSERT_GT(sun.z, 0.3);
  const glm::dvec3 shadow = centre - (centre.z - ground) / sun.z * sun;
  ASSERT_GT(centre.z - ground, 1000.0);

  // Straight down from 600 m over the shadow: the aircraft is above the eye, out of view.
  const double eye_height = 600.0;
  // The view's footprint (the window's vertical field, 400 × 300 px) around the shadow
  // lies on the DEM.
  const double tan_half_fovy = std::tan(0.5 * view::kFovyDeg * M_PI / 180.0);
  const double reach = eye_height * tan_half_fovy * 4.0 / 3.0;
  const double half = 0.5 * side * dx;  // the DEM's centre is (half, −half)
  ASSERT_LT(std::max(std::abs(shadow.x - half), std::abs(shadow.y + half)) + reach, half);
  std::ostringstream script;
  script << "0 pose " << shadow.x << " " << shadow.y << " " << ground + eye_height << " 0 -89\n";
  write_text(dir.file("s.txt"), script.str());
  const std::string common = dem + " --time " + request.time + " --width 400 --height 300 --frames 1 --script " +
                             dir.file("s.txt");
  const skylit::testing::Run with = run_view(common + " --track " + kTrack + " --aircraft balloon --screenshot " + dir.file("a.png") +
                            " --camera-log " + dir.file("a.csv"));
  ASSERT_EQ(with.status, 0) << with.out;
  const skylit::testing::Run without = run_view(common + " --screenshot " + dir.file("b.png"));
  ASSERT_EQ(without.status, 0) << without.out;
  const std::vector<CameraRow> log = read_camera_log(dir.file("a.csv"));
  ASSERT_EQ(log.size(), 1u);
  const OutputRaster a = read_output(dir.file("a.png")), b = read_output(dir.file("b.png"));
  ASSERT_EQ(a.w, 400);
  ASSERT_EQ(b.w, 400);

  glm::dvec4 clip = log[0].view_proj * glm::dvec4(shadow, 1.0);
  const double want_i = (clip.x / clip.w + 1.0) * 0.5 * a.w - 0.5, want_j = (1.0 - clip.y / clip.w) * 0.5 * a.h - 0.5;
  double weight = 0, si = 0, sj = 0, darkest = 0;
  for (int j = 0; j < a.h; ++j)
    for (int i = 0; i < a.w; ++i) {
      const double dark = luma(b, i, j) - luma(a, i, j);
      darkest = std::max(darkest, dark);
      if (dark <= 2.0) continue;
      weight += dark;
      si += dark * i;
      sj += dark * j;
    }
  ASSERT_GT(darkest, 20.0) << "the balloon's penumbra takes a good part of the sun";
  // Pixels to metres on the ground straight below: eye_height / pixels per radian.
  const double metres_per_px = eye_height * 2.0 * tan_half_fovy / a.h;
  EXPECT_LT(std::hypot(si / weight - want_i, sj / weight - want_j) * metres_per_px, 10.0)
      << "shadow centroid (" << si / weight << ", " << sj / weight << ") px, ray geometry (" << want_i << ", "
      << want_j << ")";
}

// Bilinear heights of the scene at field-frame (x, y), clamped to its edges.
double scene_ground(const terrain::HeightField& f, double x, double y) {
  const double fi = std::clamp(x / f.dx(0), 0.0, f.width - 1.0), fj = std::clamp(-y / f.dy, 0.0, f.height - 1.0);
  const int i = std::min(static_cast<int>(fi), f.width - 2), j = std::min(static_cast<int>(fj), f.height - 2);
  const double u = fi - i, v = fj - j;
  return (1 - u) * (1 - v) * f.at(i, j) + u * (1 - v) * f.at(i + 1, j) + (1 - u) * v * f.at(i, j + 1) +
         u * v * f.at(i + 1, j + 1);
}

TEST(ViewWindow, FreeCameraFlownIntoTheGroundStaysAboveIt) {
  SKYLIT_REQUIRE(missing_xvfb());
  ScratchDir dir;
  // The free camera 400 m over the field's centre, then: look down, full speed forward
  // and sideways for 4 s.
  const terrain::HeightField scene = app::make_georeferenced_scene(256, 1);
  const double cx = 128 * scene.mean_dx(), cy = -128 * scene.dy;
  std::ostringstream script;
  script << "0 pose " << cx << " " << cy << " " << scene_ground(scene, cx, cy) + 400.0
         << " 0 -30\n1 look 0 400\n2 hold w 120\n2 hold d 120\n2 hold shift 120\n122 quit\n";
  write_text(dir.file("s.txt"), script.str());
  const skylit::testing::Run r = run_view("--synthetic --scene-size 256 --camera orbit --time 2026-06-21T10:00:00Z --width 160 "
                         "--height 120 --script " + dir.file("s.txt") + " --camera-log " + dir.file("c.csv"));
  ASSERT_EQ(r.status, 0) << r.out;
  const std::vector<CameraRow> log = read_camera_log(dir.file("c.csv"));
  ASSERT_EQ(log.size(), 123u);
  double lowest = 1e9;
  for (const CameraRow& row : log) {
    const double clearance = row.eye.z - scene_ground(scene, row.eye.x, row.eye.y);
    EXPECT_GE(clearance, 3.0 - 1e-3) << "frame " << row.frame;
    lowest = std::min(lowest, clearance);
  }
  EXPECT_LT(lowest, 10.0) << "the camera did reach the ground";
  EXPECT_GT(glm::distance(log.front().eye, log.back().eye), 500.0) << "and moved over it";
}

TEST(ViewWindow, TheSameScriptGivesTheSameFrames) {
  SKYLIT_REQUIRE(missing_xvfb());
  ScratchDir dir;
  std::vector<OutputRaster> shots;
  for (const char* name : {"one.png", "two.png"}) {
    std::string script = std::string("0 press equal\n3 look 40 -10\n5 press 2\n8 wheel 2\n12 screenshot ") +
                         dir.file(name) + "\n12 quit\n";
    write_text(dir.file("s.txt"), script);
    const skylit::testing::Run r =
        run_view("--synthetic --track " + kTrack + " --width 320 --height 180 --script " + dir.file("s.txt"));
    ASSERT_EQ(r.status, 0) << r.out;
    shots.push_back(read_output(dir.file(name)));
  }
  ASSERT_EQ(shots[0].w, 320);
  ASSERT_EQ(shots[0].v.size(), shots[1].v.size());
  EXPECT_EQ(shots[0].v, shots[1].v);
  double spread = 0;  // not a blank frame
  for (float v : shots[0].v) spread = std::max(spread, std::abs(static_cast<double>(v) - shots[0].v[0]));
  EXPECT_GT(spread, 50.0);
}

TEST(ViewWindow, TrackOutsideTheDemIsANoteAndTheViewerRuns) {
  SKYLIT_REQUIRE(missing_xvfb());
  ScratchDir dir;
  const std::string far = skylit::testing::write_track_far_south(kTrack, dir.file("far.igc"));
  const skylit::testing::Run r = run_view("--synthetic --track " + far + " --width 160 --height 120 --frames 2 "
                         "--screenshot " + dir.file("f.png"));
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("outside the DEM"), std::string::npos) << r.out;
  EXPECT_EQ(read_output(dir.file("f.png")).w, 160);
}

// A DEM wider than one GPU frame takes (a sweep line of 2·16400 − 1 samples, over
// GL_MAX_TEXTURE_SIZE: 16384 on llvmpipe, 32768 on large GPUs) is halved until it fits,
// with a note, and the viewer runs.
TEST(ViewWindow, ADemTooLargeForTheGpuIsShownCoarserWithANote) {
  SKYLIT_REQUIRE(missing_xvfb());
  ScratchDir dir;
  terrain::testing::RasterSpec spec;
  spec.width = 16400;
  spec.height = 64;
  spec.values.resize(static_cast<std::size_t>(spec.width) * spec.height);
  for (int j = 0; j < spec.height; ++j)
    for (int i = 0; i < spec.width; ++i)
      spec.values[static_cast<std::size_t>(j) * spec.width + i] = 500.0 + 200.0 * std::sin(i * 0.01) * std::cos(j * 0.1);
  terrain::testing::make_raster(dir.file("wide.tif"), spec);
  const skylit::testing::Run r = run_view(dir.file("wide.tif") + " --time 2026-06-21T18:00Z --width 160 --height 120 "
                                          "--frames 2 --screenshot " + dir.file("w.png"));
  EXPECT_EQ(r.status, 0) << r.out;
  const std::size_t note = r.out.find("the DEM is too large for one GPU frame: shown at 1/");
  EXPECT_NE(note, std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("error"), std::string::npos) << r.out;
  EXPECT_EQ(read_output(dir.file("w.png")).w, 160);
}

// The sample track has 20 s of invalid fixes: there the aircraft is not drawn, the
// follow camera holds where it last saw it (not off to the field's centre), and the
// frames keep the horizons (the renderer's blocked kernels, with no spheres).
TEST(ViewWindow, ThroughATracksGapTheCameraHoldsAndTheHorizonsStay) {
  SKYLIT_REQUIRE(missing_xvfb());
  ScratchDir dir;
  // 16 frames 2 s of track time apart from 10:05:35Z, across the gap.
  const skylit::testing::Run r = run_view("--synthetic --scene-size 256 --track " + kTrack +
                                          " --time 2026-06-21T10:05:35Z --speed 8 --fps 4 --frames 16 --width 160 "
                                          "--height 120 --screenshot " + dir.file("g.png") + " --camera-log " +
                                          dir.file("c.csv"));
  ASSERT_EQ(r.status, 0) << r.out;
  const terrain::HeightField scene = app::make_georeferenced_scene(256, 1);
  const app::shade::TrackedAircraft air(kTrack, "glider", app::parse_altitude_arg("gnss"), scene);
  const std::vector<CameraRow> log = read_camera_log(dir.file("c.csv"));
  ASSERT_EQ(log.size(), 16u);
  int in_gap = 0, flown = 0;
  for (std::size_t k = 1; k < log.size(); ++k) {
    EXPECT_EQ(log[k].horizons_computed, 0) << "frame " << k;
    const double step = glm::distance(log[k].eye, log[k - 1].eye);
    if (!air.pose_at(0, log[k].time) && !air.pose_at(0, log[k - 1].time)) {
      ++in_gap;
      EXPECT_LT(step, 1.0) << "frame " << k << " in the gap";
    } else if (air.pose_at(0, log[k].time) && air.pose_at(0, log[k - 1].time)) {
      ++flown;
      EXPECT_GT(step, 20.0) << "frame " << k << " follows the aircraft";
    }
  }
  EXPECT_GE(in_gap, 5);
  EXPECT_GE(flown, 3);
}

// A date alone opens the clock midway through that day's daylight at the place, as
// `skylit sun` gives its sunrise and sunset.
TEST(ViewWindow, ADateAloneOpensAtItsSolarNoon) {
  SKYLIT_REQUIRE(missing_xvfb());
  ScratchDir dir;
  const std::string place = " --lat 47 --lon 7.9";
  const skylit::testing::Run r = run_view("--synthetic --scene-size 128 --time 2026-06-21" + place +
                                          " --width 160 --height 90 --frames 1 --screenshot " + dir.file("d.png") +
                                          " --camera-log " + dir.file("c.csv"));
  ASSERT_EQ(r.status, 0) << r.out;
  const std::vector<CameraRow> log = read_camera_log(dir.file("c.csv"));
  ASSERT_EQ(log.size(), 1u);
  const skylit::testing::Run sun = run_skylit("sun" + place + " --time 2026-06-21T12:00:00Z --json");
  ASSERT_EQ(sun.status, 0) << sun.out;
  const auto event = [&](const std::string& key) {
    const auto at = sun.out.find("\"" + key + "\": \"") + key.size() + 5;
    return sky::parse_utc_time(sun.out.substr(at, sun.out.find('"', at) - at)).unix_seconds;
  };
  EXPECT_NEAR(log[0].time, 0.5 * (event("sunrise") + event("sunset")), 1.0) << sun.out;
  EXPECT_NEAR(log[0].time, event("solar_noon"), 120.0) << sun.out;
}

struct BrushRun {
  OutputRaster before, after;  // frames 2 and 9
  std::vector<CameraRow> log;
};

// Looking south and down at a low morning sun; three raise clicks at the window's centre.
BrushRun run_brush(const ScratchDir& dir, int refresh_frames) {
  const std::string tag = std::to_string(refresh_frames);
  write_text(dir.file("s.txt"), "0 pose 7650 -5650 3500 180 -45\n0 press b\n2 screenshot " + dir.file("a" + tag + ".png") +
                                    "\n3 click 160 90\n4 click 160 90\n5 click 160 90\n9 screenshot " +
                                    dir.file("b" + tag + ".png") + "\n9 quit\n");
  const skylit::testing::Run r = run_view("--synthetic --time 2026-06-21T05:00:00Z --width 320 --height 180 --script " +
                                          dir.file("s.txt") + " --camera-log " + dir.file("c" + tag + ".csv") +
                                          " --refresh-frames " + tag);
  EXPECT_EQ(r.status, 0) << r.out;
  return {read_output(dir.file("a" + tag + ".png")), read_output(dir.file("b" + tag + ".png")),
          read_camera_log(dir.file("c" + tag + ".csv"))};
}

TEST(ViewWindow, BrushChangesTheTerrainUnderTheClick) {
  SKYLIT_REQUIRE(missing_xvfb());
  ScratchDir dir;
  // --refresh-frames 0: every click's frame computes all the horizons again.
  const BrushRun whole = run_brush(dir, 0);
  const OutputRaster &a = whole.before, &b = whole.after;
  ASSERT_EQ(a.w, 320);
  ASSERT_EQ(b.w, 320);
  double near = 0, far = 0;
  int n_near = 0, n_far = 0;
  for (int j = 0; j < a.h; ++j)
    for (int i = 0; i < a.w; ++i) {
      const double d = std::abs(luma(b, i, j) - luma(a, i, j));
      const bool close = std::abs(i - 160) < 20 && std::abs(j - 90) < 20;
      (close ? near : far) += d;
      ++(close ? n_near : n_far);
    }
  near /= n_near;
  far /= n_far;
  EXPECT_GT(near, 1.0) << "the raised ground shows";
  EXPECT_GT(near, 10.0 * far) << "where it was clicked: " << near << " against " << far << " elsewhere";
  ASSERT_EQ(whole.log.size(), 10u);
  for (const CameraRow& row : whole.log) {
    EXPECT_EQ(row.horizons_computed, row.frame == 0 || (row.frame >= 3 && row.frame <= 5) ? 1 : 0) << row.frame;
    EXPECT_EQ(row.stale_texels, 0) << row.frame;
  }

  // --refresh-frames 2: each click's frame computes the horizons near the click and leaves
  // the rest of the field stale; the two frames after the last click refresh it, half
  // each, and then the horizons are kept again.
  const BrushRun part = run_brush(dir, 2);
  const std::vector<CameraRow>& log = part.log;
  ASSERT_EQ(log.size(), 10u);
  const long texels = 512L * 512L;  // the synthetic scene's default size
  for (int k : {0, 1, 2}) EXPECT_EQ(log[k].stale_texels, 0) << k;
  EXPECT_EQ(log[0].horizons_computed, 1);
  EXPECT_EQ(log[1].horizons_computed + log[2].horizons_computed, 0);
  for (int k : {3, 4, 5}) {
    EXPECT_EQ(log[k].horizons_computed, 1) << k;
    EXPECT_GT(log[k].stale_texels, texels / 2) << k << ": the click's area alone";
  }
  EXPECT_GT(log[6].stale_texels, 0);
  EXPECT_LT(log[6].stale_texels, log[5].stale_texels - texels / 4);
  EXPECT_EQ(log[7].stale_texels, 0);
  EXPECT_EQ(log[7].horizons_computed, 1);
  for (int k : {8, 9}) EXPECT_EQ(log[k].horizons_computed + log[k].stale_texels, 0) << k;
  // The sun stands still: its far slopes are swept on the first frame and on each edit's,
  // and kept on every other (view::kSunHeadingTolerance).
  for (const CameraRow& row : log) EXPECT_EQ(row.sun_swept, row.frame == 0 || (row.frame >= 3 && row.frame <= 5) ? 1 : 0) << row.frame;
  // Refreshed texels are marched where the whole frame sweeps: the two methods' horizons
  // differ by about half a code on average, a few codes at most (docs/viewer.md).
  ASSERT_EQ(part.after.v.size(), b.v.size());
  double mean = 0, worst = 0;
  for (int j = 0; j < b.h; ++j)
    for (int i = 0; i < b.w; ++i) {
      const double d = std::abs(luma(part.after, i, j) - luma(b, i, j));
      mean += d;
      worst = std::max(worst, d);
    }
  mean /= b.w * b.h;
  EXPECT_LT(mean, 1.0) << "the refreshed frame against the whole recompute, codes";
  EXPECT_LT(worst, 6.0);
}

TEST(ViewWindow, ADragBrushesAlongThePath) {
  SKYLIT_REQUIRE(missing_xvfb());
  ScratchDir dir;
  // The brush test's view; the button down at (100, 90), dragged to (220, 90) over frames 3 … 7.
  write_text(dir.file("s.txt"), "0 pose 7650 -5650 3500 180 -45\n0 press b\n2 screenshot " + dir.file("a.png") +
                                    "\n3 drag 100 90 220 90 4\n9 screenshot " + dir.file("b.png") + "\n9 quit\n");
  const skylit::testing::Run r = run_view("--synthetic --time 2026-06-21T05:00:00Z --width 320 --height 180 --script " +
                                          dir.file("s.txt") + " --camera-log " + dir.file("c.csv") + " --refresh-frames 0");
  ASSERT_EQ(r.status, 0) << r.out;
  const OutputRaster a = read_output(dir.file("a.png")), b = read_output(dir.file("b.png"));
  ASSERT_EQ(a.w, 320);
  ASSERT_EQ(b.w, 320);
  // Mean change in a 17×17 box around (ci, cj), and away from the path's band.
  auto change = [&](int ci, int cj) {
    double sum = 0;
    int n = 0;
    for (int j = cj - 8; j <= cj + 8; ++j)
      for (int i = ci - 8; i <= ci + 8; ++i, ++n) sum += std::abs(luma(b, i, j) - luma(a, i, j));
    return sum / n;
  };
  double far = 0;
  int n_far = 0;
  for (int j = 0; j < a.h; ++j)
    for (int i = 0; i < a.w; ++i)
      if (std::abs(j - 90) > 40 || i < 60 || i > 260) {
        far += std::abs(luma(b, i, j) - luma(a, i, j));
        ++n_far;
      }
  far /= n_far;
  for (int ci : {105, 160, 215}) {
    EXPECT_GT(change(ci, 90), 1.0) << "the ridge at x = " << ci;
    EXPECT_GT(change(ci, 90), 10.0 * far) << ci;
  }
  // Every frame with the button down and the cursor moved by half a radius or more edits.
  const std::vector<CameraRow> log = read_camera_log(dir.file("c.csv"));
  ASSERT_EQ(log.size(), 10u);
  for (const CameraRow& row : log)
    EXPECT_EQ(row.horizons_computed, row.frame == 0 || (row.frame >= 3 && row.frame <= 7) ? 1 : 0) << row.frame;
}

TEST(ViewWindow, NoDisplayPointsToRender) {
  const skylit::testing::Run r = run_shell("env -u DISPLAY -u WAYLAND_DISPLAY " + std::string(SKYLIT_BINARY) +
                                           " view --synthetic --time 2026-06-21T10:00:00Z 2>&1");
  const std::string& out = r.out;
  EXPECT_EQ(r.status, 1) << out;
  EXPECT_NE(out.find("skylit render"), std::string::npos) << out;
  EXPECT_EQ(std::count(out.begin(), out.end(), '\n'), 1) << out;
}

// A display whose OpenGL stops short of 4.5 (Mesa told to offer 4.3; under Xvfb GLX is
// always Mesa's): one line that says so, and no window.
TEST(ViewWindow, NoOpenGl45SaysSoInOneLine) {
  SKYLIT_REQUIRE(missing_xvfb());
  ScratchDir dir;
  const skylit::testing::Run r = run_view("--synthetic --time 2026-06-21T10:00:00Z --frames 2 --screenshot " +
                                              dir.file("x.png"),
                                          "MESA_GL_VERSION_OVERRIDE=4.3");
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_NE(r.out.find("no OpenGL 4.5 core context"), std::string::npos) << r.out;
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
  EXPECT_FALSE(std::filesystem::exists(dir.file("x.png")));
}

// Without a display: the error is the option's, not the display's, so it came first.
TEST(ViewWindow, ABadScreenshotPathFailsBeforeTheWindowOpens) {
  ScratchDir dir;
  const skylit::testing::Run r = run_view_without_display("--synthetic --time 2026-06-21T10:00:00Z --frames 1 "
                                                          "--screenshot " + dir.file("missing/shot.png"));
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_NE(r.out.find("the folder"), std::string::npos) << r.out;
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
}

TEST(ViewWindow, ABadMeshErrorFailsBeforeTheWindowOpens) {
  for (const char* px : {"0", "17", "nan"}) {
    const skylit::testing::Run r =
        run_view_without_display(std::string("--synthetic --time 2026-06-21T10:00:00Z --mesh-error ") + px);
    EXPECT_EQ(r.status, 1) << px << ": " << r.out;
    EXPECT_NE(r.out.find("--mesh-error must be 0.5 to 16 pixels"), std::string::npos) << r.out;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
  }
}

TEST(ViewWindow, BadScriptFailsInOneLineBeforeTheWindowOpens) {
  ScratchDir dir;
  write_text(dir.file("s.txt"), "0 press w\n3 fly away\n");
  const skylit::testing::Run r =
      run_view_without_display("--synthetic --time 2026-06-21T10:00:00Z --script " + dir.file("s.txt"));
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
  EXPECT_NE(r.out.find("s.txt:2: unknown verb 'fly'"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace skylit::testing
