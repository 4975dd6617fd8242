#include "flight/pose.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>
#include <numbers>

namespace skylit::flight {

glm::dmat3 body_to_enu(const Attitude& a) {
  const double psi = glm::radians(a.heading_deg), theta = glm::radians(a.pitch_deg), phi = glm::radians(a.bank_deg);
  const glm::dvec3 forward(std::sin(psi) * std::cos(theta), std::cos(psi) * std::cos(theta), std::sin(theta));
  const glm::dvec3 right_level(std::cos(psi), -std::sin(psi), 0.0);  // the right wing before banking
  const glm::dvec3 up_level = glm::cross(right_level, forward);
  const glm::dvec3 right = std::cos(phi) * right_level - std::sin(phi) * up_level;
  const glm::dvec3 up = std::sin(phi) * right_level + std::cos(phi) * up_level;
  return glm::dmat3(forward, -right, up);
}

}  // namespace skylit::flight
