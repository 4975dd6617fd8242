// Where `render`'s frames go: numbered PNGs (frames_%05d.png, from 0 as ffmpeg reads
// them) or a video encoded by piping raw RGB frames to Debian's ffmpeg (.mp4/.mkv/.mov:
// H.264 yuv420p, VP9 where this ffmpeg has no libx264; .webm: VP9). Every check that can
// fail before the first frame fails in open_frame_sink; a video is written to a hidden
// temporary next to its target and renamed into place by finish(), so no partial video
// is ever left (a sink destroyed before finish() removes what it wrote).
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>

namespace skylit::app::view {

// Frame rates a sink takes: (0, kMaxFrameRate] frames per video second.
inline constexpr double kMaxFrameRate = 1000.0;

struct SinkOptions {
  int width = 0, height = 0;  // every frame's size (videos: even sides)
  double fps = 30.0;          // frames per video second
  int frames = 1;             // how many frames will come (PNG names are checked up front)
  bool overwrite = false;     // false: an existing output is an error
};

class FrameSink {
 public:
  virtual ~FrameSink() = default;
  // One frame, RGB8 rows top first (width·height·3 bytes).
  virtual void write(std::span<const std::uint8_t> rgb) = 0;
  // Completes the output (the video appears at its path); throws on any failure.
  virtual void finish() = 0;
  // "frames/f_%05d.png (20 PNG frames)", "flight.mp4 (300 frames, H.264 by ffmpeg)"; the
  // count only once frames are written.
  virtual std::string description() const = 0;
};

// Throw std::invalid_argument with one line ("<what> 'PATH': …") when PATH's folder is
// missing, or PATH exists and overwrite is off.
void check_folder(const std::filesystem::path& path, const std::string& what = "output");
void check_absent(const std::filesystem::path& path, bool overwrite, const std::string& what = "output");
// An RGB8 image (rows top first) as a PNG without georeferencing.
void write_rgb_png(const std::string& path, int width, int height, std::span<const std::uint8_t> rgb, bool overwrite);

// Throws std::invalid_argument with one line: an unknown extension, a PNG name without
// or with a bad %d, a missing folder, an existing output without overwrite, odd sides
// for a video, ffmpeg missing or lacking both encoders.
std::unique_ptr<FrameSink> open_frame_sink(const std::string& path, const SinkOptions& options);

}  // namespace skylit::app::view
