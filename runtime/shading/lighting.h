// The CPU twin of shaders/include/lighting/*.glsl: every lighting model in double precision,
// written operation for operation like the shaders (same guards, same clamps), so a test can
// hold the GPU to it. Formulas and domains: docs/lighting.md.
//
// Every model returns radiance for one directional light. The "raw" value is finite and >= 0
// for any input (zero-length or unnormalised vectors, grazing angles, v = -l, roughness 0,
// extreme exponents) and never exceeds upper_bound(); the value a dataset or image records is
// raw clamped to [0, 1], as the thesis' 8-bit framebuffer did.
#pragma once
#include <glm/glm.hpp>

#include "scene/light.h"
#include "shading/lighting_model.h"
#include "shading/lighting_params.h"

namespace sn::shading {

// Shared constants (same values in shaders/include/lighting/common.glsl).
constexpr double kPi = 3.14159265358979323846;
constexpr double kMinLength2 = 1e-30;  // below this squared length a vector counts as zero
constexpr double kMinAlpha = 1e-3;     // GGX width floor: alpha = max(roughness^2, 1e-3)
constexpr double kMinDenominator = 1e-30;

// x / |x|, or the zero vector when |x|^2 < kMinLength2: unit or zero, never NaN, never between.
glm::dvec3 safe_normalize(const glm::dvec3& x);
// max(cos t, 0)^e for the angle t between a and b (any lengths; zero-length gives 0), with 0^0 = 1.
// The shader computes the same value from sin^2 t to keep sharp lobes accurate in float.
double cos_lobe(const glm::dvec3& a, const glm::dvec3& b, double e);

// Phong's reflectance S_p = C_p [max(n.l, 0)(1 - d) + d] + W max(r.v, 0)^n, the specular term
// only where the light is in front (n.l > 0); r = 2 (n.l) n - l. Per channel: C_p and W are RGB.
glm::dvec3 phong(const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3& l, const glm::dvec3& color,
                 double ambient, const glm::dvec3& specular, double shininess);
// The same with Blinn's half-vector lobe max(n.h, 0)^n, h = normalize(l + v).
glm::dvec3 blinn_phong(const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3& l, const glm::dvec3& color,
                       double ambient, const glm::dvec3& specular, double shininess);
// The scalar S_p of toon3 (C_p = 1, scalar W).
double phong_reflectance(const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3& l, double ambient,
                         double specular, double shininess);

// GGX / Trowbridge-Reitz normal distribution D(h) for unit n, h and width alpha.
double ggx_distribution(const glm::dvec3& n, const glm::dvec3& h, double alpha);
// Height-correlated Smith visibility V = G2 / (4 n.l n.v), multiplied by n.l (finite at n.l -> 0).
double smith_visibility_nl(double nl, double nv, double alpha);
// Schlick's Fresnel with RGB F0.
glm::dvec3 fresnel_schlick(const glm::dvec3& f0, double vh);
// Cook-Torrance GGX: A (rho_d + F0) + E [rho_d + pi D V F] n.l, the BRDF term only where n.l > 0
// and the specular lobe only where n.v > 0 too (see docs/lighting.md).
glm::dvec3 ggx(const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3& l, double roughness, const glm::dvec3& f0,
               const glm::dvec3& diffuse, const glm::dvec3& ambient_light, const glm::dvec3& light_color);
// The thesis' three-colour toon shading (section 4.4) over S_p.
glm::dvec3 toon3(double s_p, const glm::dvec3& c_a, const glm::dvec3& c_d, const glm::dvec3& c_s, double a,
                 const glm::dvec4& thresholds);

// The model as a whole, through its registered twin (lighting_model.h). shade() = clamp(shade_raw(), 0, 1).
glm::dvec3 shade_raw(const LightingParams& p, const Surface& s);
glm::dvec3 shade(const LightingParams& p, const Surface& s);
// The same at (n, v) as given (normalised here) with `base` the texture colour (textured models).
glm::dvec3 shade_raw(const LightingParams& p, const scene::Light& light, const glm::dvec3& n, const glm::dvec3& v,
                     const glm::dvec3& base = glm::dvec3(1.0));
glm::dvec3 shade(const LightingParams& p, const scene::Light& light, const glm::dvec3& n, const glm::dvec3& v,
                 const glm::dvec3& base = glm::dvec3(1.0));
// A per-channel bound on shade_raw over every input (base colours in [0, 1]); +infinity for a
// model whose definition gives none.
glm::dvec3 upper_bound(const LightingParams& p, const scene::Light& light);
// True when the point lies within `eps` of a branch of the model (n.l = 0, n.v = 0, v = -l, or
// one its definition names, such as a toon3 threshold), where float and double may take
// different sides.
bool near_discontinuity(const LightingParams& p, const Surface& s, double eps);
bool near_discontinuity(const LightingParams& p, const scene::Light& light, const glm::dvec3& n, const glm::dvec3& v,
                        double eps);

}  // namespace sn::shading
