// GLSL of the renderer (GLSL 3.30 core, so a 3.3 context also works). Stream units throughout:
// linear values of the decoded 8-bit lightmap and sky codes.
#pragma once

namespace vbim::render::shaders {

// Shared by every fragment shader: sky lookup, haze, display transform.
inline constexpr const char* kCommon = R"(
uniform sampler2D uSky;        // lat-long dome: s = azimuth from north clockwise, t = zenith angle / 90 deg
uniform vec3 uEye;
uniform float uHazeDistance;
uniform float uExposure;
const float PI = 3.14159265358979;

vec3 skyRadiance(vec3 d) {     // pi L / exposure towards d (x east, y up, z south)
  float az = atan(d.x, -d.z);
  float theta = acos(clamp(d.y, -1.0, 1.0));
  vec2 st = vec2(az / (2.0 * PI), min(theta / (0.5 * PI), 1.0));
  vec3 c = texture(uSky, st).rgb;
  return d.y < 0.0 ? c * mix(1.0, 0.6, clamp(-d.y * 4.0, 0.0, 1.0)) : c;
}

// Distance haze: towards the streamed sky's colour at the horizon in the viewing direction.
vec3 applyHaze(vec3 c, vec3 world) {
  vec3 v = world - uEye;
  float dist = length(v);
  vec3 dir = v / max(dist, 1e-3);
  vec3 horizon = skyRadiance(normalize(vec3(dir.x, 0.02, dir.z)));
  return mix(c, horizon, 1.0 - exp(-dist / uHazeDistance));
}

vec4 display(vec3 linear) {    // exposure, soft shoulder, sRGB
  vec3 x = 1.0 - exp(-max(linear, 0.0) * uExposure);
  vec3 s = mix(x * 12.92, 1.055 * pow(x, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, x));
  return vec4(s, 1.0);
}
)";

inline constexpr const char* kTerrainVertex = R"(#version 330 core
layout(location = 0) in vec3 aPos;
uniform mat4 uViewProj;
uniform vec2 uTexel;           // (1 / (cell * width), 1 / (cell * height))
uniform vec2 uHalfTexel;       // (0.5 / width, 0.5 / height): texel centres
out vec3 vWorld;
out vec2 vUv;
void main() {
  vWorld = aPos;
  vUv = aPos.xz * uTexel + uHalfTexel;
  gl_Position = uViewProj * vec4(aPos, 1.0);
}
)";

// Hoffman & Mitchell: the terrain's colour is its diffuse colour times the lightmap.
inline constexpr const char* kTerrainFragment = R"(
uniform sampler2D uLightmap;   // sRGB texture: sampled as linear irradiance
uniform sampler2D uAlbedo;
in vec3 vWorld;
in vec2 vUv;
out vec4 oColor;
void main() {
  vec3 c = texture(uAlbedo, vUv).rgb * texture(uLightmap, vUv).rgb;
  oColor = display(applyHaze(c, vWorld));
}
)";

inline constexpr const char* kSkyVertex = R"(#version 330 core
out vec2 vNdc;
void main() {                  // one triangle covering the screen, at the far plane
  vec2 p = vec2((gl_VertexID == 1) ? 3.0 : -1.0, (gl_VertexID == 2) ? 3.0 : -1.0);
  vNdc = p;
  gl_Position = vec4(p, 1.0, 1.0);
}
)";

inline constexpr const char* kSkyFragment = R"(
uniform mat4 uInvViewProj;
in vec2 vNdc;
out vec4 oColor;
void main() {
  vec4 a = uInvViewProj * vec4(vNdc, -1.0, 1.0);
  vec4 b = uInvViewProj * vec4(vNdc, 1.0, 1.0);
  vec3 d = normalize(b.xyz / b.w - a.xyz / a.w);
  oColor = display(skyRadiance(d));
}
)";

inline constexpr const char* kObjectVertex = R"(#version 330 core
layout(location = 0) in vec3 aPos;
layout(location = 1) in vec3 aNormal;
uniform mat4 uViewProj;
uniform mat4 uModel;
uniform mat3 uNormalMatrix;
out vec3 vWorld;
out vec3 vNormal;
void main() {
  vec4 w = uModel * vec4(aPos, 1.0);
  vWorld = w.xyz;
  vNormal = uNormalMatrix * aNormal;
  gl_Position = uViewProj * w;
}
)";

// The objects' lighting (docs/render.md "Objects"):
//   E = sun * max(0, N.L) * O(p)                        direct sun, shadow term from the lightmap at p
//     + sky * (1 + N.y) / 2                             Hargreaves: the sky half of the hemisphere
//     + G(p + offset * N) * (1 - N.T) / 2               ground half: Hargreaves' ground colour G =
//                                                       albedo x lightmap sampled along the normal, on
//                                                       IceFall's ground plane tilted toward the sun,
//                                                       T = normalize(0.75 up + L) while the sun is up
inline constexpr const char* kObjectFragment = R"(
uniform sampler2D uLightmap;
uniform sampler2D uAlbedo;
uniform sampler2D uSunVisibility;
uniform vec2 uTexel;
uniform vec2 uHalfTexel;
uniform vec3 uSunDir;
uniform vec3 uSunIrradiance;
uniform vec3 uSkyIrradiance;
uniform float uGroundOffset;
uniform vec3 uObjectAlbedo;
in vec3 vWorld;
in vec3 vNormal;
out vec4 oColor;
vec2 groundUv(vec3 p) { return p.xz * uTexel + uHalfTexel; }
void main() {
  vec3 n = normalize(vNormal);
  float shadow = texture(uSunVisibility, groundUv(vWorld)).r;
  vec3 direct = uSunIrradiance * max(dot(n, uSunDir), 0.0) * shadow;
  vec2 g = groundUv(vWorld + n * uGroundOffset);
  vec3 ground = texture(uAlbedo, g).rgb * texture(uLightmap, g).rgb;
  vec3 tilted = uSunDir.y > 0.0 ? normalize(0.75 * vec3(0.0, 1.0, 0.0) + uSunDir) : vec3(0.0, 1.0, 0.0);
  vec3 ambient = uSkyIrradiance * (0.5 + 0.5 * n.y) + ground * (0.5 - 0.5 * dot(n, tilted));
  oColor = display(applyHaze(uObjectAlbedo * (direct + ambient), vWorld));
}
)";

}  // namespace vbim::render::shaders
