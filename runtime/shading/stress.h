// The numerical stress test: every lighting model over an adversarial grid of inputs (n.l and
// n.v at -1, 0, +-1e-7, grazing and 1; v = l, v = -l, v = the mirror direction; zero-length,
// tiny, huge and unnormalised vectors), on the GPU and on the CPU twin, counting NaN, Inf and
// out-of-range outputs. The required count is zero everywhere (scripts/stress_lighting.lua).
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/light.h"
#include "shading/lighting_gpu.h"
#include "shading/lighting_params.h"

namespace sn::shading {

struct StressSample {
  glm::vec3 n, v, base;
  glm::vec3 uv;  // .xy
  glm::vec3 position, world_position;
  glm::vec3 tangent, bitangent;  // a frame around n at varying angles; some zero, some along n
};
// The grid, built around the light direction (deterministic; about 30k samples).
std::vector<StressSample> adversarial_grid(const scene::Light& light);
// The grid as per-attribute sample lists (for evaluate), and one sample as the twin of a model
// reading `attributes` sees it: the others keep Surface's defaults, which the GPU gives an
// attribute a model does not read.
HostSamples stress_samples(const std::vector<StressSample>& grid);
Surface stress_surface(const StressSample& x, const scene::Light& light, const std::vector<std::string>& attributes);

struct StressCounts {
  std::size_t nan = 0, inf = 0;
  std::size_t negative = 0;  // raw radiance below 0
  std::size_t over = 0;      // raw radiance above upper_bound()
  std::size_t total() const { return nan + inf + negative + over; }
};

struct StressResult {
  std::size_t samples = 0;
  StressCounts gpu, twin;  // raw radiance (before the [0, 1] clamp)
  // What a dataset records, in every colour space (rgb, hsv, cie_xyz, cie_lab), on the GPU:
  // NaN/Inf, or outside the space's range ([0, 1]; XYZ within [0, D65 white]).
  std::size_t encoded_nan = 0, encoded_out_of_range = 0;
  double max_raw = 0;  // largest finite raw channel seen (GPU)
  std::size_t failures() const { return gpu.total() + twin.total() + encoded_nan + encoded_out_of_range; }
};

StressResult stress_test(const LightingParams& p, const scene::Light& light);
// Summed over `lights`.
StressResult stress_test(const LightingParams& p, const std::vector<scene::Light>& lights);
// An oblique light, and one along +Y, for which n.l = 0 and n.v = 0 are exact in float.
std::vector<scene::Light> stress_lights();

// sn.lighting.check: the GPU shader against the twin (raw radiance) over the adversarial grid
// and 20,000 random unit (n, v) pairs, skipping points within kTwinBranchEps of a branch
// (near_discontinuity). The difference is
// |gpu - twin| / max(1, |twin|) per channel; NaN or Inf on either side is infinite.
constexpr double kTwinBranchEps = 1e-3;
struct TwinCheck {
  double max_difference = 0;
  std::size_t compared = 0, skipped = 0;
  Surface worst;  // where the largest difference is
  glm::dvec3 worst_gpu{0.0}, worst_twin{0.0};
};
// Which points: every `grid_stride`-th point of the grid and `random` random pairs, per light.
struct TwinPoints {
  std::size_t grid_stride = 1, random = 20000;
};
TwinCheck check_twin(const LightingParams& p, const std::vector<scene::Light>& lights, const TwinPoints& points = {});

// What sn.lighting.define holds a definition to before it registers it (a twin wrong by a factor,
// or NaN where the GLSL is not, was taken at one probe point, and model:shade then gave it):
// check_twin's points, thinned to kHoldPoints (about 2,000: a few ms of twin calls), under
// `light`. A point fails where the GPU and the twin differ by more than kHoldTolerance (relative,
// as check_twin measures; NaN or Inf on one side only fails, on both sides is the stress test's
// to report), unless the twin with n, v or l tilted by kHoldTilt or stretched by kHoldStretch
// reaches the GPU's value: a branch or a lobe so steep that float rounding of the inputs crosses
// it, where the twin is right. The shipped models differ by 6e-6 at most at their defaults
// (check_twin; docs/lua-api/ground-truth.md).
constexpr double kHoldTolerance = 1e-3, kHoldTilt = 1e-3, kHoldStretch = 1e-6;
constexpr TwinPoints kHoldPoints{19, 1000};  // 19 is prime to the grid's 25 lengths per direction
struct TwinMismatch {
  bool failed = false;
  Surface at;  // the worst point the rounding does not explain
  glm::dvec3 gpu{0.0}, twin{0.0};
  double difference = 0;
};
TwinMismatch hold_twin(const LightingParams& p, const scene::Light& light);
// Where sn.lighting.define holds a model: its defaults, and every parameter halfway from its
// default to the nearer end of its range (a twin that drops a parameter, or squares it, agrees
// with the GLSL wherever the defaults hide that), under the oblique stress light tinted, so that
// a twin that drops the light's colour shows.
std::vector<LightingParams> hold_params(const ModelPtr& m);
scene::Light hold_light();

// The models the stress table covers: each model at its defaults and at the edges of its
// domain (roughness 0, 1e-4, 1; exponents 0 and 1e6; weights at their maxima; equal thresholds).
struct StressCase {
  std::string label;
  LightingParams params;
};
std::vector<StressCase> stress_cases();

}  // namespace sn::shading
