// The G-buffer pass, the GPU gather, truth images and datasets, against analytic geometry (a
// sphere seen by a pinhole camera: camera.ray() is the oracle) and the lighting twin.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <set>

#include <glm/gtc/matrix_transform.hpp>

#include "gl/context.h"
#include "data/dataset_cache.h"
#include "scene/gather.h"
#include "scene/gbuffer.h"
#include "scene/gltf.h"
#include "scene/procedural.h"
#include "scene/scene.h"
#include "shading/color.h"
#include "shading/lighting.h"
#include "shading/render_truth.h"

namespace {

using namespace sn;
using glm::dvec3;

constexpr int W = 96, H = 80;

struct Fixture {
  scene::Mesh sphere = scene::sphere(1.0, 128, 64);
  scene::Camera camera{{0.4, 0.8, 3.0}, {0, 0, 0}};
};

// Where the camera ray through pixel (x, y) (top-left origin) meets the unit sphere.
std::optional<dvec3> hit(const scene::Camera& c, int x, int y) {
  scene::Ray r = c.ray(x, y, W, H);
  double b = glm::dot(r.origin, r.direction), cc = glm::dot(r.origin, r.origin) - 1;
  double disc = b * b - cc;
  if (disc < 0) return std::nullopt;
  return r.origin + (-b - std::sqrt(disc)) * r.direction;
}

// Distance of the ray from the sphere's centre: 1 on the silhouette.
double miss_distance(const scene::Camera& c, int x, int y) {
  scene::Ray r = c.ray(x, y, W, H);
  return glm::length(r.origin - glm::dot(r.origin, r.direction) * r.direction);
}

dvec3 px(const io::Image& img, int x, int y) { return {img.at(x, y, 0), img.at(x, y, 1), img.at(x, y, 2)}; }

TEST(GBuffer, MatchesTheAnalyticSphere) {
  gl::current();
  Fixture f;
  auto g = scene::render_gbuffer({{&f.sphere}}, f.camera, W, H, {"normal", "view", "world_position", "position", "uv"});
  ASSERT_EQ(g.target->attachments(), 5);
  io::Image normal = g.target->read(0), view = g.target->read(1), world = g.target->read(2), object = g.target->read(3),
            uv = g.target->read(4);
  int covered = 0, mismatched = 0, compared_uv = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      auto h = hit(f.camera, x, y);
      bool cov = normal.at(x, y, 3) > 0.5f;
      if (cov != h.has_value()) {
        ++mismatched;  // only on the silhouette, where the polygon and the sphere differ
        EXPECT_NEAR(miss_distance(f.camera, x, y), 1.0, 0.02) << x << "," << y;
        continue;
      }
      if (!cov) {
        for (int c = 0; c < 4; ++c) ASSERT_EQ(normal.at(x, y, c), 0.f);  // background stays 0
        continue;
      }
      ++covered;
      for (const io::Image* img : {&view, &world, &object, &uv}) ASSERT_EQ(img->at(x, y, 3), 1.f);
      dvec3 p = *h;
      if (miss_distance(f.camera, x, y) > 0.97) continue;  // facets are coarsest at grazing angles
      EXPECT_LT(glm::length(px(world, x, y) - p), 3e-3);  // a 128 x 64 polygon, not the sphere
      EXPECT_EQ(px(object, x, y), px(world, x, y));  // identity model transform
      EXPECT_LT(glm::length(px(normal, x, y) - p), 3e-3);  // the unit sphere's normal is its position
      EXPECT_NEAR(glm::length(px(normal, x, y)), 1.0, 1e-6);
      // view = normalize(eye - world position), to float precision
      dvec3 v = glm::normalize(f.camera.eye() - px(world, x, y));
      EXPECT_LT(glm::length(px(view, x, y) - v), 1e-6);
      double u_expect = std::atan2(p.x, p.z) / (2 * shading::kPi);
      if (u_expect < 0) u_expect += 1;
      double v_expect = std::acos(std::clamp(p.y, -1.0, 1.0)) / shading::kPi;
      if (u_expect > 0.02 && u_expect < 0.98) {  // away from the seam
        EXPECT_NEAR(uv.at(x, y, 0), u_expect, 3e-3);
        EXPECT_NEAR(uv.at(x, y, 1), v_expect, 3e-3);
        EXPECT_EQ(uv.at(x, y, 2), 0.f);
        ++compared_uv;
      }
    }
  EXPECT_GT(covered, W * H / 8);
  EXPECT_GT(compared_uv, covered / 2);
  EXPECT_LT(mismatched, covered / 20);
}

TEST(GBuffer, RasterisesOnlyTheRequestedAttributesInOrder) {
  gl::current();
  Fixture f;
  auto g1 = scene::render_gbuffer({{&f.sphere}}, f.camera, W, H, {"normal"});
  EXPECT_EQ(g1.target->attachments(), 1);
  auto g2 = scene::render_gbuffer({{&f.sphere}}, f.camera, W, H, {"uv", "normal"});
  ASSERT_EQ(g2.target->attachments(), 2);
  EXPECT_EQ(g2.attachment("normal"), 1);
  io::Image a = g2.target->read(0), b = g1.target->read(0), n = g2.target->read(1);
  EXPECT_EQ(a.at(W / 2, H / 2, 2), 0.f);   // attachment 1 holds uv (z = 0)
  EXPECT_EQ(n.pixels, b.pixels);           // attachment 2 holds what {"normal"} alone gave
  EXPECT_THROW(g1.attachment("uv"), std::invalid_argument);
}

// The gather runs over the box that can hold covered pixels: the whole frame for the sphere
// that fills it, a box inside it for a small sphere off the centre.
TEST(GBuffer, GatherCompactsExactlyTheCoveredPixels) {
  gl::current();
  Fixture f;
  const glm::dmat4 small = glm::scale(glm::translate(glm::dmat4(1.0), {0.6, -0.4, 0.0}), dvec3(0.3));
  for (const glm::dmat4& model : {glm::dmat4(1.0), small}) {
    auto g = scene::render_gbuffer({{&f.sphere, model}}, f.camera, W, H, {"normal", "view"});
    if (model != glm::dmat4(1.0)) {
      ASSERT_TRUE(g.bounded);
      EXPECT_TRUE(g.covers.x0 > 0 && g.covers.y0 > 0 && g.covers.x1 < W && g.covers.y1 < H)
          << g.covers.x0 << " " << g.covers.y0 << " " << g.covers.x1 << " " << g.covers.y1;
    }
    io::Image n = g.target->read(0), v = g.target->read(1);
    std::size_t covered = 0;
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x) covered += n.at(x, y, 3) > 0.5f;
    ASSERT_GT(covered, 20u);
    auto s = scene::gather(g);
    ASSERT_EQ(s.count, covered);
    auto pixels = scene::download_pixels(s);
    auto sn_ = scene::download_vec4(*s.attributes[0], s.count), sv = scene::download_vec4(*s.attributes[1], s.count);
    std::set<uint32_t> seen;
    for (std::size_t i = 0; i < s.count; ++i) {
      ASSERT_TRUE(seen.insert(pixels[i]).second) << "pixel gathered twice";
      int x = int(pixels[i] % W), y = H - 1 - int(pixels[i] / W);  // GL rows run bottom-up
      for (int c = 0; c < 4; ++c) {
        ASSERT_EQ(sn_[i * 4 + c], n.at(x, y, c));
        ASSERT_EQ(sv[i * 4 + c], v.at(x, y, c));
      }
    }
  }
}

TEST(GBuffer, MissingAttributesAreClearErrors) {
  gl::current();
  Fixture f;
  const char* shared = std::getenv("SHADENET_SHARED");
  ASSERT_NE(shared, nullptr);
  scene::Mesh box = scene::load_mesh(std::string(shared) + "/meshes/Box.gltf");
  try {
    scene::render_gbuffer({{&box}}, f.camera, W, H, {"normal", "uv"});
    FAIL() << "uv on a mesh without texture coordinates must throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("attribute 'uv': mesh '"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("has no texture coordinates"), std::string::npos) << e.what();
  }
  EXPECT_THROW(scene::render_gbuffer({{&f.sphere}}, f.camera, W, H, {"base_color"}), std::invalid_argument);
  try {
    scene::render_gbuffer({{&f.sphere}}, f.camera, W, H, {"normals"});
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()),
              "unknown G-buffer attribute 'normals' (valid: normal, view, position, world_position, uv, base_color, tangent, bitangent)");
  }
  EXPECT_THROW(scene::render_gbuffer({{&f.sphere}}, f.camera, W, H, {"view", "view"}), std::invalid_argument);
}

TEST(TruthImage, EveryCoveredPixelMatchesTheTwin) {
  gl::current();
  Fixture f;
  auto g = scene::render_gbuffer({{&f.sphere}}, f.camera, W, H, {"normal", "view"});
  io::Image n = g.target->read(0), v = g.target->read(1);
  scene::Light light = scene::make_light({0.5, 0.7, 0.6}, {1, 0.9, 0.8});
  for (auto m : {"phong", "ggx", "toon3"}) {
    auto p = shading::default_params(m);
    io::Image img = shading::render_truth(g, p, light);
    int compared = 0;
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x) {
        if (n.at(x, y, 3) < 0.5f) {
          ASSERT_EQ(img.at(x, y, 3), 0.f);
          continue;
        }
        ASSERT_EQ(img.at(x, y, 3), 1.f);
        dvec3 nn(px(n, x, y)), vv(px(v, x, y));
        if (shading::near_discontinuity(p, light, nn, vv, 1e-4)) continue;
        dvec3 t = shading::shade(p, light, nn, vv);
        for (int c = 0; c < 3; ++c) ASSERT_NEAR(img.at(x, y, c), t[c], 1e-5) << p.describe();
        ++compared;
      }
    EXPECT_GT(compared, W * H / 8);
  }
  auto textured = shading::default_params("textured_phong");
  EXPECT_THROW(shading::render_truth(g, textured, light), std::invalid_argument);  // needs base_color
}

scene::Scene sphere_scene() {
  scene::Scene s;
  s.meshes.push_back({std::make_shared<scene::Mesh>(scene::sphere(1.0, 64, 32))});
  s.width = 64, s.height = 48;
  s.views = scene::framing_orbit(s.bounds(), 3, 20);
  s.light = scene::make_light({0.5, 0.7, 0.6}, {1, 1, 1});
  return s;
}

// Every (normal, view) row of `d` away from a discontinuity of r.target holds the double twin's
// colour in r.color within 1e-5; `checked` counts the rows compared.
void check_rows_against_twin(const data::Dataset& d, const data::DatasetRequest& r, const scene::Scene& s, int* checked) {
  for (int set = 0; set < 2; ++set) {
    const auto& x = set ? d.val_x : d.train_x;
    const auto& y = set ? d.val_y : d.train_y;
    for (std::size_t i = 0; i < x.size() / 6; ++i) {
      dvec3 n(x[i * 6], x[i * 6 + 1], x[i * 6 + 2]), v(x[i * 6 + 3], x[i * 6 + 4], x[i * 6 + 5]);
      EXPECT_NEAR(glm::length(n), 1.0, 1e-5);
      if (shading::near_discontinuity(r.target, s.light, n, v, 1e-4)) continue;
      dvec3 t = shading::encode_color(r.color, shading::shade(r.target, s.light, n, v));
      for (int c = 0; c < 3; ++c) {
        double e = std::abs(y[i * 3 + c] - t[c]);
        if (r.color == shading::ColorSpace::hsv && c == 0) e = std::min(e, 1 - e);  // hue wraps
        ASSERT_LE(e, 1e-5) << shading::color_space_name(r.color);
      }
      ++*checked;
    }
  }
}

TEST(Dataset, RowsAreTheTwinOfTheirInputsInTheRequestedColourSpace) {
  gl::current();
  auto s = sphere_scene();
  for (auto color : {shading::ColorSpace::rgb, shading::ColorSpace::hsv, shading::ColorSpace::cie_lab}) {
    data::DatasetRequest r;
    r.target = shading::default_params("ggx");
    r.color = color;
    r.samples = 0;
    auto d = data::build_dataset(s, r);
    ASSERT_EQ(d->inputs, 6);
    ASSERT_EQ(d->input_names, (std::vector<std::string>{"normal", "view"}));
    std::size_t total = d->train_count() + d->val_count();
    EXPECT_EQ(total, data::last_covered_pixels());
    EXPECT_NEAR(double(d->train_count()) / total, 0.8, 1.0 / total);
    int checked = 0;
    check_rows_against_twin(*d, r, s, &checked);
    EXPECT_GT(checked, int(total * 0.95));
  }
}

TEST(Dataset, SplitIsDeterministicPerSeedAndSamplesCapTheRows) {
  gl::current();
  auto s = sphere_scene();
  data::DatasetRequest r;
  r.target = shading::default_params("phong");
  r.inputs = {"position", "uv", "normal"};
  r.samples = 1000;
  r.seed = 5;
  auto a = data::build_dataset(s, r), b = data::build_dataset(s, r);
  EXPECT_EQ(a->inputs, 8);
  EXPECT_EQ(a->train_count(), 800u);
  EXPECT_EQ(a->val_count(), 200u);
  EXPECT_EQ(a->train_x, b->train_x);
  EXPECT_EQ(a->val_y, b->val_y);
  r.seed = 6;
  auto c = data::build_dataset(s, r);
  EXPECT_NE(a->train_x, c->train_x);
  EXPECT_EQ(c->train_count(), 800u);
}

// Only the sampled rows are shaded: each must still be the twin of its own inputs. A view listed
// twice puts its rows in twice.
TEST(Dataset, SampledRowsAreTheTwinOfTheirInputsAndARepeatedViewCountsTwice) {
  gl::current();
  auto s = sphere_scene();
  data::DatasetRequest r;
  r.target = shading::default_params("phong");
  r.samples = 0;
  auto covered = [&](std::vector<int> views) {
    r.views = std::move(views);
    data::build_dataset(s, r);
    return data::last_covered_pixels();
  };
  const std::size_t first = covered({0}), second = covered({1});
  ASSERT_GT(first, 100u);
  EXPECT_EQ(covered({1, 0, 1}), first + 2 * second);
  r.samples = 300;
  auto d = data::build_dataset(s, r);
  ASSERT_EQ(d->train_count() + d->val_count(), 300u);
  int checked = 0;
  check_rows_against_twin(*d, r, s, &checked);
  EXPECT_GT(checked, 280);
}

TEST(Dataset, ZeroCoveredPixelsIsAnErrorNotAnEmptyDataset) {
  gl::current();
  auto s = sphere_scene();
  s.views = {scene::Camera({0, 0, 5}, {0, 0, 10})};  // looking away from the sphere
  data::DatasetRequest r;
  r.target = shading::default_params("phong");
  try {
    data::build_dataset(s, r);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("no covered pixels"), std::string::npos) << e.what();
  }
}

TEST(Dataset, CacheKeyCoversMeshContent) {
  auto s = sphere_scene();
  data::DatasetRequest r;
  r.target = shading::default_params("phong");
  std::string k = data::dataset_key(s, r);
  auto edited = std::make_shared<scene::Mesh>(*s.meshes[0].mesh);
  edited->positions[10].x += 1e-6f;
  s.meshes[0].mesh = edited;
  EXPECT_NE(data::dataset_key(s, r), k);
}

}  // namespace

// The box a G-buffer promises to hold every covered pixel in: tight around a sphere seen from
// afar (the renderers read only it), the whole frame once the box reaches behind the eye.
TEST(GBuffer, CoveredPixelsLieInsideItsBox) {
  gl::current();
  scene::Mesh sphere = scene::sphere(1.0, 64, 32);
  auto inside = [](const scene::GBuffer& g, int* covered) {
    const io::Image cov = g.target->read(0);  // rows top first
    const scene::PixelBox b = g.box();
    *covered = 0;
    for (int y = 0; y < g.height; ++y)
      for (int x = 0; x < g.width; ++x) {
        if (!(cov.at(x, y, 3) > 0)) continue;
        ++*covered;
        const int gy = g.height - 1 - y;  // GL rows start at the bottom
        if (x < b.x0 || x >= b.x1 || gy < b.y0 || gy >= b.y1) return false;
      }
    return true;
  };
  int covered = 0;
  // Off centre, far: a small box around the disc.
  scene::Camera far{{3.0, 2.0, 9.0}, {1.5, 1.0, 0}};
  auto g = scene::render_gbuffer({{&sphere, glm::translate(glm::dmat4(1.0), glm::dvec3(0.8, 0.3, 0))}}, far, W, H,
                                 {"normal"});
  ASSERT_TRUE(g.bounded);
  EXPECT_TRUE(inside(g, &covered));
  EXPECT_GT(covered, 100);
  const scene::PixelBox b = g.box();
  EXPECT_LT(b.width() * b.height(), W * H / 3) << b.x0 << "," << b.y0 << " .. " << b.x1 << "," << b.y1;
  // Near enough that the disc fills most of the frame: the box is the frame, clamped.
  scene::Camera near{{0, 0, 1.6}, {0, 0, 0}};
  g = scene::render_gbuffer({{&sphere}}, near, W, H, {"normal"});
  EXPECT_TRUE(inside(g, &covered));
  // Inside the sphere: its box reaches behind the eye, so nothing is promised.
  scene::Camera in{{0, 0, 0.2}, {0, 0, -1}};
  g = scene::render_gbuffer({{&sphere}}, in, W, H, {"normal"});
  EXPECT_FALSE(g.bounded);
  EXPECT_EQ(g.box().width(), W);
  EXPECT_TRUE(inside(g, &covered));
  EXPECT_GT(covered, W * H / 2);
  // In front of the eye but beside the frame: an empty box, and nothing covered.
  scene::Camera away{{0, 0, 10}, {0, 0, 0}};
  g = scene::render_gbuffer({{&sphere, glm::translate(glm::dmat4(1.0), glm::dvec3(20, 0, 0))}}, away, W, H, {"normal"});
  EXPECT_TRUE(g.bounded);
  EXPECT_TRUE(inside(g, &covered));
  EXPECT_EQ(covered, 0);
  EXPECT_EQ(g.box().width() * g.box().height(), 0);
}
