#include "shading/sky_brdf_table.h"

#include "shading/brdf.h"
#include "shading/sh/quadrature.h"
#include "shading/sh/sh_rotation.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <exception>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <thread>

namespace skylit::shading {
namespace {

constexpr double kHalfPi = sh::kPi / 2;

// Any orthonormal e1, e2 completing the unit axis a to a right-handed frame.
void frame_about(const glm::dvec3& a, glm::dvec3& e1, glm::dvec3& e2) {
  const glm::dvec3 helper = std::abs(a.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
  e1 = glm::normalize(glm::cross(helper, a));
  e2 = glm::cross(a, e1);
}

}  // namespace

glm::dvec3 test_sky_sun() {
  const double elevation = 35.0 * sh::kPi / 180.0, azimuth = 40.0 * sh::kPi / 180.0;
  return sh::direction(kHalfPi - elevation, azimuth);
}

double test_sky_radiance(const glm::dvec3& d) {
  static const glm::dvec3 sun = test_sky_sun();
  return 0.6 + 0.4 * d.z + 0.8 * std::exp(6.0 * (glm::dot(d, sun) - 1.0));
}

glm::dvec3 AxisGrid::axis(int i, int j) const { return sh::direction(theta(i), phi(j)); }

namespace {

// T(a) of C channels at once, sky(ω) giving all C radiances: channel c is summed term
// for term as a one-channel projection of channel c would be (the same weights, the
// same order), while the sky and the basis are evaluated once per node.
template <std::size_t C, class Sky>
std::array<sh::Vec, C> project_channels(int order, double r, const Sky& sky, const glm::dvec3& axis_in,
                                        const LobeQuadrature& q) {
  if (q.azimuths < 1 || q.gauss_nodes < 1) throw std::invalid_argument("sky_lobe_projection: bad quadrature");
  const int nc = sh::num_coeffs(order);
  const glm::dvec3 a = glm::normalize(axis_in);
  glm::dvec3 e1, e2;
  frame_about(a, e1, e2);
  const auto unit = sh::gauss_legendre(q.gauss_nodes, 0.0, 1.0);
  const double dphi = 2.0 * sh::kPi / q.azimuths;
  std::array<sh::Vec, C> out;
  for (sh::Vec& v : out) v.assign(nc, 0.0);
  double y[sh::kMaxOrder * sh::kMaxOrder];
  const std::span<double> ys(y, nc);
  for (int k = 0; k < q.azimuths; ++k) {
    const double phi = (k + 0.5) * dphi;
    const glm::dvec3 u = std::cos(phi) * e1 + std::sin(phi) * e2;
    // Height z(θ') = sin θ'·u_z + cos θ'·a_z = R cos(θ' − δ): zero at θ' = δ + π/2 + kπ.
    // At most one root lies in (0, π/2): the roots are π apart.
    double pts[3] = {0.0, kHalfPi, kHalfPi};
    int np = 2;
    if (std::hypot(u.z, a.z) > 0.0) {
      double c = std::fmod(std::atan2(u.z, a.z) + kHalfPi, sh::kPi);
      if (c < 0.0) c += sh::kPi;
      if (c > 0.0 && c < kHalfPi) {
        pts[1] = c;
        np = 3;
      }
    }
    for (int p = 0; p + 1 < np; ++p) {
      const double lo = pts[p], len = pts[p + 1] - pts[p];
      for (std::size_t n = 0; n < unit.nodes.size(); ++n) {
        const double th = lo + len * unit.nodes[n];
        const double st = std::sin(th), ct = std::cos(th);
        const glm::dvec3 w_dir = st * u + ct * a;
        const double base = unit.weights[n] * len * st * dphi * lobe_profile(r, ct);
        const std::array<double, C> radiance = sky(w_dir);
        bool basis = false;
        for (std::size_t c = 0; c < C; ++c) {
          const double w = base * radiance[c];
          if (w == 0.0) continue;
          if (!basis) sh::eval_basis(order, w_dir, ys);
          basis = true;
          for (int i = 0; i < nc; ++i) out[c][i] += w * y[i];
        }
      }
    }
  }
  return out;
}

}  // namespace

sh::Vec sky_lobe_projection(int order, double r, const Radiance& sky, const glm::dvec3& axis_in,
                            const LobeQuadrature& q) {
  const auto one = [&](const glm::dvec3& d) { return std::array<double, 1>{sky(d)}; };
  return std::move(project_channels<1>(order, r, one, axis_in, q)[0]);
}

SkyBrdfTable::SkyBrdfTable(int order, double r, const AxisGrid& grid) : order_(order), lobe_exponent_(r), grid_(grid) {
  if (order < sh::kMinOrder || order > sh::kMaxOrder) throw std::invalid_argument("SkyBrdfTable: order");
  if (!(r > 0.0)) throw std::invalid_argument("SkyBrdfTable: lobe exponent must be > 0");
  if (grid.n_theta < 2 || grid.n_phi < 1 || !(grid.theta_max > 0.0) || grid.theta_max > sh::kPi + 1e-12)
    throw std::invalid_argument("SkyBrdfTable: bad axis grid");
  values_.assign(static_cast<std::size_t>(layers()) * grid.n_theta * grid.n_phi * 4, 0.0);
}

template <std::size_t C, class Project>
void SkyBrdfTable::fill(const std::array<SkyBrdfTable*, C>& tables, bool z_symmetric, const Project& project) {
  const AxisGrid& grid = tables[0]->grid_;
  const int nc = sh::num_coeffs(tables[0]->order_);
  // Rows are independent: workers take them in turn (results do not depend on the split).
  std::atomic<int> next_row{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  auto work = [&] {
    try {
      for (int i = next_row++; i < grid.n_theta; i = next_row++) {
        // A pole row (θ = 0 or π) is one direction: project once, copy along φ.
        // A z-symmetric sky: T(Rz(φ)·a) = rotate_z(T(a), φ), so project at φ_0 = 0 only.
        const bool pole = grid.theta(i) < 1e-12 || grid.theta(i) > sh::kPi - 1e-12;
        std::array<sh::Vec, C> t, t0;
        for (int j = 0; j < grid.n_phi; ++j) {
          if (j == 0) {
            t = t0 = project(grid.axis(i, j));
          } else if (!pole && z_symmetric) {
            for (std::size_t c = 0; c < C; ++c) t[c] = sh::rotate_z(t0[c], grid.phi(j));
          } else if (!pole) {
            t = project(grid.axis(i, j));
          }
          for (std::size_t c = 0; c < C; ++c)
            for (int k = 0; k < nc; ++k) tables[c]->values_[tables[c]->texel_index(k / 4, i, j, k % 4)] = t[c][k];
        }
      }
    } catch (...) {  // a throwing sky: stop all workers, rethrow on this thread
      next_row = grid.n_theta;
      std::lock_guard lock(failure_mutex);
      if (!failure) failure = std::current_exception();
    }
  };
  const int workers = std::clamp(static_cast<int>(std::thread::hardware_concurrency()), 1, 16);
  std::vector<std::thread> pool;
  for (int w = 1; w < workers; ++w) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
  for (SkyBrdfTable* table : tables) table->texels_.assign(table->values_.begin(), table->values_.end());
}

SkyBrdfTable::SkyBrdfTable(int order, double r, const Radiance& sky, const AxisGrid& grid, const LobeQuadrature& q,
                           bool z_symmetric)
    : SkyBrdfTable(order, r, grid) {
  if (!sky) throw std::invalid_argument("SkyBrdfTable: no sky radiance");
  const auto one = [&](const glm::dvec3& d) { return std::array<double, 1>{sky(d)}; };
  fill<1>({this}, z_symmetric, [&](const glm::dvec3& axis) { return project_channels<1>(order, r, one, axis, q); });
}

std::array<std::shared_ptr<const SkyBrdfTable>, 3> SkyBrdfTable::rgb(int order, double r, const RgbRadiance& sky,
                                                                   const AxisGrid& grid, const LobeQuadrature& q,
                                                                   bool z_symmetric) {
  if (!sky) throw std::invalid_argument("SkyBrdfTable: no sky radiance");
  std::array<std::shared_ptr<SkyBrdfTable>, 3> tables;
  for (auto& t : tables) t.reset(new SkyBrdfTable(order, r, grid));
  const auto three = [&](const glm::dvec3& d) {
    const glm::dvec3 c = sky(d);
    return std::array<double, 3>{c.r, c.g, c.b};
  };
  fill<3>({tables[0].get(), tables[1].get(), tables[2].get()}, z_symmetric,
          [&](const glm::dvec3& axis) { return project_channels<3>(order, r, three, axis, q); });
  return {tables[0], tables[1], tables[2]};
}

void SkyBrdfTable::lookup(const glm::dvec3& axis_in, std::span<double> out) const {
  const int nc = sh::num_coeffs(order_);
  if (out.size() != static_cast<std::size_t>(nc)) throw std::invalid_argument("SkyBrdfTable::lookup: size");
  const glm::dvec3 a = glm::normalize(axis_in);
  const double theta = std::acos(std::clamp(a.z, -1.0, 1.0));
  double phi = std::atan2(a.y, a.x);
  if (phi < 0.0) phi += 2.0 * sh::kPi;
  const double u = std::clamp(theta / grid_.theta_max, 0.0, 1.0) * (grid_.n_theta - 1);
  const int i0 = std::min(static_cast<int>(u), grid_.n_theta - 2);
  const double fu = u - i0;
  const double v = phi / (2.0 * sh::kPi) * grid_.n_phi;
  const int jf = static_cast<int>(std::floor(v));
  const double fv = v - jf;
  const int j0 = ((jf % grid_.n_phi) + grid_.n_phi) % grid_.n_phi, j1 = (j0 + 1) % grid_.n_phi;
  const double w00 = (1 - fu) * (1 - fv), w01 = (1 - fu) * fv, w10 = fu * (1 - fv), w11 = fu * fv;
  for (int k = 0; k < nc; ++k) {
    const int layer = k / 4, c = k % 4;
    out[k] = w00 * values_[texel_index(layer, i0, j0, c)] + w01 * values_[texel_index(layer, i0, j1, c)] +
             w10 * values_[texel_index(layer, i0 + 1, j0, c)] + w11 * values_[texel_index(layer, i0 + 1, j1, c)];
  }
}

sh::Vec SkyBrdfTable::lookup(const glm::dvec3& axis) const {
  sh::Vec out(sh::num_coeffs(order_));
  lookup(axis, out);
  return out;
}

double SkyBrdfTable::shade(std::span<const double> visibility, const glm::dvec3& axis) const {
  double t[sh::kMaxOrder * sh::kMaxOrder];
  const std::span<double> ts(t, sh::num_coeffs(order_));
  if (visibility.size() != ts.size()) throw std::invalid_argument("SkyBrdfTable::shade: visibility size");
  lookup(axis, ts);
  return sh::dot(visibility, ts);
}

}  // namespace skylit::shading
