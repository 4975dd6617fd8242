#include "gpu/shader_source.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "gpu/embedded_shaders.h"

namespace skylit::gpu {
namespace {

bool is_identifier(std::string_view s) {
  if (s.empty() || std::isdigit(static_cast<unsigned char>(s[0]))) return false;
  return std::all_of(s.begin(), s.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  });
}

std::string_view trim_left(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  return s;
}

// The file name of an `#include "name"` line, or empty if the line is no include.
std::string_view include_target(std::string_view line) {
  line = trim_left(line);
  if (!line.starts_with("#")) return {};
  line = trim_left(line.substr(1));
  if (!line.starts_with("include")) return {};
  line = trim_left(line.substr(7));
  if (line.size() < 2 || line.front() != '"') return {};
  const auto close = line.find('"', 1);
  return close == std::string_view::npos ? std::string_view{} : line.substr(1, close - 1);
}

class Assembler {
 public:
  explicit Assembler(AssembledShader& out) : mOut(out) {}

  // Appends `text` (source `id`), numbering its lines from `first_line`; expands includes.
  void append(std::string_view text, int id, int first_line) {
    int line_no = first_line;
    std::size_t pos = 0;
    while (pos < text.size()) {
      std::size_t end = text.find('\n', pos);
      if (end == std::string_view::npos) end = text.size();
      const std::string_view line = text.substr(pos, end - pos);
      pos = end + 1;
      const std::string_view target = include_target(line);
      if (target.empty())
        add_line(line, id, line_no);
      else
        include(std::string(target), mOut.source_names[id]);
      ++line_no;
    }
  }

  void add_line(std::string_view line, int id, int line_no) {
    mOut.text.append(line).append("\n");
    mOut.line_origins.push_back({id, line_no});
  }

 private:
  // `from` is a copy: it may name an element of source_names, which grows below.
  void include(const std::string& name, std::string from) {
    if (std::find(mOut.source_names.begin(), mOut.source_names.end(), name) !=
        mOut.source_names.end())
      return;  // already included: include-once semantics, no guards needed in files
    std::string_view text;
    try {
      text = embedded_shader(name);
    } catch (const std::out_of_range&) {
      throw std::runtime_error(from + ": #include \"" + name + "\": no such embedded shader");
    }
    const int id = static_cast<int>(mOut.source_names.size());
    mOut.source_names.push_back(name);
    append(text, id, 1);
  }

  AssembledShader& mOut;
};

}  // namespace

std::string glsl_float_literal(double value) {
  if (!std::isfinite(static_cast<float>(value))) throw std::invalid_argument("GLSL literal must be a finite float");
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.9g", static_cast<double>(static_cast<float>(value)));
  std::string s(buf);
  if (s.find_first_of(".eE") == std::string::npos) s += ".0";
  return s;
}

std::string glsl_float_array_literal(std::span<const double> values) {
  std::string s = "float[" + std::to_string(values.size()) + "](";
  for (std::size_t k = 0; k < values.size(); ++k) s += (k ? ", " : "") + glsl_float_literal(values[k]);
  return s + ")";
}

GlslDefines& GlslDefines::set(std::string_view name, int value) {
  return set_literal(name, std::to_string(value));
}

GlslDefines& GlslDefines::set(std::string_view name, double value) {
  return set_literal(name, glsl_float_literal(value));
}

GlslDefines& GlslDefines::set_literal(std::string_view name, std::string_view glsl_expression) {
  if (!is_identifier(name))
    throw std::invalid_argument("GlslDefines: '" + std::string(name) + "' is no identifier");
  for (const auto& [n, v] : mEntries)
    if (n == name) throw std::invalid_argument("GlslDefines: '" + n + "' set twice");
  mEntries.emplace_back(name, glsl_expression);
  return *this;
}

std::string GlslDefines::text() const {
  std::string s;
  for (const auto& [n, v] : mEntries) {
    // Parenthesise anything but a plain token, so `-X` or `A + B` stay one operand.
    const bool plain = std::all_of(v.begin(), v.end(), [](char c) {
      return std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_';
    });
    s += "#define " + n + " " + (plain ? v : "(" + v + ")") + "\n";
  }
  return s;
}

std::string AssembledShader::map_log(std::string_view log) const {
  std::string out;
  std::size_t i = 0;
  while (i < log.size()) {
    // A location is "0:" or "0(" then digits, at the start of a line or after a space.
    const bool at_start = i == 0 || log[i - 1] == '\n' || log[i - 1] == ' ';
    std::size_t j = i + 2;
    while (j < log.size() && std::isdigit(static_cast<unsigned char>(log[j]))) ++j;
    if (at_start && log[i] == '0' && i + 1 < log.size() && (log[i + 1] == ':' || log[i + 1] == '(') &&
        j > i + 2) {
      const int line = std::stoi(std::string(log.substr(i + 2, j - i - 2)));
      if (line >= 1 && line <= static_cast<int>(line_origins.size())) {
        const Origin o = line_origins[line - 1];
        out += source_names[o.source] + ":" + std::to_string(o.line);
        if (log[i + 1] == '(' && j < log.size() && log[j] == ')') ++j;  // NVIDIA's "0(12)"
        i = j;
        continue;
      }
    }
    out += log[i++];
  }
  return out;
}

AssembledShader assemble_shader_text(std::string_view name, std::string_view text,
                                     const GlslDefines& defines) {
  if (!text.starts_with("#version"))
    throw std::runtime_error(std::string(name) + ": must start with a #version line");
  const std::size_t eol = std::min(text.find('\n'), text.size());

  AssembledShader out;
  out.source_names = {"<generated defines>", std::string(name)};
  Assembler assembler(out);
  assembler.add_line(text.substr(0, eol), 1, 1);
  assembler.append(defines.text(), 0, 1);
  assembler.append(eol < text.size() ? text.substr(eol + 1) : std::string_view{}, 1, 2);
  return out;
}

AssembledShader assemble_shader(std::string_view name, const GlslDefines& defines) {
  return assemble_shader_text(name, embedded_shader(name), defines);
}

}  // namespace skylit::gpu
