#include "flight/track_input.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "flight/track_time.h"

namespace skylit::flight::detail {
namespace {

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

// Times a track may hold: 1900-01-01 to 2200-01-01 UTC (a CSV's epoch seconds can be anything).
const double kEarliestTime = seconds_from_civil(1900, 1, 1);
const double kLatestTime = seconds_from_civil(2200, 1, 1);

}  // namespace

void fail(const std::string& name, std::size_t line, const std::string& problem) {
  throw std::invalid_argument(name + ":" + std::to_string(line) + ": " + problem);
}

void fail(const std::string& name, const std::string& problem) { throw std::invalid_argument(name + ": " + problem); }

std::string quoted(std::string_view text) {
  constexpr std::size_t kMaxQuoted = 40;
  std::string q = "'";
  for (std::size_t k = 0; k < text.size() && k < kMaxQuoted; ++k)
    q += static_cast<unsigned char>(text[k]) < 0x20 || text[k] == 0x7f ? '?' : text[k];
  if (text.size() > kMaxQuoted) q += "...";
  return q + "'";
}

std::string clean_name(std::string_view text) {
  std::string s;
  for (const char c : text) s += static_cast<unsigned char>(c) < 0x20 || c == 0x7f ? ' ' : c;
  const auto first = s.find_first_not_of(' '), last = s.find_last_not_of(' ');
  return first == std::string::npos ? std::string() : s.substr(first, last - first + 1);
}

bool looks_binary(std::string_view head) {
  std::size_t control = 0;
  for (const char ch : head) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == 0) return true;
    if (c < 0x20 && c != '\t' && c != '\n' && c != '\r' && c != '\f') ++control;
  }
  return control * 20 > head.size();
}

LineReader::LineReader(std::istream& in, std::string name) : in_(in), name_(std::move(name)) {
  std::string head(kSniffBytes, '\0');
  in_.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in_.gcount()));
  if (looks_binary(head)) fail(name_, "binary content, not a track file");
  in_.clear();
  in_.seekg(0);
  if (!in_) fail(name_, "cannot rewind the input");
  if (in_.peek() == 0xEF) {
    char bom[3];
    in_.read(bom, 3);
    if (std::string_view(bom, 3) != "\xEF\xBB\xBF") {
      in_.clear();
      in_.seekg(0);
    }
  }
}

bool LineReader::next(std::string& line) {
  line.clear();
  if (!in_) return false;
  int c;
  bool any = false;
  while ((c = in_.get()) != std::char_traits<char>::eof()) {
    any = true;
    if (c == '\n') break;
    if (line.size() >= kMaxLineBytes) fail(name_, line_ + 1, "line longer than " + std::to_string(kMaxLineBytes) + " bytes, not a track file");
    if (c == 0) fail(name_, line_ + 1, "binary content (NUL byte), not a track file");
    line.push_back(static_cast<char>(c));
  }
  if (!any) return false;
  if (!line.empty() && line.back() == '\r') line.pop_back();
  ++line_;
  return true;
}

std::string read_bounded(std::istream& in, const std::string& name) {
  std::string text;
  std::vector<char> chunk(1 << 16);
  while (in) {
    in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    const auto n = static_cast<std::size_t>(in.gcount());
    if (text.size() + n > kMaxXmlBytes)
      fail(name, "larger than " + std::to_string(kMaxXmlBytes >> 20) + " MiB, too large to parse as XML");
    text.append(chunk.data(), n);
  }
  if (looks_binary(std::string_view(text).substr(0, kSniffBytes))) fail(name, "binary content, not a track file");
  return text;
}

void check_coordinates(const std::string& name, std::size_t line, double lat, double lon) {
  const bool ok = std::isfinite(lat) && std::isfinite(lon) && std::abs(lat) <= 90.0 && std::abs(lon) <= 180.0;
  if (ok) return;
  const std::string problem = "coordinates lat " + number(lat) + ", lon " + number(lon) +
                              " out of range (lat -90..90, lon -180..180)";
  if (line) fail(name, line, problem);
  fail(name, problem);
}

void append_fix(Track& track, Fix fix, const std::string& name, std::size_t line) {
  if (!(fix.time_s >= kEarliestTime && fix.time_s <= kLatestTime))
    fail(name, line, "time " + number(fix.time_s) + " s out of range (years 1900 to 2199)");
  if (!track.fixes.empty() && fix.time_s <= track.fixes.back().time_s)
    fail(name, line,
         "time " + format_iso8601(fix.time_s) + (fix.time_s == track.fixes.back().time_s ? " repeats" : " runs backwards") +
             " (previous fix at " + format_iso8601(track.fixes.back().time_s) + ")");
  if (track.fixes.size() >= kMaxFixes) fail(name, line, "more than " + std::to_string(kMaxFixes) + " fixes in one track");
  track.fixes.push_back(std::move(fix));
}

void require_fixes(const std::vector<Track>& tracks, const std::string& name, const std::string& what) {
  for (const Track& t : tracks)
    if (!t.fixes.empty()) return;
  fail(name, "no track points (" + what + ")");
}

}  // namespace skylit::flight::detail
