// glTF vertex deformations drawn at load: morph targets at their default weights, skins in the
// pose their joint nodes hold (scene/gltf_deform.h).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "gltf_fixture.h"
#include "io/temp_dir.h"
#include "scene/gltf.h"
#include "scene/mesh.h"

using namespace sn::scene;
using namespace gltf_fixture;

namespace {

std::filesystem::path temp_dir() {
  static const sn::io::TempDir dir("test_gltf_deform");  // removed at exit
  return dir.path();
}

void expect_near(glm::dvec3 a, glm::dvec3 b, double tol, const std::string& what) {
  EXPECT_NEAR(a.x, b.x, tol) << what;
  EXPECT_NEAR(a.y, b.y, tol) << what;
  EXPECT_NEAR(a.z, b.z, tol) << what;
}

}  // namespace

TEST(GltfDeform, MorphTargetsAddAtTheirDefaultWeightsAndANodesWeightsOverrideTheMeshs) {
  // Target 0 lifts every vertex by 2 in z and tips the normals towards +y; target 1 moves vertex
  // 1 by 1 in x. The mesh weighs them 0.5 and 0.25; a second node placing it (moved by 10 in x)
  // weighs them 0 and 1. The targets were ignored: the rest shape was the base.
  Fixture f;
  tinygltf::Primitive p = primitive(TINYGLTF_MODE_TRIANGLES, f.vec3s({0, 0, 0, 1, 0, 0, 0, 1, 0}),
                                    f.vec3s({0, 0, 1, 0, 0, 1, 0, 0, 1}));
  p.targets.push_back({{"POSITION", f.vec3s({0, 0, 2, 0, 0, 2, 0, 0, 2})}, {"NORMAL", f.vec3s({0, 2, 0, 0, 2, 0, 0, 2, 0})}});
  p.targets.push_back({{"POSITION", f.vec3s({0, 0, 0, 1, 0, 0, 0, 0, 0})}});
  tinygltf::Mesh mesh;
  mesh.primitives = {p};
  mesh.weights = {0.5, 0.25};
  f.model.meshes.push_back(mesh);
  f.place(0);
  f.model.nodes[size_t(f.place(0))].translation = {10, 0, 0};
  f.model.nodes.back().weights = {0, 1};
  Mesh m = load_mesh(f.write(temp_dir() / "morph.gltf"));
  ASSERT_EQ(m.vertex_count(), 6u);
  expect_near(m.positions[0], {0, 0, 1}, 1e-7, "mesh weights, vertex 0");
  expect_near(m.positions[1], {1.25, 0, 1}, 1e-7, "mesh weights, vertex 1");
  expect_near(m.normals[0], glm::normalize(glm::dvec3(0, 1, 1)), 1e-6, "mesh weights, normal");
  expect_near(m.positions[3], {10, 0, 0}, 1e-7, "node weights, vertex 0");
  expect_near(m.positions[4], {12, 0, 0}, 1e-7, "node weights, vertex 1");
  expect_near(m.normals[3], {0, 0, 1}, 1e-6, "node weights, normal");
}

TEST(GltfDeform, ASparseMorphTargetMovesOnlyTheVerticesItNames) {
  // Target 0 has no buffer view (zeros) and one sparse value: vertex 2 moves by (0, 0, 4); weight 0.5.
  std::vector<unsigned char> bytes = float_bytes({0, 0, 0, 1, 0, 0, 0, 1, 0});
  bytes.insert(bytes.end(), {2, 0, 0, 0});
  auto v = float_bytes({0, 0, 4});
  bytes.insert(bytes.end(), v.begin(), v.end());
  std::string path = raw_fixture(
      temp_dir() / "sparse_morph.gltf", bytes,
      R"([{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 1},
          {"buffer": 0, "byteOffset": 40, "byteLength": 12}])",
      R"([{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
          {"componentType": 5126, "count": 3, "type": "VEC3",
           "sparse": {"count": 1, "indices": {"bufferView": 1, "componentType": 5121}, "values": {"bufferView": 2}}}])",
      R"({"attributes": {"POSITION": 0}, "targets": [{"POSITION": 1}]})", R"([{"mesh": 0, "weights": [0.5]}])");
  Mesh m = load_mesh(path);
  expect_near(m.positions[0], {0, 0, 0}, 0, "untouched");
  expect_near(m.positions[1], {1, 0, 0}, 0, "untouched");
  expect_near(m.positions[2], {0, 1, 2}, 1e-7, "the sparse vertex");
}
