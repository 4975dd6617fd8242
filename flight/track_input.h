// What every track reader shares: a line reader with bounded memory, the binary-content
// check, the size cap of the XML formats, and the checks each fix must pass. Errors are
// std::invalid_argument with one line "NAME:LINE: problem" (NAME: the file or source).
#pragma once

#include <cstddef>
#include <istream>
#include <string>
#include <string_view>

#include "flight/track.h"

namespace skylit::flight::detail {

// A line longer than this is not a track line: the file is rejected, so one huge
// "line" cannot take unbounded memory.
inline constexpr std::size_t kMaxLineBytes = 64 * 1024;
// GPX and KML are parsed as one DOM (pugixml); larger files are rejected.
inline constexpr std::size_t kMaxXmlBytes = 256u * 1024 * 1024;
// Fixes per file: 58 days at 1 s. Bounds the memory a (malicious) file can make us hold.
inline constexpr std::size_t kMaxFixes = 5'000'000;
// Bytes examined for binary content and for the format (read_track_file's sniffing).
inline constexpr std::size_t kSniffBytes = 4096;

[[noreturn]] void fail(const std::string& name, std::size_t line, const std::string& problem);
[[noreturn]] void fail(const std::string& name, const std::string& problem);

// True when the bytes look like a binary file: a NUL byte, or more than 1 in 20
// control characters other than tab, CR, LF (UTF-8 text passes).
bool looks_binary(std::string_view head);

// Reads the stream line by line (CR LF or LF; a UTF-8 byte-order mark is skipped),
// counting lines, rejecting binary content and over-long lines.
class LineReader {
 public:
  LineReader(std::istream& in, std::string name);
  // The next line without its end; false at the end of the stream.
  bool next(std::string& line);
  std::size_t line_number() const { return line_; }
  const std::string& name() const { return name_; }

 private:
  std::istream& in_;
  std::string name_;
  std::size_t line_ = 0;
};

// The whole stream (at most kMaxXmlBytes, else an error), checked for binary content.
std::string read_bounded(std::istream& in, const std::string& name);

// File text for a message: in single quotes, control characters as '?', at most 40
// characters (then "..."), so an error stays one line whatever the file holds.
std::string quoted(std::string_view text);

// A name from the file (track id, callsign) fit for one-line output: control
// characters become spaces, surrounding spaces go.
std::string clean_name(std::string_view text);

// Latitude in [−90, 90], longitude in [−180, 180], both finite; else an error naming
// the line (0: no line number).
void check_coordinates(const std::string& name, std::size_t line, double lat, double lon);

// Appends a fix after checking that its time lies in the years 1900–2199 and after the
// track's last one, and that the file has not exceeded kMaxFixes.
void append_fix(Track& track, Fix fix, const std::string& name, std::size_t line);

// Empty result: "NAME: no track points (what)".
void require_fixes(const std::vector<Track>& tracks, const std::string& name, const std::string& what);

}  // namespace skylit::flight::detail
