// glTF texture coordinates and samplers: which TEXCOORD set a primitive's vertices take, what a
// primitive without one gets, and the sampler's wrap modes on the GPU against the CPU twin.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "gl/context.h"
#include "gl/program.h"
#include "gl/render_target.h"
#include "gltf_fixture.h"
#include "io/image.h"
#include "io/temp_dir.h"
#include "scene/camera.h"
#include "scene/gltf.h"
#include "scene/gpu_mesh.h"
#include "scene/mesh.h"

using namespace sn::scene;
using namespace gltf_fixture;

namespace {

std::filesystem::path temp_dir() {
  static const sn::io::TempDir dir("test_gltf_texture");  // removed at exit
  return dir.path();
}

// The first note holding `text`, or "" when none does.
std::string note_with(const Mesh& m, const std::string& text) {
  for (const std::string& n : m.notes)
    if (n.find(text) != std::string::npos) return n;
  return "";
}

// Adds `img` as an embedded PNG, a texture of it (with `sampler`, -1: the default) and a material
// whose base-colour texture it is, read from TEXCOORD_`set`; returns the material's index.
int textured_material(Fixture& f, const sn::io::Image& img, int sampler = -1, int set = 0) {
  std::vector<unsigned char> png = sn::io::encode_image(img, "texture.png");
  tinygltf::Image image;
  image.mimeType = "image/png";
  image.bufferView = f.view(png);
  f.model.images.push_back(image);
  tinygltf::Texture tex;
  tex.source = int(f.model.images.size()) - 1;
  tex.sampler = sampler;
  f.model.textures.push_back(tex);
  tinygltf::Material mat;
  mat.pbrMetallicRoughness.baseColorTexture.index = int(f.model.textures.size()) - 1;
  mat.pbrMetallicRoughness.baseColorTexture.texCoord = set;
  f.model.materials.push_back(mat);
  return int(f.model.materials.size()) - 1;
}

const std::vector<float> kTriangle = {0, 0, 0, 1, 0, 0, 0, 1, 0};

}  // namespace

TEST(GltfTexture, APrimitiveWithoutTexcoordsGetsZeroAndTheOthersKeepTheirs) {
  // A textured body and an untextured part: the body's uvs used to be zeroed as well.
  Fixture f;
  tinygltf::Mesh mesh;
  tinygltf::Primitive body = primitive(TINYGLTF_MODE_TRIANGLES, f.vec3s(kTriangle));
  body.attributes["TEXCOORD_0"] = f.vec2s({0.25f, 0.5f, 0.75f, 0.5f, 0.5f, 1.0f});
  mesh.primitives = {body, primitive(TINYGLTF_MODE_TRIANGLES, f.vec3s(kTriangle))};
  f.model.meshes.push_back(mesh);
  f.place(0);
  Mesh m = load_mesh(f.write(temp_dir() / "partial_uvs.gltf"));
  ASSERT_EQ(m.vertex_count(), 6u);
  EXPECT_TRUE(m.has_uvs);
  EXPECT_EQ(m.uvs[0], glm::vec2(0.25f, 0.5f));
  EXPECT_EQ(m.uvs[2], glm::vec2(0.5f, 1.0f));
  for (int i = 3; i < 6; ++i) EXPECT_EQ(m.uvs[i], glm::vec2(0.0f)) << i;
  EXPECT_NE(note_with(m, "has 1 of 2 primitives without texture coordinates (mesh 0 primitive 1 (TEXCOORD_0)): "
                         "their uvs are (0, 0)"),
            "");
  // None with texture coordinates: the mesh has none, and says nothing about it.
  Fixture g;
  tinygltf::Mesh bare;
  bare.primitives = {primitive(TINYGLTF_MODE_TRIANGLES, g.vec3s(kTriangle))};
  g.model.meshes.push_back(bare);
  g.place(0);
  Mesh b = load_mesh(g.write(temp_dir() / "no_uvs.gltf"));
  EXPECT_FALSE(b.has_uvs);
  EXPECT_EQ(note_with(b, "texture coordinates"), "");
}

TEST(GltfTexture, TheBaseColorTexturesTexCoordPicksTheSet) {
  // Material 0's base-colour texture reads TEXCOORD_1 (texCoord = 1); TEXCOORD_0 used to be read.
  Fixture f;
  textured_material(f, sn::io::Image(2, 2, 3, 0.5f), -1, 1);
  tinygltf::Mesh mesh;
  tinygltf::Primitive both = primitive(TINYGLTF_MODE_TRIANGLES, f.vec3s(kTriangle));
  both.attributes["TEXCOORD_0"] = f.vec2s({9, 9, 9, 9, 9, 9});
  both.attributes["TEXCOORD_1"] = f.vec2s({0.25f, 0.5f, 0.75f, 0.5f, 0.5f, 1.0f});
  both.material = 0;
  // The same material on a primitive that lacks the set: (0, 0) and a note naming the set.
  tinygltf::Primitive only0 = primitive(TINYGLTF_MODE_TRIANGLES, f.vec3s(kTriangle));
  only0.attributes["TEXCOORD_0"] = f.vec2s({9, 9, 9, 9, 9, 9});
  only0.material = 0;
  // Without a textured material, TEXCOORD_0 as before.
  tinygltf::Primitive plain = primitive(TINYGLTF_MODE_TRIANGLES, f.vec3s(kTriangle));
  plain.attributes["TEXCOORD_0"] = f.vec2s({0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f});
  mesh.primitives = {both, only0, plain};
  f.model.meshes.push_back(mesh);
  f.place(0);
  Mesh m = load_mesh(f.write(temp_dir() / "texcoord1.gltf"));
  ASSERT_EQ(m.vertex_count(), 9u);
  EXPECT_TRUE(m.has_uvs);
  EXPECT_EQ(m.uvs[0], glm::vec2(0.25f, 0.5f));
  EXPECT_EQ(m.uvs[1], glm::vec2(0.75f, 0.5f));
  for (int i = 3; i < 6; ++i) EXPECT_EQ(m.uvs[i], glm::vec2(0.0f)) << i;
  EXPECT_EQ(m.uvs[6], glm::vec2(0.5f));
  EXPECT_NE(note_with(m, "(mesh 0 primitive 1 (TEXCOORD_1))"), "") << (m.notes.empty() ? "" : m.notes[0]);
}

// A textured primitive without the set its texture reads shows the texture as one flat colour:
// the note that says so used to come only when another primitive had texture coordinates.
TEST(GltfTexture, ATexturedPrimitiveWithoutItsSetIsANoteEvenWhenNoneHasOne) {
  for (int set : {0, 1}) {
    Fixture f;
    textured_material(f, sn::io::Image(2, 2, 3, 0.5f), -1, set);
    tinygltf::Primitive p = primitive(TINYGLTF_MODE_TRIANGLES, f.vec3s(kTriangle));
    if (set == 1) p.attributes["TEXCOORD_0"] = f.vec2s({9, 9, 9, 9, 9, 9});  // not the set it reads
    p.material = 0;
    tinygltf::Mesh mesh;
    mesh.primitives = {p};
    f.model.meshes.push_back(mesh);
    f.place(0);
    Mesh m = load_mesh(f.write(temp_dir() / "textured_without_uvs.gltf"));
    EXPECT_FALSE(m.has_uvs) << set;
    EXPECT_TRUE(m.base_color) << set;
    for (const glm::vec2& uv : m.uvs) EXPECT_EQ(uv, glm::vec2(0.0f)) << set;
    const std::string name = "TEXCOORD_" + std::to_string(set);
    EXPECT_EQ(m.uv_sets, name);
    EXPECT_EQ(note_with(m, "texture coordinates"),
              "has 1 of 1 primitives without texture coordinates (mesh 0 primitive 0 (" + name +
                  ")): their uvs are (0, 0), where a texture shows one flat colour (the average of its four corner "
                  "texels under repeat wrapping and linear filtering, else its top-left texel); give them texture "
                  "coordinates in the file");
  }
}

// Numbers glTF does not define fall back to repeat, linear and trilinear with a note naming them;
// undefined filters (-1) fall back without one.
TEST(GltfTexture, UndefinedSamplerNumbersFallBackWithANote) {
  Fixture f;
  tinygltf::Sampler s;
  s.wrapS = 12345, s.wrapT = TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE, s.minFilter = 5;  // magFilter: -1
  f.model.samplers.push_back(s);
  tinygltf::Primitive p = primitive(TINYGLTF_MODE_TRIANGLES, f.vec3s(kTriangle));
  p.attributes["TEXCOORD_0"] = f.vec2s({0, 0, 1, 0, 0, 1});
  sn::io::Image img(2, 2, 3, 0.5f);
  p.material = textured_material(f, img, 0);
  tinygltf::Mesh mesh;
  mesh.primitives = {p};
  f.model.meshes.push_back(mesh);
  f.place(0);
  Mesh m = load_mesh(f.write(temp_dir() / "undefined_sampler.gltf"));
  EXPECT_TRUE(m.base_color.sampler == (Sampler{Wrap::repeat, Wrap::clamp_to_edge}));
  EXPECT_NE(note_with(m, "with wrapS 12345, which glTF does not define (10497 repeat, 33071 clamp to edge, 33648 "
                         "mirrored repeat): the texture repeats there"), "");
  EXPECT_NE(note_with(m, "with minFilter 5, which glTF does not define (9728, 9729, 9984-9987): trilinear there"), "");
  EXPECT_EQ(note_with(m, "magFilter"), "");
}

TEST(GltfTexture, WrapTexelFollowsOpenGl) {
  // A 4-texel axis, indices -5..8.
  std::vector<int> repeat, clamp, mirror;
  for (int i = -5; i <= 8; ++i)
    repeat.push_back(wrap_texel(Wrap::repeat, i, 4)), clamp.push_back(wrap_texel(Wrap::clamp_to_edge, i, 4)),
        mirror.push_back(wrap_texel(Wrap::mirrored_repeat, i, 4));
  EXPECT_EQ(repeat, (std::vector<int>{3, 0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3, 0}));
  EXPECT_EQ(clamp, (std::vector<int>{0, 0, 0, 0, 0, 0, 1, 2, 3, 3, 3, 3, 3, 3}));
  EXPECT_EQ(mirror, (std::vector<int>{3, 3, 2, 1, 0, 0, 1, 2, 3, 3, 2, 1, 0, 0}));
}

// A quad whose uvs run from -1 to 2, under each sampler: the colour drawn at each pixel is the CPU
// twin's lookup (sample_lod0) at the uv drawn there, with the file's wrap modes and magnification
// filter. With repeat and linear hard-coded (as they were) every other case is far off.
TEST(GltfTexture, TheSamplersWrapModesAndFiltersReachTheGpuAndTheCpuTwin) {
  sn::gl::current();
  sn::io::Image img(4, 4, 3);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) img.at(x, y, 0) = x / 3.f, img.at(x, y, 1) = y / 3.f, img.at(x, y, 2) = (x + y) % 2;
  const Sampler samplers[] = {
      {Wrap::repeat, Wrap::repeat},
      {Wrap::clamp_to_edge, Wrap::clamp_to_edge},
      {Wrap::mirrored_repeat, Wrap::mirrored_repeat, MagFilter::linear, MinFilter::nearest},
      {Wrap::clamp_to_edge, Wrap::mirrored_repeat},
      {Wrap::repeat, Wrap::repeat, MagFilter::nearest, MinFilter::linear_mipmap_nearest},
      {Wrap::clamp_to_edge, Wrap::repeat, MagFilter::nearest, MinFilter::nearest}};
  const int gl_wrap[] = {TINYGLTF_TEXTURE_WRAP_REPEAT, TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE,
                         TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT};
  const int gl_min[] = {TINYGLTF_TEXTURE_FILTER_NEAREST,
                        TINYGLTF_TEXTURE_FILTER_LINEAR,
                        TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST,
                        TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_NEAREST,
                        TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR,
                        TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR};
  Camera cam(glm::dvec3(0, 0, 2.5), glm::dvec3(0));
  sn::gl::RenderTarget target(128, 128);
  for (const Sampler& want : samplers) {
    Fixture f;
    tinygltf::Sampler s;
    s.wrapS = gl_wrap[int(want.s)], s.wrapT = gl_wrap[int(want.t)];
    s.magFilter = want.mag == MagFilter::nearest ? TINYGLTF_TEXTURE_FILTER_NEAREST : TINYGLTF_TEXTURE_FILTER_LINEAR;
    s.minFilter = gl_min[int(want.min)];
    for (int i = 0; i < 6; ++i) EXPECT_EQ(gl_value(MinFilter(i)), gl_min[i]);
    f.model.samplers.push_back(s);
    tinygltf::Primitive quad = primitive(TINYGLTF_MODE_TRIANGLES, f.vec3s({-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0}),
                                         f.vec3s({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}),
                                         f.accessor(f.view(std::vector<uint16_t>{0, 1, 2, 0, 2, 3}),
                                                    TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_SCALAR, 6));
    quad.attributes["TEXCOORD_0"] = f.vec2s({-1, 2, 2, 2, 2, -1, -1, -1});
    quad.material = textured_material(f, img, 0);
    tinygltf::Mesh mesh;
    mesh.primitives = {quad};
    f.model.meshes.push_back(mesh);
    f.place(0);
    const std::string name = "sampler_" + std::to_string(int(want.s)) + std::to_string(int(want.t)) +
                             std::to_string(int(want.mag)) + std::to_string(int(want.min));
    Mesh m = load_mesh(f.write(temp_dir() / (name + ".gltf")));
    ASSERT_TRUE(m.base_color.sampler == want) << name;
    // A .glb the mesh is saved as keeps its sampler.
    save_glb(m, (temp_dir() / (name + ".glb")).string());
    EXPECT_TRUE(load_mesh((temp_dir() / (name + ".glb")).string()).base_color.sampler == want) << name;

    auto render = [&](const char* frag) {
      auto p = sn::gl::get_program({"", "mesh.vert", std::string("tests/data/") + frag, {}});
      target.bind();
      target.clear();
      set_standard_uniforms(*p, cam, 1.0, glm::dmat4(1.0), upload(m));
      draw(*p, upload(m), glm::dmat4(1.0));
      return target.read();
    };
    sn::io::Image uv = render("uv.frag"), color = render("base_color.frag");
    int covered = 0;
    double max_err = 0, repeat_err = 0;
    for (int y = 0; y < uv.height; ++y)
      for (int x = 0; x < uv.width; ++x) {
        if (uv.at(x, y, 3) < 0.5) continue;
        ++covered;
        for (int c = 0; c < 3; ++c) {
          double u = uv.at(x, y, 0), v = uv.at(x, y, 1);
          max_err = std::max(max_err, std::abs(color.at(x, y, c) - sample_lod0(*m.base_color, want, u, v, c)));
          repeat_err += std::abs(color.at(x, y, c) - sample_lod0(*m.base_color, Sampler(), u, v, c));
        }
      }
    ASSERT_GT(covered, 4000) << name;
    // GPUs blend with 8-bit weights (llvmpipe: under 1/255 on the duck).
    EXPECT_LT(max_err, 4.0 / 255) << name;
    // The test can tell the modes apart: repeat's lookup is far off for the others.
    if (!(want == Sampler())) EXPECT_GT(repeat_err / (3 * covered), 0.05) << name;
  }
}
