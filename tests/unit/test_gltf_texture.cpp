// glTF texture coordinates and samplers: which TEXCOORD set a primitive's vertices take, what a
// primitive without one gets, and the sampler's wrap modes on the GPU against the CPU twin.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "gltf_fixture.h"
#include "io/image.h"
#include "io/temp_dir.h"
#include "scene/gltf.h"
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
