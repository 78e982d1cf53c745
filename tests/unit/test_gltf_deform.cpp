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

}  // namespace

TEST(GltfDeform, MorphTargetsAddAtTheirDefaultWeightsAndANodesWeightsOverrideTheMeshs) {
  // Target 0 lifts every vertex by 2 in z and tips the normals towards +y; target 1 moves vertex
  // 1 by 1 in x. The mesh weighs them 0.5 and 0.25; a second node placing it (moved by 10 in x)
  // weighs them 0 and 1. The targets were ignored: the rest shape was the base. Target 0 also turns
  // the tangents (1, 0, 0) by (0, 2, -2), across the tipped normal; their handedness -1 stays (a
  // target's TANGENT was ignored).
  Fixture f;
  tinygltf::Primitive p = primitive(TINYGLTF_MODE_TRIANGLES, f.vec3s({0, 0, 0, 1, 0, 0, 0, 1, 0}),
                                    f.vec3s({0, 0, 1, 0, 0, 1, 0, 0, 1}));
  p.attributes["TANGENT"] = f.accessor(f.view(std::vector<float>{1, 0, 0, -1, 1, 0, 0, -1, 1, 0, 0, -1}),
                                       TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC4, 3);
  p.targets.push_back({{"POSITION", f.vec3s({0, 0, 2, 0, 0, 2, 0, 0, 2})},
                       {"NORMAL", f.vec3s({0, 2, 0, 0, 2, 0, 0, 2, 0})},
                       {"TANGENT", f.vec3s({0, 2, -2, 0, 2, -2, 0, 2, -2})}});
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
  ASSERT_EQ(m.tangents.size(), 6u);
  expect_near(glm::dvec3(m.tangents[0]), glm::normalize(glm::dvec3(1, 1, -1)), 1e-6, "mesh weights, tangent");
  expect_near(glm::dvec3(m.tangents[3]), {1, 0, 0}, 1e-6, "node weights, tangent");
  EXPECT_EQ(m.tangents[0].w, -1.0f);
  EXPECT_EQ(m.tangents[3].w, -1.0f);
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

TEST(GltfDeform, ASkinnedMeshIsPlacedByItsJointsAloneNotItsNode) {
  // Node 0 holds the skinned triangle and a translation of 100 the specification says to ignore
  // (glTF 3.7.3); it was applied, and the joints were not. Joint 0 is node 1 (translated (0, 5, 0),
  // its inverse bind matrix undoing that: it leaves vertices in place); joint 1 is node 2, node
  // 1's child, translated (2, 0, 0) and turned 90 degrees about x, with the identity as inverse
  // bind matrix. Vertex 0 follows joint 0, vertex 1 joint 1, vertex 2 both, half each.
  Fixture f;
  tinygltf::Primitive p = primitive(TINYGLTF_MODE_TRIANGLES, f.vec3s({0, 0, 0, 1, 0, 0, 0, 1, 0}),
                                    f.vec3s({0, 0, 1, 0, 0, 1, 0, 0, 1}));
  p.attributes["JOINTS_0"] = f.accessor(f.view(std::vector<uint8_t>{0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0}),
                                        TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_TYPE_VEC4, 3);
  p.attributes["WEIGHTS_0"] = f.accessor(f.view(std::vector<float>{1, 0, 0, 0, 1, 0, 0, 0, 0.5f, 0.5f, 0, 0}),
                                         TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC4, 3);
  tinygltf::Mesh mesh;
  mesh.primitives = {p};
  f.model.meshes.push_back(mesh);
  const glm::dmat4 ibm0 = glm::translate(glm::dmat4(1.0), glm::dvec3(0, -5, 0));
  std::vector<float> ibms;
  for (const glm::dmat4& m : {ibm0, glm::dmat4(1.0)})
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) ibms.push_back(float(m[c][r]));
  tinygltf::Skin skin;
  skin.inverseBindMatrices = f.accessor(f.view(ibms), TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_MAT4, 2);
  skin.joints = {1, 2};
  f.model.skins.push_back(skin);
  tinygltf::Node skinned, root, arm;
  skinned.mesh = 0;
  skinned.skin = 0;
  skinned.translation = {100, 0, 0};
  root.translation = {0, 5, 0};
  root.children = {2};
  arm.translation = {2, 0, 0};
  const double h = std::sqrt(0.5);
  arm.rotation = {h, 0, 0, h};  // 90 degrees about x: y -> z, z -> -y
  f.model.nodes = {skinned, root, arm};
  f.model.scenes.resize(1);
  f.model.scenes[0].nodes = {0, 1};
  f.model.defaultScene = 0;
  Mesh m = load_mesh(f.write(temp_dir() / "skin.gltf"));
  ASSERT_EQ(m.vertex_count(), 3u);
  expect_near(m.positions[0], {0, 0, 0}, 1e-6, "joint 0");
  expect_near(m.positions[1], {3, 5, 0}, 1e-6, "joint 1");
  expect_near(m.normals[1], {0, -1, 0}, 1e-6, "joint 1's normal");
  expect_near(m.positions[2], {1, 3, 0.5}, 1e-6, "half each");
  // The blend's normal: the inverse transpose of the blended matrix's linear part.
  const glm::dmat4 joint1 = glm::translate(glm::dmat4(1.0), glm::dvec3(2, 5, 0)) *
                            glm::rotate(glm::dmat4(1.0), std::acos(-1.0) / 2, glm::dvec3(1, 0, 0));
  const glm::dmat3 blend = glm::dmat3(0.5 * glm::dmat4(1.0) + 0.5 * joint1);
  expect_near(m.normals[2], glm::normalize(glm::transpose(glm::inverse(blend)) * glm::dvec3(0, 0, 1)), 1e-6,
              "half each, normal");
  EXPECT_TRUE(m.notes.empty()) << m.notes[0];

  // A skinned primitive without JOINTS_0 is a broken file, named as such.
  f.model.meshes[0].primitives[0].attributes.erase("JOINTS_0");
  std::string e;
  try {
    load_mesh(f.write(temp_dir() / "skin_without_joints.gltf"));
  } catch (const std::exception& x) {
    e = x.what();
  }
  EXPECT_NE(e.find("mesh 0 primitive 0 is skinned (its node has skin 0) but lacks JOINTS_0"), std::string::npos) << e;
}
