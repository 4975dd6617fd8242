// Sphere sets for the blocker tests: a 30-sphere airliner (wing, fuselage, tail) and a
// spread of cases (one airliner, a fleet of five, 400 coincident spheres, 200 scattered,
// one small sphere).
#pragma once

#include <random>
#include <vector>

#include <glm/vec3.hpp>

#include "shading/blockers/sphere_blocker.h"

namespace skylit::blockers::test {

inline std::vector<Sphere> airliner(const glm::dvec3& c) {
  std::vector<Sphere> s;
  for (int k = 0; k < 20; ++k) s.push_back({c + glm::dvec3(0, (k - 9.5) * 1.75, 0), 0.9});
  for (int k = 0; k < 8; ++k) s.push_back({c + glm::dvec3((k - 3.5) * 1.75, 0, 0), 1.25});
  s.push_back({c + glm::dvec3(-9.0, 0, 2.0), 1.2});
  s.push_back({c + glm::dvec3(-9.0, 0, 3.5), 1.2});
  return s;
}

inline std::vector<std::vector<Sphere>> sphere_cases() {
  std::vector<Sphere> fleet, scattered;
  for (int k = 0; k < 5; ++k) {
    const auto a = airliner({300.0 * k, 100.0 * (k % 2), 500.0});
    fleet.insert(fleet.end(), a.begin(), a.end());
  }
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int k = 0; k < 200; ++k) scattered.push_back({{u(rng) * 400, u(rng) * 400, 50 + u(rng) * 100}, 0.1 + 3 * u(rng)});
  return {airliner({0, 0, 150}), fleet, std::vector<Sphere>(400, {{5, 5, 30}, 5.0}), scattered, {{{1, 2, 3}, 0.5}}};
}

}  // namespace skylit::blockers::test
