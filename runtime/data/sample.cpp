#include "data/sample.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "data/dataset_cache.h"
#include "data/random.h"
#include "gl/buffer.h"
#include "io/text.h"
#include "scene/gather.h"
#include "shading/lighting_gpu.h"

namespace sn::data {

namespace {

const char* const kNormalNames[] = {"sphere", "hemisphere", "lit"};
const char* const kViewNames[] = {"uniform", "cosine"};

template <std::size_t N>
int parse_name(const std::string& name, const char* const (&names)[N], const char* what) {
  std::string valid;
  for (std::size_t i = 0; i < N; ++i) {
    if (name == names[i]) return int(i);
    valid += (i ? ", " : "") + std::string(names[i]);
  }
  throw std::invalid_argument(std::string("unknown ") + what + " domain '" + name + "' (valid: " + valid + ")");
}

// ---- stratified points: Owen-scrambled Sobol' (0, 2)-sequence ----

uint32_t reverse_bits(uint32_t x) {
  x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
  x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
  x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
  x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
  return (x >> 16) | (x << 16);
}

// Sobol's second dimension: bit k of the index adds direction v_k, v_0 = 2^31,
// v_k = v_{k-1} ^ (v_{k-1} >> 1) (the Pascal matrix mod 2). The first is the bit reversal.
uint32_t sobol_dim1(uint32_t index) {
  uint32_t x = 0;
  for (uint32_t v = 0x80000000u; index; index >>= 1, v ^= v >> 1)
    if (index & 1) x ^= v;
  return x;
}

// Nested uniform (Owen) scrambling by a hash: on the reversed bits, every step changes bit k
// only as a function of bits below it, i.e. each dyadic interval is mapped onto one of the same
// size, so a net stays a net. Constants: Helmer 2021 (as in Cycles and pbrt-v4).
uint32_t owen_scramble(uint32_t x, uint32_t key) {
  x = reverse_bits(x);
  x ^= x * 0x3d20adeau;
  x += key;
  x *= (key >> 16) | 1u;
  x ^= x * 0x05526c56u;
  x ^= x * 0x53a22864u;
  return reverse_bits(x);
}

// 32 scrambled bits and 21 from `jitter` below them: uniform in [0, 1) with 53 bits, never 1.
double to_unit(uint32_t bits, SplitMix& jitter) {
  return double((uint64_t(bits) << 21) | (jitter.next() >> 43)) * 0x1p-53;
}

// n stratified points of [0, 1)^2, one scramble key per dimension.
std::vector<glm::dvec2> stratified_points(std::size_t n, uint32_t key_u, uint32_t key_v, SplitMix& jitter) {
  std::vector<glm::dvec2> p(n);
  for (std::size_t i = 0; i < n; ++i) {
    const uint32_t u = owen_scramble(reverse_bits(uint32_t(i)), key_u);
    const uint32_t v = owen_scramble(sobol_dim1(uint32_t(i)), key_v);
    p[i] = {to_unit(u, jitter), to_unit(v, jitter)};
  }
  return p;
}

// ---- directions ----

// An orthonormal frame (t, b) about unit a (Duff et al. 2017, branchless): a = y gives t = x,
// b = -z, so the sphere's quadrants of phi are the octants' signs of x and z.
void frame(const glm::dvec3& a, glm::dvec3& t, glm::dvec3& b) {
  const double sign = std::copysign(1.0, a.z);
  const double k = -1.0 / (sign + a.z);
  const double m = a.x * a.y * k;
  t = {1.0 + sign * a.x * a.x * k, sign * m, -sign * a.x};
  b = {m, sign + a.y * a.y * k, -a.y};
}

// c a + s (cos phi t + sin phi b), with s = sqrt(1 - c^2) given (computed where it is accurate).
glm::dvec3 direction(const glm::dvec3& a, double c, double s, double turn) {
  glm::dvec3 t, b;
  frame(a, t, b);
  const glm::dvec2 cs = turn_cos_sin(turn);
  return c * a + s * (cs.x * t + cs.y * b);
}

glm::dvec3 normal_axis(const SampleRequest& r) {
  switch (r.normals) {
    case NormalDomain::sphere: return {0.0, 1.0, 0.0};
    case NormalDomain::hemisphere: return r.axis / glm::length(r.axis);
    case NormalDomain::lit: return r.light.dir;
  }
  return {0.0, 1.0, 0.0};
}

}  // namespace

NormalDomain parse_normal_domain(const std::string& name) { return NormalDomain(parse_name(name, kNormalNames, "normals")); }
ViewDomain parse_view_domain(const std::string& name) { return ViewDomain(parse_name(name, kViewNames, "views")); }
const char* normal_domain_name(NormalDomain d) { return kNormalNames[int(d)]; }
const char* view_domain_name(ViewDomain d) { return kViewNames[int(d)]; }

glm::dvec2 turn_cos_sin(double t) {
  // Quarter turns are exact: 4t and its fraction lose no bit, and so does the complement; what
  // is left is at most an eighth of a turn (x <= pi/4), where the Taylor series of sin to x^17
  // and of cos to x^18 leave less than 1e-19.
  const double w = 4.0 * t;
  const double q = std::floor(w);
  double f = w - q;
  const bool complement = f > 0.5;
  if (complement) f = 1.0 - f;
  const double x = f * 1.57079632679489661923, x2 = x * x;
  double s = 1.0, c = 1.0;
  for (int k = 16; k >= 2; k -= 2) s = 1.0 - x2 / double(k * (k + 1)) * s;
  for (int k = 17; k >= 1; k -= 2) c = 1.0 - x2 / double(k * (k + 1)) * c;
  s *= x;
  if (complement) std::swap(s, c);
  switch (int(q)) {
    case 0: return {c, s};
    case 1: return {-s, c};
    case 2: return {-c, -s};
    default: return {s, -c};
  }
}

void validate(const SampleRequest& r) {
  if (!r.target.spec().attributes.empty())
    throw std::invalid_argument("lighting model " + r.target.spec().name + " reads the attribute '" +
                                r.target.spec().attributes[0] +
                                "', which a sampled (normal, view) pair has not: build its dataset from a mesh "
                                "with scene:dataset{...}");
  if (r.n < 2 || r.n > kMaxSampleRows)
    throw std::invalid_argument("a sampled dataset has 2.." + std::to_string(kMaxSampleRows) + " rows, not " +
                                std::to_string(r.n));
  if (!(r.split > 0 && r.split < 1))
    throw std::invalid_argument("dataset split must lie strictly between 0 and 1 (the training share), got " +
                                io::number_text(r.split));
  const double len = glm::length(r.axis);
  if (!std::isfinite(len) || len < 1e-12)
    throw std::invalid_argument("the hemisphere's axis must be a non-zero, finite direction, got {" +
                                io::number_text(r.axis.x) + ", " + io::number_text(r.axis.y) + ", " +
                                io::number_text(r.axis.z) + "}");
}

Directions sample_directions(const SampleRequest& r) {
  validate(r);
  // Every random number below comes from this one stream, in this order.
  SplitMix seeds{r.seed};
  const uint64_t k0 = seeds.next(), k1 = seeds.next();
  SplitMix jitter{seeds.next()};
  SplitMix pairing{seeds.next()};
  const std::size_t n = r.n;
  const auto np = stratified_points(n, uint32_t(k0), uint32_t(k0 >> 32), jitter);
  const auto vp = stratified_points(n, uint32_t(k1), uint32_t(k1 >> 32), jitter);
  // Normal stratum i meets view stratum pi(i): both sets stay stratified, their pairing is random.
  std::vector<std::size_t> pi(n);
  std::iota(pi.begin(), pi.end(), 0);
  for (std::size_t i = n; i > 1; --i) std::swap(pi[i - 1], pi[pairing.below(i)]);

  const glm::dvec3 axis = normal_axis(r);
  constexpr double e = kMinCosView;
  Directions d;
  d.normals.resize(n);
  d.views.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double u = np[i].x;
    glm::dvec3 normal;
    if (r.normals == NormalDomain::sphere)
      normal = direction(axis, 1.0 - 2.0 * u, 2.0 * std::sqrt(u * (1.0 - u)), np[i].y);  // 1 - c^2 = 4u(1 - u)
    else
      normal = direction(axis, 1.0 - u, std::sqrt(u * (2.0 - u)), np[i].y);  // 1 - c^2 = u(2 - u)
    const glm::dvec2 w = vp[pi[i]];
    double c, s;
    if (r.views == ViewDomain::uniform) {
      const double a = (1.0 - e) * w.x;  // 1 - c
      c = 1.0 - a, s = std::sqrt(a * (2.0 - a));
    } else {
      const double s2 = (1.0 - e * e) * w.x;  // Malley: a uniform disc point lifted onto the hemisphere
      c = std::sqrt(1.0 - s2), s = std::sqrt(s2);
    }
    d.normals[i] = glm::vec3(normal);
    d.views[i] = glm::vec3(direction(normal, c, s, w.y));
  }
  return d;
}

std::shared_ptr<Dataset> sample_dataset(const SampleRequest& r) {
  Directions dirs = sample_directions(r);
  const std::size_t n = r.n;

  // Shaded in chunks, so GPU memory stays small whatever n is.
  constexpr std::size_t kChunk = std::size_t(1) << 20;
  const std::size_t cap = std::min(n, kChunk);
  gl::Buffer normals(gl::ElemType::vec4, cap), views(gl::ElemType::vec4, cap), targets(gl::ElemType::vec4, cap);
  std::vector<float> ys(n * 3), staging(cap * 4);
  for (std::size_t first = 0; first < n; first += kChunk) {
    const std::size_t m = std::min(kChunk, n - first);
    for (auto [from, to] : {std::pair{&dirs.normals, &normals}, std::pair{&dirs.views, &views}}) {
      for (std::size_t i = 0; i < m; ++i) {
        const glm::vec3& v = (*from)[first + i];
        staging[i * 4] = v.x, staging[i * 4 + 1] = v.y, staging[i * 4 + 2] = v.z, staging[i * 4 + 3] = 0.0f;
      }
      to->upload(staging.data(), 0, m * 4);
    }
    shading::evaluate(r.target, r.light, {{"normal", &normals}, {"view", &views}}, targets, m, r.color);
    const std::vector<float> t = scene::download_vec4(targets, m);
    shading::check_finite_targets(r.target, t, m, [&](std::size_t i) {
      const glm::vec3 &n = dirs.normals[first + i], &v = dirs.views[first + i];
      return "normal (" + io::number_text(n.x) + ", " + io::number_text(n.y) + ", " + io::number_text(n.z) +
             "), view (" + io::number_text(v.x) + ", " + io::number_text(v.y) + ", " + io::number_text(v.z) + ")";
    });
    for (std::size_t i = 0; i < m; ++i)
      for (int c = 0; c < 3; ++c) ys[(first + i) * 3 + c] = t[i * 4 + c];
  }

  // The split, as build_dataset's: a seeded permutation, the first share trains. Its stream is
  // seeded apart from the directions' (seed + 1 would reuse the stream shifted by one step).
  SplitMix rng{r.seed ^ 0x5851f42d4c957f2dull};
  std::vector<std::size_t> perm(n);
  std::iota(perm.begin(), perm.end(), 0);
  for (std::size_t i = n; i > 1; --i) std::swap(perm[i - 1], perm[rng.below(i)]);
  const std::size_t n_train = train_rows(r.split, n);

  auto d = std::make_shared<Dataset>();
  d->inputs = 6;
  d->outputs = 3;
  d->color = r.color;
  d->input_names = {"normal", "view"};
  d->train_x.reserve(n_train * 6), d->train_y.reserve(n_train * 3);
  d->val_x.reserve((n - n_train) * 6), d->val_y.reserve((n - n_train) * 3);
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t at = perm[j];
    auto& x = j < n_train ? d->train_x : d->val_x;
    auto& y = j < n_train ? d->train_y : d->val_y;
    const glm::vec3 &nn = dirs.normals[at], &vv = dirs.views[at];
    x.insert(x.end(), {nn.x, nn.y, nn.z, vv.x, vv.y, vv.z});
    y.insert(y.end(), ys.begin() + at * 3, ys.begin() + at * 3 + 3);
  }
  return d;
}

std::string sample_key(const SampleRequest& r) {
  const glm::dvec3 a = normal_axis(r);
  std::string k = "sample\nmodel ";
  k += r.target.key();
  k += "\n";
  k += scene::light_key(r.light);
  k += "\nn ";
  k += std::to_string(r.n);
  k += " normals ";
  k += normal_domain_name(r.normals);
  k += " views ";
  k += view_domain_name(r.views);
  k += "\naxis ";
  k += io::exact_text(a.x) + "," + io::exact_text(a.y) + "," + io::exact_text(a.z);
  k += "\ncolor ";
  k += shading::color_space_name(r.color);
  k += "\nsplit ";
  k += io::exact_text(r.split);
  k += " seed ";
  k += std::to_string(r.seed);
  k += "\nshaders ";
  k += shader_sources_hash({"eval_lighting.comp"}, shading::lighting_includes(r.target.spec()));
  return k;
}

std::shared_ptr<Dataset> cached_sample_dataset(const SampleRequest& r) {
  validate(r);  // before the key: it normalises the axis
  return cached(sample_key(r), [&] { return sample_dataset(r); });
}

}  // namespace sn::data
