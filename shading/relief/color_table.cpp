#include "shading/relief/color_table.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string_view>

namespace skylit::relief {
namespace {

std::vector<std::string> fields_of(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  for (const char c : line) {
    if (c == ' ' || c == '\t' || c == ',' || c == ':' || c == '\r' || c == '\n') {
      if (!cur.empty()) out.push_back(std::move(cur)), cur.clear();
    } else {
      cur += c;
    }
  }
  if (!cur.empty()) out.push_back(std::move(cur));
  return out;
}

bool iequals(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

struct NamedColor {
  std::string_view name;
  float r, g, b;  // gdaldem's fractions, scaled by 255 and truncated
};
constexpr NamedColor kNamedColors[] = {
    {"white", 1.f, 1.f, 1.f},     {"black", 0.f, 0.f, 0.f},     {"red", 1.f, 0.f, 0.f},
    {"green", 0.f, 1.f, 0.f},     {"blue", 0.f, 0.f, 1.f},      {"yellow", 1.f, 1.f, 0.f},
    {"magenta", 1.f, 0.f, 1.f},   {"cyan", 0.f, 1.f, 1.f},      {"aqua", 0.f, .75f, .75f},
    {"grey", .75f, .75f, .75f},   {"gray", .75f, .75f, .75f},   {"orange", 1.f, .5f, 0.f},
    {"brown", .75f, .5f, .25f},   {"purple", .5f, 0.f, 1.f},    {"violet", .5f, 0.f, 1.f},
    {"indigo", 0.f, .5f, 1.f},
};

class LineError {
 public:
  LineError(const std::string& name, int line) : prefix_(name + ":" + std::to_string(line) + ": ") {}
  [[noreturn]] void fail(const std::string& why) const { throw std::invalid_argument(prefix_ + why); }

  double number(const std::string& field, const char* what) const {
    const char* s = field.c_str();
    char* end = nullptr;
    const double v = std::strtod(s, &end);
    if (end == s || *end != '\0' || !std::isfinite(v)) fail(std::string("bad ") + what + " '" + field + "'");
    return v;
  }
  // A colour component as gdaldem's atoi reads it (truncated), 0…255.
  int component(const std::string& field) const {
    const double v = number(field, "colour component");
    if (v < 0.0 || v >= 256.0) fail("colour component '" + field + "' is outside 0…255");
    return static_cast<int>(v);
  }

 private:
  std::string prefix_;
};

bool sorts_before(const ColorEntry& x, const ColorEntry& y) {
  return (std::isnan(x.value) && !std::isnan(y.value)) || x.value < y.value;  // NaN first
}

// gdaldem's post-processing (GDALColorReliefProcessColors): an entry one ulp-ish below and
// above the nodata value keeps nodata's colour from bleeding into neighbouring heights, and a
// run of equal values is spread by multiples of |v|·DBL_EPSILON so that a step stays a step.
void process(std::vector<ColorEntry>& e, const std::optional<double>& nodata) {
  std::stable_sort(e.begin(), e.end(), sorts_before);
  const std::size_t n = e.size();
  std::vector<ColorEntry> added;
  std::size_t prev = 0;
  std::size_t repeated = 0;  // index of the second of a run of equal values, 0 for none
  for (std::size_t i = 1; i < n; ++i) {
    if (nodata && e[i].value == *nodata) {
      const double below = e[i].value - std::abs(e[i].value) * DBL_EPSILON;
      if (below > e[prev].value) {
        added.push_back(e[prev]);
        added.back().value = below;
      }
    } else if (nodata && e[prev].value == *nodata) {
      const double above = e[prev].value + std::abs(e[prev].value) * DBL_EPSILON;
      if (above < e[i].value) {
        added.push_back(e[i]);
        added.back().value = above;
      }
    } else if (repeated == 0 && e[i].value == e[prev].value) {
      repeated = i;
    } else if (repeated != 0 && e[i].value != e[prev].value) {
      double total = 0.0;
      double left = 0.0;
      if (repeated >= 2) {
        total = e[i].value - e[repeated - 2].value;
        left = e[prev].value - e[repeated - 2].value;
      } else {
        total = e[i].value - e[prev].value;
      }
      const int count = static_cast<int>(i - repeated + 1);
      const double base = std::abs(e[prev].value);
      if (total > base * count * DBL_EPSILON) {
        double k = 0.5 - count * left / total;
        for (std::size_t j = repeated - 1; j < i; ++j, k += 1.0) e[j].value += (base * k) * DBL_EPSILON;
      }
      repeated = 0;
    }
    prev = i;
  }
  if (!added.empty()) {
    e.insert(e.end(), added.begin(), added.end());
    std::stable_sort(e.begin(), e.end(), sorts_before);
  }
}

}  // namespace

ColorTable parse_color_table(std::istream& in, const std::string& name, const SourceInfo& source) {
  std::vector<ColorEntry> entries;
  std::optional<std::pair<double, double>> range;
  bool cpt = false;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const LineError err(name, number);
    if (!line.empty() && line[0] == '#' && line.find("COLOR_MODEL") != std::string::npos) {
      if (line.find("COLOR_MODEL = RGB") == std::string::npos) err.fail("only COLOR_MODEL = RGB is supported");
      cpt = true;
    }
    const auto f = fields_of(line);
    if (f.empty() || f[0][0] == '#' || f[0][0] == '/') continue;
    if (cpt) {
      if (f.size() == 8) {
        for (int k = 0; k < 2; ++k)
          entries.push_back({err.number(f[4 * k], "elevation"), err.component(f[4 * k + 1]),
                             err.component(f[4 * k + 2]), err.component(f[4 * k + 3]), 255});
      } else if (f.size() == 4 && (iequals(f[0], "N") || iequals(f[0], "B") || iequals(f[0], "F"))) {
        if (iequals(f[0], "N") && source.nodata)
          entries.push_back({*source.nodata, err.component(f[1]), err.component(f[2]), err.component(f[3]), 255});
      } else {
        err.fail("expected 'z0 R G B z1 R G B' or 'B|F|N R G B' in a COLOR_MODEL = RGB (.cpt) table");
      }
      continue;
    }
    if (f.size() < 2) err.fail("expected 'elevation R G B [A]' or 'elevation NAME [A]'");
    if (f.size() > 5) err.fail("too many fields (expected 'elevation R G B [A]')");
    ColorEntry c;
    if (iequals(f[0], "nv")) {
      c.value = source.nodata.value_or(0.0);
    } else if (f[0].size() > 1 && f[0].back() == '%') {
      const double pct = err.number(f[0].substr(0, f[0].size() - 1), "percentage") / 100.0;
      if (pct < 0.0 || pct > 1.0) err.fail("percentage '" + f[0] + "' is outside 0…100%");
      if (!range) {
        if (!source.min_max) err.fail("a percentage needs the heights' range");
        range = source.min_max();
      }
      c.value = range->first + pct * (range->second - range->first);
    } else {
      c.value = err.number(f[0], "elevation");
    }
    if (f.size() >= 4) {
      c.r = err.component(f[1]);
      c.g = err.component(f[2]);
      c.b = err.component(f[3]);
      if (f.size() == 5) c.a = err.component(f[4]);
    } else {
      const auto it = std::find_if(std::begin(kNamedColors), std::end(kNamedColors),
                                   [&](const NamedColor& n) { return iequals(n.name, f[1]); });
      if (it == std::end(kNamedColors)) err.fail("unknown colour '" + f[1] + "'");
      c.r = static_cast<int>(255.0 * it->r);
      c.g = static_cast<int>(255.0 * it->g);
      c.b = static_cast<int>(255.0 * it->b);
      if (f.size() == 3) c.a = err.component(f[2]);
    }
    entries.push_back(c);
  }
  if (entries.empty()) throw std::invalid_argument(name + ": no colour entries");
  process(entries, source.nodata);
  return {std::move(entries)};
}

ColorTable read_color_table(const std::string& path, const SourceInfo& source) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument("cannot read colour table " + path);
  return parse_color_table(in, path, source);
}

}  // namespace skylit::relief
