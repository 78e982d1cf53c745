// Datasets sampled from a lighting model's domain instead of rendered from a mesh: rows of
// (normal, view) drawn over chosen sets of directions, shaded on the GPU. For the question "can
// a network learn this function", where a mesh's normals and a camera's views would be a bias.
//
// Every direction comes from a stratified point (u, v) in [0, 1)^2 through an equal-area map, so
// equal areas of (u, v) are equal solid angles (or equal projected solid angles, for "cosine").
// With c the cosine to the domain's axis A and phi = 2 pi v the angle about it:
//   normals  sphere      A = y (world up)     c = 1 - 2u                  c in [-1, 1]
//            hemisphere  A = axis (default y) c = 1 - u                   c in (0, 1]
//            lit         A = the light's dir  c = 1 - u                   n.l in (0, 1]
//   views    uniform     A = the row's normal c = 1 - (1 - e) u           n.v in (e, 1]
//            cosine      A = the row's normal c = sqrt(1 - (1 - e^2) u)   density proportional to n.v
// (e = kMinCosView) and the direction is c A + sqrt(1 - c^2) (cos phi t + sin phi b) for a fixed
// orthonormal frame (t, b) about A.
//
// The points are Owen-scrambled Sobol' (0, 2)-sequence points (a hash scramble after Burley
// 2020, one key per dimension drawn from the seed): every aligned block of 2^k rows puts exactly
// one point in every dyadic box of area 2^-k, whatever its shape, and any n is a sum of such
// blocks, so region counts stay within a few rows of their share. Normal i is paired with view
// point pi(i) for a seeded permutation pi; then the rows are split by a seeded permutation, as
// build_dataset does. Only integer arithmetic, SplitMix and IEEE +, -, *, / and sqrt decide a row
// (no libm trig, no std distributions; sample.cpp is compiled without FMA contraction), so the
// same request gives the same rows on any IEEE-754 machine.
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "data/build.h"
#include "data/dataset.h"
#include "scene/light.h"
#include "shading/color.h"
#include "shading/lighting_params.h"

namespace sn::data {

enum class NormalDomain { sphere, hemisphere, lit };
enum class ViewDomain { uniform, cosine };

// Throw "unknown normals domain 'x' (valid: sphere, hemisphere, lit)" and the like.
NormalDomain parse_normal_domain(const std::string& name);
ViewDomain parse_view_domain(const std::string& name);
const char* normal_domain_name(NormalDomain d);
const char* view_domain_name(ViewDomain d);

// The most rows one request may ask for: 2^24 rows are 600 MB of floats, 260 times the thesis'
// 64,149; more is a typo, not an experiment.
constexpr std::size_t kMaxSampleRows = std::size_t(1) << 24;
// Views never graze exactly: n.v >= 1e-5 keeps a float-rounded row from facing away (a back-facing
// view never occurs in a render). It removes 1e-5 of the uniform hemisphere's solid angle.
constexpr double kMinCosView = 1e-5;

struct SampleRequest {
  shading::LightingParams target;
  scene::Light light;
  std::size_t n = kThesisSamples;  // rows, training and validation together
  NormalDomain normals = NormalDomain::sphere;
  ViewDomain views = ViewDomain::uniform;
  glm::dvec3 axis{0.0, 1.0, 0.0};  // hemisphere only; any non-zero length (normalised here)
  uint64_t seed = 1;
  double split = 0.8;
  shading::ColorSpace color = shading::ColorSpace::rgb;
};

// Throws std::invalid_argument for anything sample_dataset would refuse (before any GPU work):
// a textured target, n outside 2..kMaxSampleRows, a split outside (0, 1) or one that leaves no
// training or no validation row, a zero-length or non-finite axis.
void validate(const SampleRequest& r);

// The rows' inputs in stratum order (before the split's permutation), on the CPU: normals[i] and
// views[i] are unit vectors, views[i] . normals[i] > 0.
struct Directions {
  std::vector<glm::vec3> normals, views;
};
Directions sample_directions(const SampleRequest& r);

// Samples, shades on the GPU (shaders/eval_lighting.comp) and splits; no cache.
std::shared_ptr<Dataset> sample_dataset(const SampleRequest& r);

// The full key text (readable): model, light, n, domains, axis, seed, split, colour, shaders.
std::string sample_key(const SampleRequest& r);
// sample_dataset through the dataset cache (dataset_cache.h): an identical request is a hit.
std::shared_ptr<Dataset> cached_sample_dataset(const SampleRequest& r);

// cos(2 pi t), sin(2 pi t) for t in [0, 1), from +, * and exact reductions only (reproducible
// where libm's cos and sin are not); within 2e-16 of the true values.
glm::dvec2 turn_cos_sin(double t);

}  // namespace sn::data
