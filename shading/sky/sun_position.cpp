#include "shading/sky/sun_position.h"

#include <cmath>
#include <initializer_list>
#include <iterator>
#include <numbers>
#include <span>

namespace skylit::sky {
namespace {

using std::numbers::pi;
constexpr double kDeg = pi / 180.0;
constexpr double kTwoPi = 2.0 * pi;

// ---------------------------------------------------------------------------
// SPA Table A4.2: Earth periodic terms (VSOP87 truncated). Each term adds
// A·cos(B + C·JME); the series are in 1e-8 rad (L, B) and 1e-8 AU (R).
struct Term {
  double a, b, c;
};

constexpr Term kL0[] = {
    {175347046.0, 0.0, 0.0},       {3341656.0, 4.6692568, 6283.07585},
    {34894.0, 4.6261, 12566.1517}, {3497.0, 2.7441, 5753.3849},
    {3418.0, 2.8289, 3.5231},      {3136.0, 3.6277, 77713.7715},
    {2676.0, 4.4181, 7860.4194},   {2343.0, 6.1352, 3930.2097},
    {1324.0, 0.7425, 11506.7698},  {1273.0, 2.0371, 529.691},
    {1199.0, 1.1096, 1577.3435},   {990.0, 5.233, 5884.927},
    {902.0, 2.045, 26.298},        {857.0, 3.508, 398.149},
    {780.0, 1.179, 5223.694},      {753.0, 2.533, 5507.553},
    {505.0, 4.583, 18849.228},     {492.0, 4.205, 775.523},
    {357.0, 2.92, 0.067},          {317.0, 5.849, 11790.629},
    {284.0, 1.899, 796.298},       {271.0, 0.315, 10977.079},
    {243.0, 0.345, 5486.778},      {206.0, 4.806, 2544.314},
    {205.0, 1.869, 5573.143},      {202.0, 2.458, 6069.777},
    {156.0, 0.833, 213.299},       {132.0, 3.411, 2942.463},
    {126.0, 1.083, 20.775},        {115.0, 0.645, 0.98},
    {103.0, 0.636, 4694.003},      {102.0, 0.976, 15720.839},
    {102.0, 4.267, 7.114},         {99.0, 6.21, 2146.17},
    {98.0, 0.68, 155.42},          {86.0, 5.98, 161000.69},
    {85.0, 1.3, 6275.96},          {85.0, 3.67, 71430.7},
    {80.0, 1.81, 17260.15},        {79.0, 3.04, 12036.46},
    {75.0, 1.76, 5088.63},         {74.0, 3.5, 3154.69},
    {74.0, 4.68, 801.82},          {70.0, 0.83, 9437.76},
    {62.0, 3.98, 8827.39},         {61.0, 1.82, 7084.9},
    {57.0, 2.78, 6286.6},          {56.0, 4.39, 14143.5},
    {56.0, 3.47, 6279.55},         {52.0, 0.19, 12139.55},
    {52.0, 1.33, 1748.02},         {51.0, 0.28, 5856.48},
    {49.0, 0.49, 1194.45},         {41.0, 5.37, 8429.24},
    {41.0, 2.4, 19651.05},         {39.0, 6.17, 10447.39},
    {37.0, 6.04, 10213.29},        {37.0, 2.57, 1059.38},
    {36.0, 1.71, 2352.87},         {36.0, 1.78, 6812.77},
    {33.0, 0.59, 17789.85},        {30.0, 0.44, 83996.85},
    {30.0, 2.74, 1349.87},         {25.0, 3.16, 4690.48},
};
constexpr Term kL1[] = {
    {628331966747.0, 0.0, 0.0},   {206059.0, 2.678235, 6283.07585},
    {4303.0, 2.6351, 12566.1517}, {425.0, 1.59, 3.523},
    {119.0, 5.796, 26.298},       {109.0, 2.966, 1577.344},
    {93.0, 2.59, 18849.23},       {72.0, 1.14, 529.69},
    {68.0, 1.87, 398.15},         {67.0, 4.41, 5507.55},
    {59.0, 2.89, 5223.69},        {56.0, 2.17, 155.42},
    {45.0, 0.4, 796.3},           {36.0, 0.47, 775.52},
    {29.0, 2.65, 7.11},           {21.0, 5.34, 0.98},
    {19.0, 1.85, 5486.78},        {19.0, 4.97, 213.3},
    {17.0, 2.99, 6275.96},        {16.0, 0.03, 2544.31},
    {16.0, 1.43, 2146.17},        {15.0, 1.21, 10977.08},
    {12.0, 2.83, 1748.02},        {12.0, 3.26, 5088.63},
    {12.0, 5.27, 1194.45},        {12.0, 2.08, 4694.0},
    {11.0, 0.77, 553.57},         {10.0, 1.3, 6286.6},
    {10.0, 4.24, 1349.87},        {9.0, 2.7, 242.73},
    {9.0, 5.64, 951.72},          {8.0, 5.3, 2352.87},
    {6.0, 2.65, 9437.76},         {6.0, 4.67, 4690.48},
};
constexpr Term kL2[] = {
    {52919.0, 0.0, 0.0}, {8720.0, 1.0721, 6283.0758}, {309.0, 0.867, 12566.152}, {27.0, 0.05, 3.52},
    {16.0, 5.19, 26.3},  {16.0, 3.68, 155.42},        {10.0, 0.76, 18849.23},    {9.0, 2.06, 77713.77},
    {7.0, 0.83, 775.52}, {5.0, 4.66, 1577.34},        {4.0, 1.03, 7.11},         {4.0, 3.44, 5573.14},
    {3.0, 5.14, 796.3},  {3.0, 6.05, 5507.55},        {3.0, 1.19, 242.73},       {3.0, 6.12, 529.69},
    {3.0, 0.31, 398.15}, {3.0, 2.28, 553.57},         {2.0, 4.38, 5223.69},      {2.0, 3.75, 0.98},
};
constexpr Term kL3[] = {
    {289.0, 5.844, 6283.076}, {35.0, 0.0, 0.0},     {17.0, 5.49, 12566.15}, {3.0, 5.2, 155.42},
    {1.0, 4.72, 3.52},        {1.0, 5.3, 18849.23}, {1.0, 5.97, 242.73},
};
constexpr Term kL4[] = {{114.0, 3.142, 0.0}, {8.0, 4.13, 6283.08}, {1.0, 3.84, 12566.15}};
constexpr Term kL5[] = {{1.0, 3.14, 0.0}};

constexpr Term kB0[] = {
    {280.0, 3.199, 84334.662}, {102.0, 5.422, 5507.553}, {80.0, 3.88, 5223.69},
    {44.0, 3.7, 2352.87},      {32.0, 4.0, 1577.34},
};
constexpr Term kB1[] = {{9.0, 3.9, 5507.55}, {6.0, 1.73, 5223.69}};

constexpr Term kR0[] = {
    {100013989.0, 0.0, 0.0},        {1670700.0, 3.0984635, 6283.07585},
    {13956.0, 3.05525, 12566.1517}, {3084.0, 5.1985, 77713.7715},
    {1628.0, 1.1739, 5753.3849},    {1576.0, 2.8469, 7860.4194},
    {925.0, 5.453, 11506.77},       {542.0, 4.564, 3930.21},
    {472.0, 3.661, 5884.927},       {346.0, 0.964, 5507.553},
    {329.0, 5.9, 5223.694},         {307.0, 0.299, 5573.143},
    {243.0, 4.273, 11790.629},      {212.0, 5.847, 1577.344},
    {186.0, 5.022, 10977.079},      {175.0, 3.012, 18849.228},
    {110.0, 5.055, 5486.778},       {98.0, 0.89, 6069.78},
    {86.0, 5.69, 15720.84},         {86.0, 1.27, 161000.69},
    {65.0, 0.27, 17260.15},         {63.0, 0.92, 529.69},
    {57.0, 2.01, 83996.85},         {56.0, 5.24, 71430.7},
    {49.0, 3.25, 2544.31},          {47.0, 2.58, 775.52},
    {45.0, 5.54, 9437.76},          {43.0, 6.01, 6275.96},
    {39.0, 5.36, 4694.0},           {38.0, 2.39, 8827.39},
    {37.0, 0.83, 19651.05},         {37.0, 4.9, 12139.55},
    {36.0, 1.67, 12036.46},         {35.0, 1.84, 2942.46},
    {33.0, 0.24, 7084.9},           {32.0, 0.18, 5088.63},
    {32.0, 1.78, 398.15},           {28.0, 1.21, 6286.6},
    {28.0, 1.9, 6279.55},           {26.0, 4.59, 10447.39},
};
constexpr Term kR1[] = {
    {103019.0, 1.10749, 6283.07585},
    {1721.0, 1.0644, 12566.1517},
    {702.0, 3.142, 0.0},
    {32.0, 1.02, 18849.23},
    {31.0, 2.84, 5507.55},
    {25.0, 1.32, 5223.69},
    {18.0, 1.42, 1577.34},
    {10.0, 5.91, 10977.08},
    {9.0, 1.42, 6275.96},
    {9.0, 0.27, 5486.78},
};
constexpr Term kR2[] = {
    {4359.0, 5.7846, 6283.0758}, {124.0, 5.579, 12566.152}, {12.0, 3.14, 0.0},
    {9.0, 3.63, 77713.77},       {6.0, 1.87, 5573.14},      {3.0, 5.47, 18849.23},
};
constexpr Term kR3[] = {{145.0, 4.273, 6283.076}, {7.0, 3.92, 12566.15}};
constexpr Term kR4[] = {{4.0, 2.56, 6283.08}};

// Term counts as printed in the paper.
static_assert(std::size(kL0) == 64 && std::size(kL1) == 34 && std::size(kL2) == 20 && std::size(kL3) == 7 &&
              std::size(kL4) == 3 && std::size(kL5) == 1);
static_assert(std::size(kB0) == 5 && std::size(kB1) == 2);
static_assert(std::size(kR0) == 40 && std::size(kR1) == 10 && std::size(kR2) == 6 && std::size(kR3) == 2 &&
              std::size(kR4) == 1);

// ---------------------------------------------------------------------------
// SPA Table A4.3: nutation in longitude and obliquity. Argument multipliers
// of X0..X4, then Δψ = Σ (a + b·JCE)·sin(arg), Δε = Σ (c + d·JCE)·cos(arg),
// in units of 0.0001″.
struct NutationTerm {
  int y[5];
  double a, b, c, d;
};

constexpr NutationTerm kNutation[] = {
    {{0, 0, 0, 0, 1}, -171996, -174.2, 92025, 8.9},
    {{-2, 0, 0, 2, 2}, -13187, -1.6, 5736, -3.1},
    {{0, 0, 0, 2, 2}, -2274, -0.2, 977, -0.5},
    {{0, 0, 0, 0, 2}, 2062, 0.2, -895, 0.5},
    {{0, 1, 0, 0, 0}, 1426, -3.4, 54, -0.1},
    {{0, 0, 1, 0, 0}, 712, 0.1, -7, 0},
    {{-2, 1, 0, 2, 2}, -517, 1.2, 224, -0.6},
    {{0, 0, 0, 2, 1}, -386, -0.4, 200, 0},
    {{0, 0, 1, 2, 2}, -301, 0, 129, -0.1},
    {{-2, -1, 0, 2, 2}, 217, -0.5, -95, 0.3},
    {{-2, 0, 1, 0, 0}, -158, 0, 0, 0},
    {{-2, 0, 0, 2, 1}, 129, 0.1, -70, 0},
    {{0, 0, -1, 2, 2}, 123, 0, -53, 0},
    {{2, 0, 0, 0, 0}, 63, 0, 0, 0},
    {{0, 0, 1, 0, 1}, 63, 0.1, -33, 0},
    {{2, 0, -1, 2, 2}, -59, 0, 26, 0},
    {{0, 0, -1, 0, 1}, -58, -0.1, 32, 0},
    {{0, 0, 1, 2, 1}, -51, 0, 27, 0},
    {{-2, 0, 2, 0, 0}, 48, 0, 0, 0},
    {{0, 0, -2, 2, 1}, 46, 0, -24, 0},
    {{2, 0, 0, 2, 2}, -38, 0, 16, 0},
    {{0, 0, 2, 2, 2}, -31, 0, 13, 0},
    {{0, 0, 2, 0, 0}, 29, 0, 0, 0},
    {{-2, 0, 1, 2, 2}, 29, 0, -12, 0},
    {{0, 0, 0, 2, 0}, 26, 0, 0, 0},
    {{-2, 0, 0, 2, 0}, -22, 0, 0, 0},
    {{0, 0, -1, 2, 1}, 21, 0, -10, 0},
    {{0, 2, 0, 0, 0}, 17, -0.1, 0, 0},
    {{2, 0, -1, 0, 1}, 16, 0, -8, 0},
    {{-2, 2, 0, 2, 2}, -16, 0.1, 7, 0},
    {{0, 1, 0, 0, 1}, -15, 0, 9, 0},
    {{-2, 0, 1, 0, 1}, -13, 0, 7, 0},
    {{0, -1, 0, 0, 1}, -12, 0, 6, 0},
    {{0, 0, 2, -2, 0}, 11, 0, 0, 0},
    {{2, 0, -1, 2, 1}, -10, 0, 5, 0},
    {{2, 0, 1, 2, 2}, -8, 0, 3, 0},
    {{0, 1, 0, 2, 2}, 7, 0, -3, 0},
    {{-2, 1, 1, 0, 0}, -7, 0, 0, 0},
    {{0, -1, 0, 2, 2}, -7, 0, 3, 0},
    {{2, 0, 0, 2, 1}, -7, 0, 3, 0},
    {{2, 0, 1, 0, 0}, 6, 0, 0, 0},
    {{-2, 0, 2, 2, 2}, 6, 0, -3, 0},
    {{-2, 0, 1, 2, 1}, 6, 0, -3, 0},
    {{2, 0, -2, 0, 1}, -6, 0, 3, 0},
    {{2, 0, 0, 0, 1}, -6, 0, 3, 0},
    {{0, -1, 1, 0, 0}, 5, 0, 0, 0},
    {{-2, -1, 0, 2, 1}, -5, 0, 3, 0},
    {{-2, 0, 0, 0, 1}, -5, 0, 3, 0},
    {{0, 0, 2, 2, 1}, -5, 0, 3, 0},
    {{-2, 0, 2, 0, 1}, 4, 0, 0, 0},
    {{-2, 1, 0, 2, 1}, 4, 0, 0, 0},
    {{0, 0, 1, -2, 0}, 4, 0, 0, 0},
    {{-1, 0, 1, 0, 0}, -4, 0, 0, 0},
    {{-2, 1, 0, 0, 0}, -4, 0, 0, 0},
    {{1, 0, 0, 0, 0}, -4, 0, 0, 0},
    {{0, 0, 1, 2, 0}, 3, 0, 0, 0},
    {{0, 0, -2, 2, 2}, -3, 0, 0, 0},
    {{-1, -1, 1, 0, 0}, -3, 0, 0, 0},
    {{0, 1, 1, 0, 0}, -3, 0, 0, 0},
    {{0, -1, 1, 2, 2}, -3, 0, 0, 0},
    {{2, -1, -1, 2, 2}, -3, 0, 0, 0},
    {{0, 0, 3, 2, 2}, -3, 0, 0, 0},
    {{2, -1, 0, 2, 2}, -3, 0, 0, 0},
};

static_assert(std::size(kNutation) == 63);

// ---------------------------------------------------------------------------

double sum_terms(std::span<const Term> terms, double jme) {
  double s = 0.0;
  for (const Term& t : terms) s += t.a * std::cos(t.b + t.c * jme);
  return s;
}

// Σ_k S_k·JME^k / 1e8 (SPA eq. 10–11).
double vsop_series(std::initializer_list<std::span<const Term>> series, double jme) {
  double s = 0.0, power = 1.0;
  for (const auto& terms : series) {
    s += sum_terms(terms, jme) * power;
    power *= jme;
  }
  return s / 1e8;
}

double polynomial(double x, std::initializer_list<double> coeffs) {
  double s = 0.0, power = 1.0;
  for (double c : coeffs) {
    s += c * power;
    power *= x;
  }
  return s;
}

// Wraps an angle to [0, 2π) and to (−π, π].
double wrap_two_pi(double a) {
  a = std::fmod(a, kTwoPi);
  return a < 0.0 ? a + kTwoPi : a;
}
double wrap_pi(double a) {
  a = wrap_two_pi(a);
  return a > pi ? a - kTwoPi : a;
}

// Julian Day of J2000.0 and the sidereal rate (SPA eq. 28 and A.2 step 4).
constexpr double kJ2000 = 2451545.0;
constexpr double kSiderealPerSolarDay = 360.985647 / 360.0;
// Sun's centre at rise/set: 34′ refraction + 16′ semi-diameter below the horizon.
constexpr double kRiseSetElevation = -0.8333 * kDeg;
// SPA applies refraction only while the sun is above −(semi-diameter + 0.5667°).
constexpr double kRefractionFloor = -(0.26667 + 0.5667) * kDeg;

// Geocentric sun in radians; the public struct converts.
struct Geo {
  double L, B, R, dpsi, deps, eps, lambda, nu, alpha, delta, eot;
};

Geo compute_geo(double jd, double delta_t_s) {
  const double jc = (jd - kJ2000) / 36525.0;
  const double jde = jd + delta_t_s / 86400.0;
  const double jce = (jde - kJ2000) / 36525.0;
  const double jme = jce / 10.0;

  Geo g{};
  g.L = wrap_two_pi(vsop_series({kL0, kL1, kL2, kL3, kL4, kL5}, jme));
  g.B = vsop_series({kB0, kB1}, jme);
  g.R = vsop_series({kR0, kR1, kR2, kR3, kR4}, jme);

  // Geocentric ecliptic longitude and latitude (sun seen from the Earth).
  const double theta = wrap_two_pi(g.L + pi);
  const double beta = -g.B;

  // Fundamental arguments of nutation (degrees, Meeus ch. 22 / SPA eq. 15–19).
  const double x[5] = {
      polynomial(jce, {297.85036, 445267.111480, -0.0019142, 1.0 / 189474.0}),
      polynomial(jce, {357.52772, 35999.050340, -0.0001603, -1.0 / 300000.0}),
      polynomial(jce, {134.96298, 477198.867398, 0.0086972, 1.0 / 56250.0}),
      polynomial(jce, {93.27191, 483202.017538, -0.0036825, 1.0 / 327270.0}),
      polynomial(jce, {125.04452, -1934.136261, 0.0020708, 1.0 / 450000.0}),
  };
  double dpsi = 0.0, deps = 0.0;
  for (const NutationTerm& n : kNutation) {
    double arg = 0.0;
    for (int j = 0; j < 5; ++j) arg += x[j] * n.y[j];
    arg *= kDeg;
    dpsi += (n.a + n.b * jce) * std::sin(arg);
    deps += (n.c + n.d * jce) * std::cos(arg);
  }
  constexpr double kTenThousandthArcsec = kDeg / 36000000.0;
  g.dpsi = dpsi * kTenThousandthArcsec;
  g.deps = deps * kTenThousandthArcsec;

  // True obliquity: Laskar's mean obliquity (arcsec, U = JME/10) plus nutation.
  const double eps0 = polynomial(
      jme / 10.0, {84381.448, -4680.93, -1.55, 1999.25, -51.38, -249.67, -39.05, 7.12, 27.87, 5.79, 2.45});
  g.eps = eps0 / 3600.0 * kDeg + g.deps;

  // Aberration, apparent longitude, apparent sidereal time (eq. 23–29).
  const double aberration = -20.4898 / (3600.0 * g.R) * kDeg;
  g.lambda = wrap_two_pi(theta + g.dpsi + aberration);
  const double nu0 =
      polynomial(jc, {280.46061837, 0.0, 0.000387933, -1.0 / 38710000.0}) + 360.98564736629 * (jd - kJ2000);
  g.nu = wrap_two_pi(nu0 * kDeg + g.dpsi * std::cos(g.eps));

  g.alpha = wrap_two_pi(std::atan2(std::sin(g.lambda) * std::cos(g.eps) - std::tan(beta) * std::sin(g.eps),
                                   std::cos(g.lambda)));
  g.delta =
      std::asin(std::sin(beta) * std::cos(g.eps) + std::cos(beta) * std::sin(g.eps) * std::sin(g.lambda));

  // Equation of time (SPA appendix A.1): sun's mean longitude M.
  const double m = polynomial(
      jme, {280.4664567, 360007.6982779, 0.03032028, 1.0 / 49931.0, -1.0 / 15300.0, -1.0 / 2000000.0});
  g.eot = wrap_pi(m * kDeg - 0.0057183 * kDeg - g.alpha + g.dpsi * std::cos(g.eps));
  return g;
}

GeocentricSun to_degrees(const Geo& g) {
  return {g.L / kDeg,        g.B / kDeg,      g.R,         g.dpsi / kDeg,  g.deps / kDeg,
          g.eps / kDeg,      g.lambda / kDeg, g.nu / kDeg, g.alpha / kDeg, g.delta / kDeg,
          g.eot / kDeg * 4.0};
}

double resolve_delta_t(UtcTime t, std::optional<double> delta_t_s) {
  return delta_t_s ? *delta_t_s : delta_t_seconds(decimal_year(t));
}

}  // namespace

double delta_t_seconds(double y) {
  const auto long_term = [](double year) {
    const double u = (year - 1820.0) / 100.0;
    return -20.0 + 32.0 * u * u;
  };
  if (y < 1860.0) return long_term(y);
  if (y < 1900.0)
    return polynomial(y - 1860.0, {7.62, 0.5737, -0.251754, 0.01680668, -0.0004473624, 1.0 / 233174.0});
  if (y < 1920.0) return polynomial(y - 1900.0, {-2.79, 1.494119, -0.0598939, 0.0061966, -0.000197});
  if (y < 1941.0) return polynomial(y - 1920.0, {21.20, 0.84493, -0.076100, 0.0020936});
  if (y < 1961.0) return polynomial(y - 1950.0, {29.07, 0.407, -1.0 / 233.0, 1.0 / 2547.0});
  if (y < 1986.0) return polynomial(y - 1975.0, {45.45, 1.067, -1.0 / 260.0, -1.0 / 718.0});
  if (y < 2005.0)
    return polynomial(y - 2000.0, {63.86, 0.3345, -0.060374, 0.0017275, 0.000651814, 0.00002373599});
  if (y < 2050.0) return polynomial(y - 2000.0, {62.92, 0.32217, 0.005589});
  // The linear term joins the 2005–2050 fit at 2050 and the parabola at 2150.
  if (y < 2150.0) return long_term(y) - 0.5628 * (2150.0 - y);
  return long_term(y);
}

GeocentricSun geocentric_sun(double julian_day_ut, double delta_t_s) {
  return to_degrees(compute_geo(julian_day_ut, delta_t_s));
}

SolarPosition solar_position(UtcTime t, const Observer& observer, const Atmosphere& atmosphere,
                             std::optional<double> delta_t_s) {
  const double jd = julian_day(t);
  const Geo g = compute_geo(jd, resolve_delta_t(t, delta_t_s));
  const double phi = observer.latitude_deg * kDeg;
  const double sigma = observer.longitude_deg * kDeg;

  // Observer local hour angle (eq. 32).
  const double h = wrap_two_pi(g.nu + sigma - g.alpha);

  // Parallax in right ascension and declination (eq. 33–38); the ellipsoid
  // ratio 0.99664719 and radius 6378140 m are SPA's.
  const double xi = 8.794 / (3600.0 * g.R) * kDeg;
  const double u = std::atan2(0.99664719 * std::sin(phi), std::cos(phi));
  const double height_ratio = observer.height_m / 6378140.0;
  const double x = std::cos(u) + height_ratio * std::cos(phi);
  const double y = 0.99664719 * std::sin(u) + height_ratio * std::sin(phi);
  const double d_alpha =
      std::atan2(-x * std::sin(xi) * std::sin(h), std::cos(g.delta) - x * std::sin(xi) * std::cos(h));
  const double delta_p = std::atan2((std::sin(g.delta) - y * std::sin(xi)) * std::cos(d_alpha),
                                    std::cos(g.delta) - x * std::sin(xi) * std::cos(h));
  const double h_p = h - d_alpha;

  // Topocentric elevation, refraction (eq. 41–43), azimuth (eq. 44–46).
  const double e0 =
      std::asin(std::sin(phi) * std::sin(delta_p) + std::cos(phi) * std::cos(delta_p) * std::cos(h_p));
  double refraction = 0.0;
  if (e0 >= kRefractionFloor) {
    const double e0_deg = e0 / kDeg;
    refraction = (atmosphere.pressure_mbar / 1010.0) * (283.0 / (273.0 + atmosphere.temperature_c)) * 1.02 /
                 (60.0 * std::tan((e0_deg + 10.3 / (e0_deg + 5.11)) * kDeg)) * kDeg;
  }
  const double e = e0 + refraction;
  // Γ is the astronomers' azimuth (from south, westward); Φ = Γ + 180°.
  const double gamma =
      std::atan2(std::sin(h_p), std::cos(h_p) * std::sin(phi) - std::tan(delta_p) * std::cos(phi));

  SolarPosition p{};
  p.azimuth_deg = wrap_two_pi(gamma + pi) / kDeg;
  p.elevation_deg = e0 / kDeg;
  p.apparent_elevation_deg = e / kDeg;
  p.zenith_deg = 90.0 - p.apparent_elevation_deg;
  p.hour_angle_deg = wrap_pi(h_p) / kDeg;
  p.declination_deg = delta_p / kDeg;
  p.geocentric = to_degrees(g);
  return p;
}

SunEvents sun_events(UtcTime t, const Observer& observer, std::optional<double> delta_t_s) {
  const double dt_days = resolve_delta_t(t, delta_t_s) / 86400.0;
  const double phi = observer.latitude_deg * kDeg;
  const double sigma = observer.longitude_deg * kDeg;

  // Day D: the UT date whose number equals the local-mean-time date of t.
  // Fractions m below count days from D's 0h UT and may leave [0, 1), so
  // events near UT midnight stay on the observer's own day.
  const double day = std::floor(t.unix_seconds / 86400.0 + observer.longitude_deg / 360.0);
  const double jd0 = julian_day(UtcTime{day * 86400.0});

  // SPA A.2: ν at 0h UT; α, δ at 0h TT of D−1, D, D+1 (ΔT = 0), interpolated
  // quadratically. Differences in α are wrapped so a 360°→0° step is harmless.
  const Geo prev = compute_geo(jd0 - 1.0, 0.0);
  const Geo cur = compute_geo(jd0, 0.0);
  const Geo next = compute_geo(jd0 + 1.0, 0.0);
  const double a_alpha = wrap_pi(cur.alpha - prev.alpha), b_alpha = wrap_pi(next.alpha - cur.alpha);
  const double a_delta = cur.delta - prev.delta, b_delta = next.delta - cur.delta;
  const auto interpolate = [](double y0, double a, double b, double n) {
    return y0 + n * (a + b + (b - a) * n) / 2.0;
  };
  struct Local {
    double hour_angle, elevation, declination;
  };
  const auto local_at = [&](double m) {
    const double n = m + dt_days;
    const double alpha = interpolate(cur.alpha, a_alpha, b_alpha, n);
    const double delta = interpolate(cur.delta, a_delta, b_delta, n);
    const double hour_angle = wrap_pi(cur.nu + kTwoPi * kSiderealPerSolarDay * m + sigma - alpha);
    const double elevation =
        std::asin(std::sin(phi) * std::sin(delta) + std::cos(phi) * std::cos(delta) * std::cos(hour_angle));
    return Local{hour_angle, elevation, delta};
  };
  const auto to_utc = [day](double m) { return UtcTime{(day + m) * 86400.0}; };

  // Transit: the meridian crossing nearest local mean noon, refined until the
  // hour angle vanishes (the paper's single correction, repeated).
  const double noon_guess = 0.5 - sigma / kTwoPi;
  double m0 = noon_guess + wrap_pi(cur.alpha - sigma - cur.nu - kTwoPi * noon_guess) / kTwoPi;
  for (int i = 0; i < 10; ++i) {
    const double step = -local_at(m0).hour_angle / kTwoPi;
    m0 += step;
    if (std::abs(step) < 1e-9) break;
  }
  SunEvents events;
  events.solar_noon = to_utc(m0);

  // Hour angle of rise/set from the transit declination (eq. A.2 step 5).
  const double delta0 = local_at(m0).declination;
  const double cos_h0 =
      (std::sin(kRiseSetElevation) - std::sin(phi) * std::sin(delta0)) / (std::cos(phi) * std::cos(delta0));
  if (!(cos_h0 <= 1.0)) {  // also catches ±∞/NaN at the poles
    const bool up = std::sin(phi) * std::sin(delta0) > std::sin(kRiseSetElevation);
    events.always_up = up;
    events.always_down = !up;
    return events;
  }
  if (cos_h0 < -1.0) {
    events.always_up = true;
    return events;
  }
  const double h0 = std::acos(cos_h0);

  // Newton on elevation − (−0.8333°), started from the transit ± H0 (A.2 step 12).
  const auto refine = [&](double m) -> std::optional<UtcTime> {
    for (int i = 0; i < 20; ++i) {
      const Local l = local_at(m);
      const double slope = kTwoPi * std::cos(l.declination) * std::cos(phi) * std::sin(l.hour_angle);
      if (std::abs(slope) < 1e-12) return std::nullopt;
      const double step = (l.elevation - kRiseSetElevation) / slope;
      m += step;
      if (std::abs(m - m0) > 0.5) return std::nullopt;
      if (std::abs(step) < 1e-9) return to_utc(m);
    }
    return std::nullopt;
  };
  events.sunrise = refine(m0 - h0 / kTwoPi);
  events.sunset = refine(m0 + h0 / kTwoPi);
  return events;
}

}  // namespace skylit::sky
