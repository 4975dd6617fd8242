#include "app/view/frame_sink.h"

#include "app/common/frame_pattern.h"
#include "terrain/raster_writer.h"

#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <future>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <fcntl.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace skylit::app::view {

void check_folder(const std::filesystem::path& path, const std::string& what) {
  namespace fs = std::filesystem;
  const fs::path dir = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw std::invalid_argument(what + " '" + path.string() + "': the folder '" + dir.string() + "' does not exist");
}

void check_absent(const std::filesystem::path& path, bool overwrite, const std::string& what) {
  std::error_code ec;
  if (!overwrite && std::filesystem::exists(path, ec))
    throw std::invalid_argument(what + " '" + path.string() + "' exists (--overwrite replaces it)");
}

void write_rgb_png(const std::string& path, int width, int height, std::span<const std::uint8_t> rgb, bool overwrite) {
  terrain::RasterWriteOptions w;
  w.format = "PNG";
  // zlib level 3: a 1280×720 frame of the sample flight encodes in 0.45× level 6's time
  // (~100 ms against ~230 ms on the CI-class VM) for 5.5 % more bytes.
  w.creation_options = {"ZLEVEL=3"};
  w.layout = terrain::SampleLayout::PixelInterleaved;
  w.overwrite = overwrite;
  terrain::GeoReference none;
  none.has_geotransform = false;
  terrain::write_raster(path, none, width, height, 3, rgb, w);
}

namespace {

namespace fs = std::filesystem;

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// --- PNG frames -------------------------------------------------------------------

class PngFrames final : public FrameSink {
 public:
  PngFrames(std::string pattern, const SinkOptions& o) : pattern_(std::move(pattern)), options_(o) {
    check_folder(frame_path(pattern_, 0));
    if (o.frames > 1 && frame_path(pattern_, 0) == frame_path(pattern_, 1))
      throw std::invalid_argument("output '" + pattern_ + "' names every frame alike");
    for (int k = 0; k < o.frames; ++k) check_absent(frame_path(pattern_, k), o.overwrite);
  }
  ~PngFrames() override {
    if (writing_.valid()) writing_.wait();
  }
  // Frame k is encoded on another thread while frame k + 1 is drawn; one at a time.
  void write(std::span<const std::uint8_t> rgb) override {
    wait_for_write();
    writing_ = std::async(std::launch::async, [this, path = frame_path(pattern_, next_++),
                                               frame = std::vector<std::uint8_t>(rgb.begin(), rgb.end())] {
      write_rgb_png(path, options_.width, options_.height, frame, options_.overwrite);
    });
  }
  void finish() override { wait_for_write(); }
  std::string description() const override {
    if (next_ == 0) return pattern_ + " (PNG frames)";  // none written yet
    return pattern_ + " (" + std::to_string(next_) + " PNG frame" + (next_ == 1 ? "" : "s") + ")";
  }

 private:
  void wait_for_write() {
    if (writing_.valid()) writing_.get();  // rethrows the writer's error here
  }
  std::string pattern_;
  SinkOptions options_;
  int next_ = 0;
  std::future<void> writing_;
};

// --- ffmpeg ---------------------------------------------------------------------------

struct Child {
  pid_t pid = -1;
};

// Starts `argv` (found on PATH) with stdin from `in`, stdout to `out` and stderr to `err`
// (-1: /dev/null). nullopt when the program is not installed.
std::optional<Child> spawn(const std::vector<std::string>& argv, int in, int out, int err) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  const int fds[3] = {in, out, err};
  for (int k = 0; k < 3; ++k) {
    if (fds[k] >= 0) posix_spawn_file_actions_adddup2(&actions, fds[k], k);
    else posix_spawn_file_actions_addopen(&actions, k, "/dev/null", k == 0 ? O_RDONLY : O_WRONLY, 0);
  }
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = -1;
  const int rc = posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc == ENOENT) return std::nullopt;
  if (rc != 0) throw std::runtime_error("cannot start " + argv[0] + ": " + std::strerror(rc));
  return Child{pid};
}

// The exit status of a child (−1 when it died of a signal).
int wait_for(Child c) {
  int status = 0;
  while (waitpid(c.pid, &status, 0) < 0 && errno == EINTR) {
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

const char* kInstallFfmpeg = "ffmpeg is not installed (apt-get install ffmpeg), or write PNG frames (frames_%05d.png)";

// The video encoders this ffmpeg has, from `ffmpeg -encoders`.
std::string ffmpeg_encoders() {
  int fds[2];
  if (pipe(fds) != 0) throw std::runtime_error(std::string("cannot make a pipe: ") + std::strerror(errno));
  const auto child = spawn({"ffmpeg", "-hide_banner", "-encoders"}, -1, fds[1], -1);
  close(fds[1]);
  std::string text;
  char buf[4096];
  for (ssize_t n; (n = read(fds[0], buf, sizeof buf)) != 0;) {
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) break;
    text.append(buf, static_cast<std::size_t>(n));
  }
  close(fds[0]);
  if (!child) throw std::invalid_argument(kInstallFfmpeg);
  wait_for(*child);
  return text;
}

bool has_encoder(const std::string& list, const std::string& name) {
  std::istringstream lines(list);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::string flags, encoder;
    if (words >> flags >> encoder && flags.size() == 6 && flags[0] == 'V' && encoder == name) return true;
  }
  return false;
}

struct Codec {
  std::string muxer;  // ffmpeg -f
  std::vector<std::string> args;
  std::string name;
};

// H.264 where the container takes it and ffmpeg has libx264, else VP9.
Codec choose_codec(const std::string& ext, const fs::path& path) {
  const std::string encoders = ffmpeg_encoders();
  const bool h264 = ext != ".webm" && has_encoder(encoders, "libx264");
  const bool vp9 = ext != ".mov" && has_encoder(encoders, "libvpx-vp9");
  const std::string muxer = ext == ".mp4" ? "mp4" : ext == ".mkv" ? "matroska" : ext == ".mov" ? "mov" : "webm";
  if (h264)
    return {muxer, {"-c:v", "libx264", "-preset", "medium", "-crf", "18", "-pix_fmt", "yuv420p"}, "H.264"};
  if (vp9)
    return {muxer, {"-c:v", "libvpx-vp9", "-crf", "24", "-b:v", "0", "-row-mt", "1", "-pix_fmt", "yuv420p"}, "VP9"};
  throw std::invalid_argument("output '" + path.string() + "': this ffmpeg has no " +
                              (ext == ".webm" ? "libvpx-vp9" : ext == ".mov" ? "libx264" : "libx264 or libvpx-vp9") +
                              " encoder (Debian's ffmpeg has both), or write PNG frames (frames_%05d.png)");
}

// A video: raw RGB frames into ffmpeg's stdin, through a socket so that a dead encoder
// gives EPIPE from send(MSG_NOSIGNAL) instead of killing this process with SIGPIPE.
class FfmpegVideo final : public FrameSink {
 public:
  FfmpegVideo(fs::path path, const std::string& ext, const SinkOptions& o) : path_(std::move(path)), options_(o) {
    check_folder(path_);
    check_absent(path_, o.overwrite);
    if (o.width % 2 != 0 || o.height % 2 != 0)
      throw std::invalid_argument("output '" + path_.string() + "': a video's sides must be even (--size " +
                                  std::to_string(o.width) + "x" + std::to_string(o.height) + ")");
    const Codec codec = choose_codec(ext, path_);
    codec_ = codec.name;
    const fs::path dir = path_.parent_path().empty() ? fs::path(".") : path_.parent_path();
    std::string temp = (dir / ("." + path_.filename().string() + ".tmp-XXXXXX")).string();
    const int fd = mkstemp(temp.data());
    if (fd < 0) throw std::runtime_error("output '" + path_.string() + "': cannot create a temporary file: " + std::strerror(errno));
    const mode_t mask = umask(0);  // mkstemp makes 0600; the video gets what a new file would
    umask(mask);
    fchmod(fd, 0666 & ~mask);
    close(fd);
    temp_ = temp;
    std::string log = (dir / ("." + path_.filename().string() + ".log-XXXXXX")).string();
    log_fd_ = mkstemp(log.data());
    if (log_fd_ < 0) {
      discard();
      throw std::runtime_error("output '" + path_.string() + "': cannot create a temporary file: " + std::strerror(errno));
    }
    log_ = log;
    int fds[2];
    if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds) != 0) {
      discard();
      throw std::runtime_error(std::string("cannot make a socket pair: ") + std::strerror(errno));
    }
    char rate[32];
    std::snprintf(rate, sizeof rate, "%.9g", o.fps);
    std::vector<std::string> argv = {"ffmpeg", "-hide_banner", "-loglevel", "error", "-nostdin", "-y",
                                     "-f", "rawvideo", "-pix_fmt", "rgb24",
                                     "-s", std::to_string(o.width) + "x" + std::to_string(o.height),
                                     "-r", rate, "-i", "pipe:0"};
    argv.insert(argv.end(), codec.args.begin(), codec.args.end());
    if (codec.muxer == "mp4" || codec.muxer == "mov") argv.insert(argv.end(), {"-movflags", "+faststart"});
    argv.insert(argv.end(), {"-f", codec.muxer, temp_.string()});
    const auto child = spawn(argv, fds[0], -1, log_fd_);
    close(fds[0]);
    if (!child) {
      close(fds[1]);
      discard();
      throw std::invalid_argument(kInstallFfmpeg);
    }
    child_ = *child;
    socket_ = fds[1];
  }
  ~FfmpegVideo() override {
    if (socket_ >= 0) close(socket_);
    if (child_.pid > 0) {
      kill(child_.pid, SIGTERM);
      wait_for(child_);
    }
    discard();
  }
  void write(std::span<const std::uint8_t> rgb) override {
    if (rgb.size() != static_cast<std::size_t>(options_.width) * options_.height * 3)
      throw std::logic_error("frame sink: a frame of the wrong size");
    if (socket_ < 0) throw std::logic_error("frame sink: write after finish");
    std::size_t done = 0;
    while (done < rgb.size()) {
      const ssize_t n = send(socket_, rgb.data() + done, rgb.size() - done, MSG_NOSIGNAL);
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) fail("ffmpeg stopped reading frames");
      done += static_cast<std::size_t>(n);
    }
    ++frames_;
  }
  void finish() override {
    close(socket_);
    socket_ = -1;
    const int status = wait_for(child_);
    child_.pid = -1;
    if (status != 0) fail("ffmpeg failed (exit status " + std::to_string(status) + ")");
    std::error_code ec;
    fs::rename(temp_, path_, ec);
    if (ec) fail("cannot rename the finished video into place: " + ec.message());
    temp_.clear();
    discard();
  }
  std::string description() const override {
    if (frames_ == 0) return path_.string() + " (" + codec_ + " by ffmpeg)";  // none written yet
    return path_.string() + " (" + std::to_string(frames_) + " frames, " + codec_ + " by ffmpeg)";
  }

 private:
  [[noreturn]] void fail(const std::string& what) {
    std::string detail;
    if (!log_.empty()) {
      std::ifstream in(log_);
      for (std::string line; std::getline(in, line);)
        if (!line.empty()) detail = line;  // ffmpeg's last word says why
    }
    if (socket_ >= 0) close(socket_);
    socket_ = -1;
    if (child_.pid > 0) wait_for(child_);
    child_.pid = -1;
    discard();
    throw std::runtime_error("output '" + path_.string() + "': " + what + (detail.empty() ? "" : ": " + detail));
  }
  void discard() {
    std::error_code ec;
    if (!temp_.empty()) fs::remove(temp_, ec);
    temp_.clear();
    if (log_fd_ >= 0) close(log_fd_);
    log_fd_ = -1;
    if (!log_.empty()) fs::remove(log_, ec);
    log_.clear();
  }

  fs::path path_, temp_, log_;
  SinkOptions options_;
  std::string codec_;
  Child child_;
  int socket_ = -1, log_fd_ = -1;
  int frames_ = 0;
};

}  // namespace

std::unique_ptr<FrameSink> open_frame_sink(const std::string& path, const SinkOptions& options) {
  if (options.width < 1 || options.height < 1 || options.frames < 0)
    throw std::logic_error("frame sink: no frame size");
  if (!(options.fps > 0.0) || options.fps > kMaxFrameRate)
    throw std::invalid_argument("the frame rate must be in (0, " + std::to_string(static_cast<int>(kMaxFrameRate)) +
                                "] frames per second");
  const std::string ext = lower(fs::path(path).extension().string());
  if (ext == ".png") {
    if (!frame_pattern(path))
      throw std::invalid_argument("output '" + path + "': PNG frames need a %d for the frame number (frames_%05d.png)");
    return std::make_unique<PngFrames>(path, options);
  }
  if (ext == ".mp4" || ext == ".mkv" || ext == ".mov" || ext == ".webm") {
    if (path.find('%') != std::string::npos)
      throw std::invalid_argument("output '" + path + "': a video is one file: give it no %d");
    return std::make_unique<FfmpegVideo>(path, ext, options);
  }
  throw std::invalid_argument("output '" + path + "': give frames_%05d.png (PNG frames) or a video (.mp4, .mkv, .mov, .webm)");
}

}  // namespace skylit::app::view
