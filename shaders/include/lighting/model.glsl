// The lighting model a shader evaluates, chosen at compile time by LIGHTING_MODEL (the order of
// sn::shading::Model): its parameters are uniforms named "u_" + parameter name, set from the
// model object by runtime/shading/lighting_gpu.cpp. Defines
//   vec3 lighting_raw(vec3 n, vec3 v, vec3 base)  radiance, finite and >= 0 for any input
//   vec3 lighting(vec3 n, vec3 v, vec3 base)      clamped to [0, 1], what images and datasets record
// n, v in world space (normalised here), base = the texture colour (textured models only).
#define LIGHTING_PHONG 0
#define LIGHTING_BLINN_PHONG 1
#define LIGHTING_GGX 2
#define LIGHTING_TOON3 3
#define LIGHTING_TEXTURED_PHONG 4

#ifndef LIGHTING_MODEL
#error "LIGHTING_MODEL is not defined (0 phong, 1 blinn_phong, 2 ggx, 3 toon3, 4 textured_phong)"
#endif

// Every model file is pasted unconditionally: the loader expands each #include once, before the
// GLSL preprocessor runs, so an #include inside an #if branch would be lost to the other branches.
#include "lighting/common.glsl"
#include "lighting/phong.glsl"
#include "lighting/blinn_phong.glsl"
#include "lighting/ggx.glsl"
#include "lighting/toon3.glsl"

uniform vec3 u_light_dir;    // unit, towards the light
uniform vec3 u_light_color;

#if LIGHTING_MODEL == LIGHTING_PHONG || LIGHTING_MODEL == LIGHTING_TEXTURED_PHONG
uniform vec3 u_color;
uniform float u_ambient;
uniform vec3 u_specular;
uniform float u_shininess;
#elif LIGHTING_MODEL == LIGHTING_BLINN_PHONG
uniform vec3 u_color;
uniform float u_ambient;
uniform vec3 u_specular;
uniform float u_shininess;
#elif LIGHTING_MODEL == LIGHTING_GGX
uniform float u_roughness;
uniform vec3 u_f0;
uniform vec3 u_diffuse;
uniform vec3 u_ambient;
#elif LIGHTING_MODEL == LIGHTING_TOON3
uniform vec3 u_ambient;
uniform vec3 u_diffuse;
uniform vec3 u_specular;
uniform float u_a;
uniform vec4 u_thresholds;
uniform float u_shininess;
uniform float u_ambient_weight;
uniform float u_specular_weight;
#else
#error "unknown LIGHTING_MODEL"
#endif

vec3 lighting_raw(vec3 n_in, vec3 v_in, vec3 base) {
  vec3 n = safe_normalize(n_in), v = safe_normalize(v_in), l = u_light_dir;
#if LIGHTING_MODEL == LIGHTING_PHONG
  return u_light_color * phong(n, v, l, u_color, u_ambient, u_specular, u_shininess);
#elif LIGHTING_MODEL == LIGHTING_TEXTURED_PHONG
  return u_light_color * phong(n, v, l, u_color * clamp(base, 0.0, 1.0), u_ambient, u_specular, u_shininess);
#elif LIGHTING_MODEL == LIGHTING_BLINN_PHONG
  return u_light_color * blinn_phong(n, v, l, u_color, u_ambient, u_specular, u_shininess);
#elif LIGHTING_MODEL == LIGHTING_GGX
  return ggx(n, v, l, u_roughness, u_f0, u_diffuse, u_ambient, u_light_color);
#elif LIGHTING_MODEL == LIGHTING_TOON3
  float s = phong_reflectance(n, v, l, u_ambient_weight, u_specular_weight, u_shininess);
  return toon3(s, u_ambient, u_diffuse, u_specular, u_a, u_thresholds);
#endif
}

vec3 lighting(vec3 n, vec3 v, vec3 base) { return clamp(lighting_raw(n, v, base), 0.0, 1.0); }
