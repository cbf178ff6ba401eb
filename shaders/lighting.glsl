// VRML97 lighting (ISO/IEC 14772-1, 4.14.4), in linear light, shared by the fragment
// shader (per pixel) and the vertex shader (per vertex, the interactive profile on CPU
// devices):
//   I = OE + SUM_i( on_i * attenuation_i * spot_i * IL_i * (ambient_i + diffuse_i + specular_i) )
//   attenuation_i = 1 / max(a0 + a1 d + a2 d^2, 1)   (1 for directional lights)
//   ambient_i  = Ia_i * OD * Oa
//   diffuse_i  = I_i * OD * (N . L)
//   specular_i = I_i * OS * (N . normalize(L + V))^(shininess * 128)
// with OD the diffuse colour replaced by the per-vertex colour or the texture (4.14.3,
// table 4.5), and no fog. The sum is kept in two parts, what OD multiplies and what it
// does not: I = OE + OD * diffuse + specular, so that lighting worked out per vertex
// can take the texture's OD per pixel.
// Needs `frame` (FrameBlock), `lights` (LightBlock), `lightLists` (LightListBlock) and
// `draw` (the push constants) declared before it.

struct LightTerms {
  vec3 diffuse;   // SUM_i of on * attenuation * spot * IL * (Ia * Oa + I * (N . L))
  vec3 specular;  // SUM_i of on * attenuation * spot * IL * I * OS * highlight
};

// One light's terms for a unit vector L towards it, times `scale` (attenuation * spot).
void addLight(inout LightTerms terms, const float scale, const vec3 color, const float intensity,
              const float ambientIntensity, const vec3 L, const vec3 N, const vec3 V, const MaterialGpu m) {
  const float nDotL = dot(N, L);
  terms.diffuse += scale * color * (ambientIntensity * m.diffuseAmbient.a + intensity * max(nDotL, 0.0));
  // Most materials have no specular colour. The test is on a push constant, so it is a
  // real branch on every device and those materials never pay for pow().
  if (m.flags.y != 0u && nDotL > 0.0) {
    const vec3 halfway = L + V;
    const float halfLength = length(halfway);
    const float nDotH = halfLength > 0.0 ? max(dot(N, halfway / halfLength), 0.0) : 0.0;
    const float exponent = m.specularShininess.a;
    const float highlight = exponent > 0.0 ? pow(nDotH, exponent) : 1.0;
    terms.specular += scale * color * intensity * m.specularShininess.rgb * highlight;
  }
}

// Point and spot lights: L, d and the attenuation (0 beyond the radius).
float pointAttenuation(const LightGpu light, const vec3 P, const vec3 N, out vec3 L) {
  const vec3 toLight = light.positionType.xyz - P;
  const float d = length(toLight);
  L = d > 0.0 ? toLight / d : N;
  const vec3 a = light.attenuationRadius.xyz;
  return d > light.attenuationRadius.w ? 0.0 : 1.0 / max(a.x + a.y * d + a.z * d * d, 1.0);
}

// The VRML97 spot factor (4.14.4): 1 inside beamWidth, 0 beyond cutOffAngle, linear
// in the angle between.
float spotFactor(const LightGpu light, const vec3 L) {
  const float spotAngle = acos(clamp(dot(-L, light.directionAmbient.xyz), -1.0, 1.0));
  const float beamWidth = light.spot.x;
  const float cutOffAngle = light.spot.y;
  if (spotAngle >= cutOffAngle) return 0.0;
  if (spotAngle <= beamWidth) return 1.0;
  return (spotAngle - cutOffAngle) / (beamWidth - cutOffAngle);
}

// All the lights at world position P with unit normal N.
LightTerms lightTerms(const vec3 P, const vec3 N, const MaterialGpu m) {
  const vec3 V = normalize(frame.cameraPosition.xyz - P);
  LightTerms terms = LightTerms(vec3(0.0), vec3(0.0));
  // Directional lights come first in the light buffer and reach everything; the point
  // and spot lights within reach of this shape come as a list with its draw. Every
  // count is uniform (a uniform or a push constant), so every loop is a real loop on
  // every device, and a kind the shape lacks costs nothing.
  for (uint i = 0u; i < frame.lightCounts.x; ++i) {
    const LightGpu light = lights[i];
    addLight(terms, 1.0, light.colorIntensity.rgb, light.colorIntensity.a, light.directionAmbient.w,
             -light.directionAmbient.xyz, N, V, m);
  }
  uint k = draw.lightListOffset;
  for (uint end = k + draw.pointLightCount; k < end; ++k) {
    const LightGpu light = lights[lightLists[k]];
    vec3 L;
    const float attenuation = pointAttenuation(light, P, N, L);
    addLight(terms, attenuation, light.colorIntensity.rgb, light.colorIntensity.a, light.directionAmbient.w, L, N, V, m);
  }
  for (uint end = k + draw.spotLightCount; k < end; ++k) {
    const LightGpu light = lights[lightLists[k]];
    vec3 L;
    const float attenuation = pointAttenuation(light, P, N, L) * spotFactor(light, L);
    addLight(terms, attenuation, light.colorIntensity.rgb, light.colorIntensity.a, light.directionAmbient.w, L, N, V, m);
  }
  if (frame.lightCounts.w != 0u) {
    // The headlight: a white directional light along the view, intensity 1, no ambient (6.29).
    addLight(terms, 1.0, vec3(1.0), 1.0, 0.0, -frame.headlightDirection.xyz, N, V, m);
  }
  return terms;
}
