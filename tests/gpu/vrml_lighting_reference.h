// An independent C++ statement of the VRML97 lighting equations (ISO/IEC 14772-1,
// 4.14.4) for the lighting tests, written from the standard rather than from the
// shader. Inputs are linear colours; returns the linear colour, clamped to [0, 1].
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/glm.hpp>

#include "engine/scene/scene.h"

namespace pw::test {

struct ReferenceSurface {
  glm::vec3 position;        // P
  glm::vec3 normal;          // N (unit)
  glm::vec3 eye;             // viewer position (V = normalize(eye - P))
  glm::vec3 diffuse;         // OD, linear
  float ambientIntensity;    // Oa
  glm::vec3 emissive;        // OE, linear
  glm::vec3 specular;        // OS, linear
  float shininess;           // 0..1
};

// `lights` carry linear colours.
inline glm::vec3 vrmlLighting(const ReferenceSurface& s, const std::vector<engine::Light>& lights) {
  glm::vec3 sum = s.emissive;
  const glm::vec3 V = glm::normalize(s.eye - s.position);
  for (const engine::Light& light : lights) {
    if (!light.on) continue;
    glm::vec3 L;
    double attenuation = 1.0, spot = 1.0;
    if (light.type == engine::LightType::kDirectional) {
      L = -glm::normalize(light.direction);
    } else {
      const glm::vec3 toLight = light.position - s.position;
      const double d = glm::length(toLight);
      if (d > light.radius) continue;
      L = toLight / float(d);
      const glm::vec3 a = light.attenuation;
      attenuation = 1.0 / std::max(a[0] + a[1] * d + a[2] * d * d, 1.0);
      if (light.type == engine::LightType::kSpot) {
        const double spotAngle = std::acos(std::clamp(double(glm::dot(-L, glm::normalize(light.direction))), -1.0, 1.0));
        const double beam = std::min(light.beamWidth, light.cutOffAngle);
        if (spotAngle >= light.cutOffAngle) spot = 0;
        else if (spotAngle <= beam) spot = 1;
        else spot = (spotAngle - light.cutOffAngle) / (beam - light.cutOffAngle);
      }
    }
    const glm::vec3 ambient = light.ambientIntensity * s.diffuse * s.ambientIntensity;
    const double nDotL = glm::dot(s.normal, L);
    glm::vec3 diffuse(0.0f), specular(0.0f);
    if (nDotL > 0) {
      diffuse = light.intensity * s.diffuse * float(nDotL);
      const double nDotH = std::max(0.0f, glm::dot(s.normal, glm::normalize(L + V)));
      specular = light.intensity * s.specular * float(std::pow(nDotH, double(s.shininess) * 128.0));
    }
    sum += float(attenuation * spot) * light.color * (ambient + diffuse + specular);
  }
  return glm::clamp(sum, glm::vec3(0.0f), glm::vec3(1.0f));
}

}  // namespace pw::test
