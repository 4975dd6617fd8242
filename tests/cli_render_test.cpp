// `skylit render` end to end (headless EGL on llvmpipe, no X display) and its frame
// sink: the straight-down frame equals `skylit shade -p shaded` of the same field, time
// and aircraft; PNG frames and videos decoded by Debian's ffmpeg hold what was written;
// bad input fails in one line and leaves nothing behind.
#include "app/view/frame_sink.h"
#include "cli_test_util.h"
#include "shading/sky/time_utc.h"
#include "view/trail_colour.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace {

using skylit::terrain::testing::ScratchDir;
using skylit::testing::count_lines;
using skylit::testing::read_output;
using skylit::testing::run_skylit;
namespace fs = std::filesystem;

const std::string kTrack = std::string(SKYLIT_SOURCE_DIR) + "/data/tracks/sample_glider.igc";

// stdout of a shell command (its exit status in `status`).
std::string shell(const std::string& cmd, int* status = nullptr) {
  FILE* p = popen(cmd.c_str(), "r");
  std::string out;
  std::array<char, 65536> buf{};
  for (std::size_t n; (n = std::fread(buf.data(), 1, buf.size(), p)) > 0;) out.append(buf.data(), n);
  const int raw = pclose(p);
  if (status) *status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  return out;
}

// A test frame: a colour ramp that moves with k (smooth, so a video codec keeps it).
std::vector<std::uint8_t> ramp_frame(int w, int h, int k) {
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(w) * h * 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      std::uint8_t* p = &rgb[(static_cast<std::size_t>(y) * w + x) * 3];
      p[0] = static_cast<std::uint8_t>(40 + (x + 4 * k) * 160 / (w + 40));
      p[1] = static_cast<std::uint8_t>(40 + y * 160 / h);
      p[2] = static_cast<std::uint8_t>(200 - k * 10);
    }
  return rgb;
}

// Every frame of a video as RGB24, decoded by ffmpeg.
std::vector<std::uint8_t> decode(const std::string& video) {
  const std::string bytes = shell("ffmpeg -v error -i '" + video + "' -f rawvideo -pix_fmt rgb24 -");
  return {bytes.begin(), bytes.end()};
}

double rms(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b, std::size_t offset = 0) {
  double s = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    const double d = double(a[k]) - double(b[offset + k]);
    s += d * d;
  }
  return std::sqrt(s / a.size());
}

// PNG pixels as RGB24 through GDAL (band-sequential floats to interleaved bytes).
std::vector<std::uint8_t> png_rgb(const std::string& path, int* w = nullptr, int* h = nullptr) {
  const auto r = read_output(path);
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(r.w) * r.h * 3);
  for (int j = 0; j < r.h; ++j)
    for (int i = 0; i < r.w; ++i)
      for (int c = 0; c < 3; ++c) rgb[(static_cast<std::size_t>(j) * r.w + i) * 3 + c] = static_cast<std::uint8_t>(r.at(c, i, j));
  if (w) *w = r.w;
  if (h) *h = r.h;
  return rgb;
}

TEST(FrameSink, VideoDecodesToTheFramesWritten) {
  for (const std::string ext : {".mp4", ".webm"}) {
    ScratchDir dir;
    const int w = 96, h = 64, n = 6;
    skylit::app::view::SinkOptions o;
    o.width = w;
    o.height = h;
    o.fps = 12;
    o.frames = n;
    const std::string path = dir.file("clip" + ext);
    auto sink = skylit::app::view::open_frame_sink(path, o);
    for (int k = 0; k < n; ++k) sink->write(ramp_frame(w, h, k));
    EXPECT_FALSE(fs::exists(path)) << "the video appears only when finished";
    sink->finish();
    EXPECT_EQ(dir.listing(), std::vector<std::string>{"clip" + ext}) << "no temporaries left";
    EXPECT_EQ(shell("ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames,width,height "
                    "-of csv=p=0 '" + path + "'"),
              std::to_string(w) + "," + std::to_string(h) + "," + std::to_string(n) + "\n");
    const auto frames = decode(path);
    ASSERT_EQ(frames.size(), std::size_t(w) * h * 3 * n) << ext;
    for (int k = 0; k < n; ++k)  // yuv420p and a lossy codec: a few codes
      EXPECT_LT(rms(ramp_frame(w, h, k), frames, std::size_t(w) * h * 3 * k), 4.0) << ext << " frame " << k;
  }
}

TEST(FrameSink, PngFramesHoldTheBytesWritten) {
  ScratchDir dir;
  skylit::app::view::SinkOptions o;
  o.width = 33;
  o.height = 17;
  o.frames = 3;
  auto sink = skylit::app::view::open_frame_sink(dir.file("f_%03d.png"), o);
  for (int k = 0; k < 3; ++k) sink->write(ramp_frame(33, 17, k));
  sink->finish();
  EXPECT_EQ(dir.listing(), (std::vector<std::string>{"f_000.png", "f_001.png", "f_002.png"}));
  for (int k = 0; k < 3; ++k) EXPECT_EQ(png_rgb(dir.file("f_00" + std::to_string(k) + ".png")), ramp_frame(33, 17, k));
}

TEST(FrameSink, AnUnfinishedVideoLeavesNothing) {
  ScratchDir dir;
  skylit::app::view::SinkOptions o;
  o.width = 64;
  o.height = 64;
  {
    auto sink = skylit::app::view::open_frame_sink(dir.file("cut.mkv"), o);
    sink->write(ramp_frame(64, 64, 0));
  }
  EXPECT_TRUE(dir.listing().empty());
}

TEST(FrameSink, BadOutputsFailBeforeAnyFrame) {
  ScratchDir dir;
  skylit::app::view::SinkOptions o;
  o.width = 65;
  o.height = 64;
  o.frames = 2;
  auto fails = [&](const std::string& path, const std::string& needle) {
    try {
      skylit::app::view::open_frame_sink(path, o);
      ADD_FAILURE() << path << " opened";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  };
  fails(dir.file("odd.mp4"), "even");
  fails(dir.file("frames.png"), "%d");
  fails(dir.file("clip_%d.mp4"), "no %d");
  fails(dir.file("clip.avi"), ".mp4");
  fails(dir.file("missing/clip.webm"), "does not exist");
  o.width = 64;
  shell("touch '" + dir.file("f_1.png") + "'");
  fails(dir.file("f_%d.png"), "--overwrite");
  EXPECT_EQ(dir.listing(), std::vector<std::string>{"f_1.png"});
}

TEST(FrameSink, NoFfmpegSaysHowToGetIt) {
  ScratchDir dir;
  int status = 0;
  const std::string out = shell("env PATH=/nonexistent " + std::string(SKYLIT_BINARY) + " render --synthetic --scene-size 64 "
                                "--time 2026-06-21T10:00Z --lat 46 --lon 7 --size 64x64 -q -o '" + dir.file("a.mp4") +
                                "' 2>&1", &status);
  EXPECT_EQ(status, 1) << out;
  EXPECT_EQ(count_lines(out), 1) << out;
  EXPECT_NE(out.find("apt-get install ffmpeg"), std::string::npos) << out;
  EXPECT_TRUE(dir.listing().empty());
}

// The viewer's straight-down frame is the export tool's `shaded` picture: same field,
// time, sky and aircraft, one pixel per texel (issue: within 2 codes RMS).
TEST(Render, OrthoNadirFrameEqualsShadeShaded) {
  ScratchDir dir;
  const std::string dem = dir.file("scene.tif");
  ASSERT_EQ(run_skylit("scene --size 192 -q -o " + dem).status, 0);
  const std::string light = " --time 2026-06-21T10:02:00Z --sky preetham --track " + kTrack;
  const auto shade = run_skylit("shade " + dem + " -p shaded -q -o " + dir.file("shade.png") + light, true);
  ASSERT_EQ(shade.status, 0) << shade.out;
  // No X display: render is headless.
  const auto render = run_skylit("render " + dem + " --camera ortho-nadir --size 192x192 --from 2026-06-21T10:02:00Z "
                                 "--to 2026-06-21T10:02:00Z -q -o " + dir.file("nadir_%d.png") + light + " </dev/null",
                                 true);
  ASSERT_EQ(render.status, 0) << render.out;
  int w = 0, h = 0;
  const auto a = png_rgb(dir.file("shade.png"), &w, &h);
  const auto b = png_rgb(dir.file("nadir_0.png"));
  ASSERT_EQ(w, 192);
  ASSERT_EQ(b.size(), a.size());
  EXPECT_LT(rms(b, a), 2.0);
  // Not equal by being flat: the picture has relief and a dark side.
  const auto [lo, hi] = std::minmax_element(a.begin(), a.end());
  EXPECT_GT(*hi - *lo, 100);
}

TEST(Render, FollowFramesAndTheirVideoAgree) {
  ScratchDir dir;
  const std::string common = " --synthetic --track " + kTrack + " --size 160x90 --fps 2 --duration 1.5 -q";
  const auto png = run_skylit("render" + common + " -o " + dir.file("f_%02d.png"), true);
  ASSERT_EQ(png.status, 0) << png.out;
  EXPECT_EQ(dir.listing(), (std::vector<std::string>{"f_00.png", "f_01.png", "f_02.png", "f_03.png"}));
  const auto mp4 = run_skylit("render" + common + " -o " + dir.file("f.mp4"), true);
  ASSERT_EQ(mp4.status, 0) << mp4.out;
  const auto video = decode(dir.file("f.mp4"));
  ASSERT_EQ(video.size(), std::size_t(160) * 90 * 3 * 4);
  for (int k = 0; k < 4; ++k) {
    const auto frame = png_rgb(dir.file("f_0" + std::to_string(k) + ".png"));
    EXPECT_LT(rms(frame, video, frame.size() * k), 6.0) << "frame " << k;
  }
}

// A date alone is that local day's daylight: the frames run from sunrise to sunset, as
// `skylit sun` gives them for the place, in 30 s of video unless --speed says otherwise.
TEST(Render, ADateAloneRendersItsDaylight) {
  ScratchDir dir;
  const std::string place = " --lat 47 --lon 7.9";
  const auto r = run_skylit("render --synthetic --scene-size 64 --size 64x36 --camera orbit --time 2026-06-21 --fps 0.1" +
                                place + " -o " + dir.file("d_%d.png"),
                            true);
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_EQ(dir.listing(), (std::vector<std::string>{"d_0.png", "d_1.png", "d_2.png", "d_3.png"})) << r.out;
  const auto from = r.out.find(" from "), to = r.out.find(" to ", from);
  ASSERT_NE(to, std::string::npos) << r.out;
  const double start = skylit::sky::parse_utc_time(r.out.substr(from + 6, to - from - 6)).unix_seconds;
  const double end = skylit::sky::parse_utc_time(r.out.substr(to + 4, r.out.find(' ', to + 4) - to - 4)).unix_seconds;
  int status = 0;
  const std::string sun = shell(std::string(SKYLIT_BINARY) + " sun" + place + " --time 2026-06-21T12:00:00Z --json", &status);
  ASSERT_EQ(status, 0) << sun;
  const auto field = [&](const std::string& key) {
    const auto at = sun.find("\"" + key + "\": \"") + key.size() + 5;
    return skylit::sky::parse_utc_time(sun.substr(at, sun.find('"', at) - at)).unix_seconds;
  };
  EXPECT_NEAR(start, field("sunrise"), 1.0) << sun << r.out;
  EXPECT_NEAR(end, field("sunset"), 1.0) << sun << r.out;
}

// The tracks' trails are drawn over the terrain in altitude colours (viridis), and not
// at all with --trail off: the two frames differ only in trail-coloured pixels.
TEST(Render, TrailIsDrawnUnlessOff) {
  ScratchDir dir;
  const std::string common = " --synthetic --scene-size 256 --track " + kTrack +
                             " --from 2026-06-21T10:05:00Z --duration 0 --size 320x180 -q -o ";
  for (const char* trail : {"off", "altitude"}) {
    const auto r = run_skylit("render" + common + dir.file(std::string(trail) + "_%d.png") + " --trail " + trail, true);
    ASSERT_EQ(r.status, 0) << r.out;
  }
  const auto off = png_rgb(dir.file("off_0.png")), on = png_rgb(dir.file("altitude_0.png"));
  ASSERT_EQ(off.size(), on.size());
  int changed = 0, off_ramp = 0;
  for (std::size_t p = 0; p < on.size(); p += 3) {
    if (on[p] == off[p] && on[p + 1] == off[p + 1] && on[p + 2] == off[p + 2]) continue;
    ++changed;
    double nearest = 1e9;  // to the viridis ramp, in codes
    for (int k = 0; k <= 64; ++k) {
      const glm::vec3 c = skylit::view::ramp_colour(skylit::view::TrailColour::Altitude, k / 64.0) * 255.0f;
      nearest = std::min(nearest, static_cast<double>(std::max({std::abs(c.r - on[p]), std::abs(c.g - on[p + 1]),
                                                                  std::abs(c.b - on[p + 2])})));
    }
    off_ramp += nearest > 48.0;  // the line's antialiased rim blends with the ground
  }
  EXPECT_GT(changed, 50) << "the trail is drawn";
  EXPECT_LT(off_ramp, changed / 3) << "in the altitude ramp's colours";
}

// The patches drawn, from --timings' "frame 0: ... (N patches)".
int patches_drawn(const std::string& out) {
  const std::size_t at = out.find(" patches)");
  if (at == std::string::npos) return -1;
  const std::size_t open = out.rfind('(', at);
  return std::stoi(out.substr(open + 1, at - open - 1));
}

TEST(Render, ALargerMeshErrorDrawsFewerPatchesAndMovesOnlyEdges) {
  // The same frame at 2 px (the default) and 4 px: the LOD keeps fewer, coarser patches,
  // and the picture changes little (texture-space shading: the light is the same; only
  // silhouettes move, by a few pixels).
  ScratchDir dir;
  const std::string common = " --synthetic --scene-size 512 --track " + kTrack +
                             " --from 2026-06-21T10:05:00Z --duration 0 --size 640x360 --trail off --timings -q -o ";
  int patches[2] = {};
  for (int k : {0, 1}) {
    const std::string px = k == 0 ? "2" : "4";
    const auto r = run_skylit("render" + common + dir.file("e" + px + "_%d.png") + " --mesh-error " + px, true);
    ASSERT_EQ(r.status, 0) << r.out;
    patches[k] = patches_drawn(r.out);
  }
  EXPECT_GT(patches[0], 100) << "the frame shows terrain";
  EXPECT_LT(patches[1], 0.8 * patches[0]);
  const auto fine = png_rgb(dir.file("e2_0.png")), coarse = png_rgb(dir.file("e4_0.png"));
  ASSERT_EQ(fine.size(), coarse.size());
  EXPECT_LT(rms(fine, coarse), 8.0) << "codes";
}

TEST(Render, TrackOutsideTheDemIsANoteAndTheFramesAreWritten) {
  ScratchDir dir;
  const std::string far = skylit::testing::write_track_far_south(kTrack, dir.file("far.igc"));
  const auto r = run_skylit("render --synthetic --scene-size 64 --size 64x36 --track " + far + " --fps 1 --duration 1 -o " +
                                dir.file("f_%d.png"),
                            true);
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("skylit: note: track 1 lies outside the DEM"), std::string::npos) << r.out;
  EXPECT_EQ(read_output(dir.file("f_1.png")).w, 64);
  // The sample track itself flies over the 256² scene (7.7 km): no note.
  const auto over = run_skylit("render --synthetic --scene-size 256 --size 64x36 --track " + kTrack +
                                   " --fps 1 --duration 0 -o " + dir.file("g_%d.png"),
                               true);
  EXPECT_EQ(over.status, 0) << over.out;
  EXPECT_EQ(over.out.find("outside the DEM"), std::string::npos) << over.out;
}

TEST(Render, BadInputFailsInOneLine) {
  ScratchDir dir;
  auto fails = [&](const std::string& args, const std::string& needle) {
    const auto r = run_skylit("render " + args + " -q", true);
    EXPECT_TRUE(r.status == 1 || r.status == 2) << args << "\n" << r.out;
    EXPECT_EQ(count_lines(r.out), 1) << r.out;
    EXPECT_NE(r.out.find(needle), std::string::npos) << "expected '" << needle << "' in: " << r.out;
    EXPECT_TRUE(dir.listing().empty()) << args;
  };
  const std::string out = " -o " + dir.file("f_%d.png");
  fails("--synthetic --time 2026-06-21T10:00Z --camera sideways" + out, "--camera 'sideways'");
  fails("--synthetic --time 2026-06-21T10:00Z --size 640" + out, "WIDTHxHEIGHT");
  fails("--synthetic" + out, "--time");
  fails("--synthetic --time 2026-06-21T10:00Z --trail rainbow" + out, "--trail 'rainbow'");
  fails("--synthetic --time 2026-06-21T10:00Z --mesh-error 0.1" + out, "--mesh-error must be 0.5 to 16 pixels");
  fails("--synthetic --time 2026-12-21 --lat 85 --lon 0" + out, "polar night");
  fails("--synthetic --time 2026-02-30" + out, "invalid date '2026-02-30': no such day");  // a date's own error
  fails("--synthetic --time 2026-06-21T10:00Z --size 641x360 -o " + dir.file("v.mp4"), "even");
  fails("--synthetic --time 2026-06-21T10:00Z --speed 0" + out, "--speed");
  fails(dir.file("absent.tif") + " --time 2026-06-21T10:00Z" + out, "absent.tif");
  fails("--synthetic --time 2026-06-21T10:00Z --fps 1e9 --duration 10" + out, "--fps must be in (0, 1000]");
  // 1 + 2000 s × 1000 fps frames, counted in double (the int count overflowed before).
  fails("--synthetic --time 2026-06-21T10:00Z --fps 1000 --duration 2000" + out, "2000001 frames");
}

}  // namespace
