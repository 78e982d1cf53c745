#include "data/dataset_cache.h"

#include <cstdio>
#include <cstring>
#include <list>
#include <utility>

#include "gl/shader_source.h"
#include "io/hash.h"
#include "io/limits.h"
#include "shading/lighting_gpu.h"
#include "io/text.h"
#include "scene/gbuffer.h"
#include "scene/transform.h"

namespace sn::data {

namespace {

using io::hex64;

std::string vec3_text(const glm::dvec3& v) { return io::exact_text(v.x) + "," + io::exact_text(v.y) + "," + io::exact_text(v.z); }

struct Cache {
  std::list<std::pair<std::string, std::shared_ptr<Dataset>>> entries;  // most recent first
  std::size_t builds = 0, hits = 0;
};
Cache& cache() {
  static Cache c;
  return c;
}

}  // namespace

std::string shader_sources_hash(std::initializer_list<const char*> files, const gl::Includes& includes) {
  io::Fnv1a f;
  for (const char* file : files) {
    std::string text = gl::preprocess(file, {}, includes).text;
    f.bytes(text.data(), text.size());
  }
  return hex64(f.h);
}

uint64_t mesh_content_hash(const scene::Mesh& m) {
  io::Fnv1a f;
  f.vec(m.positions);
  f.vec(m.normals);
  f.vec(m.uvs);
  f.vec(m.indices);
  f.vec(m.tangents);
  const std::vector<unsigned char>* encoded = m.base_color.encoded();
  // The sampler's wrap modes change what a texture shows outside [0, 1], its filters what it shows
  // between texels.
  const scene::Sampler& s = m.base_color.sampler;
  uint8_t flags[7] = {uint8_t(m.has_uvs), uint8_t(m.base_color.has_value()), uint8_t(encoded != nullptr),
                      uint8_t(s.s), uint8_t(s.t), uint8_t(s.mag), uint8_t(s.min)};
  f.bytes(flags, sizeof flags);
  if (encoded) {
    f.vec(*encoded);  // the file's bytes: hashed without decoding them (OpenImageIO is not loaded)
  } else if (m.base_color) {
    int dims[3] = {m.base_color->width, m.base_color->height, m.base_color->channels};
    f.bytes(dims, sizeof dims);
    f.vec(m.base_color->pixels);
  }
  return f.h;
}

std::string dataset_key(const scene::Scene& s, const DatasetRequest& r) {
  std::string k = "meshes";
  for (const auto& m : s.meshes) k += " " + hex64(mesh_content_hash(*m.mesh)) + " " + scene::transform_key(m.transform);
  k += "\nposes";
  std::vector<int> poses = r.poses;
  if (poses.empty())
    for (int i = 0; i < int(s.poses.size()); ++i) poses.push_back(i);
  for (int p : poses)
    if (p >= 0 && p < int(s.poses.size())) k += "\n  " + scene::transform_key(s.poses[size_t(p)]);
  k += "\nsize " + std::to_string(s.width) + "x" + std::to_string(s.height);
  std::vector<int> views = r.views;
  if (views.empty())
    for (int i = 0; i < int(s.views.size()); ++i) views.push_back(i);
  k += "\nviews";
  for (int v : views) {
    if (v < 0 || v >= int(s.views.size())) continue;  // build_dataset reports it
    const scene::Camera& c = s.views[v];
    k += "\n  " + vec3_text(c.eye()) + " " + vec3_text(c.target()) + " " + vec3_text(c.up()) + " " +
         io::exact_text(c.fov_y()) + " " + io::exact_text(c.aspect_for(s.width, s.height)) + " " + io::exact_text(c.near()) + " " + io::exact_text(c.far());
  }
  k += "\nmodel " + r.target.key();
  k += "\n" + scene::light_key(s.light);
  k += "\ninputs";
  for (const auto& a : r.inputs) k += " " + a;
  k += "\ncolor " + std::string(shading::color_space_name(r.color));
  for (const auto& v : r.vary) k += "\nvary " + v.name + " " + io::exact_text(v.min) + " " + io::exact_text(v.max);
  k += "\nsplit " + io::exact_text(r.split) + " seed " + std::to_string(r.seed) + " samples " + std::to_string(r.samples);
  // The shaders every number of a scene dataset passes through.
  std::vector<std::string> vary;
  for (const auto& v : r.vary) vary.push_back(v.name);
  k += "\nshaders " + shader_sources_hash({"mesh.vert", "gbuffer.frag", "gather.comp", "eval_lighting.comp"},
                                         shading::lighting_includes(r.target.spec(), vary));
  return k;
}

std::shared_ptr<Dataset> cached_dataset(const scene::Scene& s, const DatasetRequest& r) {
  return cached(dataset_key(s, r), [&] { return build_dataset(s, r); });
}

std::shared_ptr<Dataset> cached(const std::string& key, const std::function<std::shared_ptr<Dataset>()>& build) {
  Cache& c = cache();
  for (auto it = c.entries.begin(); it != c.entries.end(); ++it) {
    if (it->first == key) {
      c.entries.splice(c.entries.begin(), c.entries, it);  // most recently used
      ++c.hits;
      return c.entries.front().second;
    }
  }
  auto d = build();
  io::Fnv1a f;
  f.bytes(key.data(), key.size());
  d->key = "dataset-" + hex64(f.h);
  ++c.builds;
  c.entries.emplace_front(key, d);
  std::size_t bytes = 0;
  for (const auto& e : c.entries) bytes += dataset_bytes(*e.second);
  const std::uint64_t most = io::limits().dataset_cache_bytes;
  while (c.entries.size() > 1 && (c.entries.size() > kDatasetCacheCapacity || bytes > most)) {
    bytes -= dataset_bytes(*c.entries.back().second);
    c.entries.pop_back();
  }
  return d;
}

std::size_t dataset_bytes(const Dataset& d) {
  return (d.train_x.size() + d.train_y.size() + d.val_x.size() + d.val_y.size()) * sizeof(float);
}

DatasetStats dataset_stats() {
  const Cache& c = cache();
  return {c.builds, c.hits, scene::gbuffer_renders(), c.entries.size()};
}

void clear_dataset_cache() { cache().entries.clear(); }

}  // namespace sn::data
