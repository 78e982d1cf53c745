// glTF accessors' component types: what each attribute may be stored as (glTF 2.0 and
// KHR_mesh_quantization), numbers glTF does not define, and normalised indices.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "gltf_fixture.h"
#include "io/temp_dir.h"
#include "message_of.h"
#include "scene/gltf.h"
#include "scene/mesh.h"

using namespace sn::scene;
using namespace gltf_fixture;

namespace {

std::filesystem::path temp_dir() {
  static const sn::io::TempDir dir("test_gltf_accessor");  // removed at exit
  return dir.path();
}

template <class T>
void append(std::vector<unsigned char>& bytes, const std::vector<T>& values) {
  while (bytes.size() % 4) bytes.push_back(0);
  const auto* p = reinterpret_cast<const unsigned char*>(values.data());
  bytes.insert(bytes.end(), p, p + values.size() * sizeof(T));
}

// One triangle: float positions (view 0, accessor 0), then `extra` (its bytes as view 1, its
// accessor 1 given as JSON without "bufferView") under attribute `attribute` ("indices": the
// index list).
std::string with_accessor(const std::string& name, const std::vector<unsigned char>& extra, const std::string& attribute,
                          const std::string& accessor, const std::string& stride = "") {
  std::vector<unsigned char> bytes = float_bytes({0, 0, 0, 1, 0, 0, 0, 1, 0});
  const std::size_t offset = bytes.size();
  bytes.insert(bytes.end(), extra.begin(), extra.end());
  const std::string views = R"([{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": )" +
                            std::to_string(offset) + R"(, "byteLength": )" + std::to_string(extra.size()) +
                            (stride.empty() ? "" : R"(, "byteStride": )" + stride) + "}]";
  const std::string accessors = R"([{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                                    {"bufferView": 1, )" + accessor + "}]";
  const std::string primitive = attribute == "indices"
                                    ? R"({"attributes": {"POSITION": 0}, "indices": 1})"
                                    : R"({"attributes": {"POSITION": 0, ")" + attribute + R"(": 1}})";
  return raw_fixture(temp_dir() / name, bytes, views, accessors, primitive);
}

}  // namespace

TEST(GltfAccessor, AttributesStoredAsTypesGltfDoesNotAllowAreRefusedByName) {
  // POSITION as unsigned int: read as integers, a mesh 1e9 wide (glTF: float, or with
  // KHR_mesh_quantization 8- and 16-bit integers).
  std::vector<unsigned char> bytes;
  append(bytes, std::vector<uint32_t>{0, 0, 0, 1000000000, 0, 0, 0, 3000000000u, 0});
  std::string p = raw_fixture(temp_dir() / "pos_uint.gltf", bytes,
                              R"([{"buffer": 0, "byteOffset": 0, "byteLength": 36}])",
                              R"([{"bufferView": 0, "componentType": 5125, "count": 3, "type": "VEC3"}])",
                              R"({"attributes": {"POSITION": 0}})");
  std::string e = message_of([&] { load_mesh(p); });
  EXPECT_NE(e.find("pos_uint.gltf': mesh 0 primitive 0 POSITION (accessor 0) is stored as 5125 unsigned int, which "
                   "glTF does not allow there (allowed: float; with KHR_mesh_quantization also byte, byte normalized, "
                   "unsigned byte, unsigned byte normalized, short, short normalized, unsigned short, unsigned short "
                   "normalized)"),
            std::string::npos)
      << e;

  // NORMAL as unsigned byte normalised: [0, 1] cannot point backwards, every normal came out turned.
  bytes.clear();
  append(bytes, std::vector<uint8_t>{128, 128, 255, 0, 128, 128, 255, 0, 128, 128, 255, 0});
  p = with_accessor("normal_u8.gltf", bytes, "NORMAL",
                    R"("componentType": 5121, "normalized": true, "count": 3, "type": "VEC3")", "4");
  e = message_of([&] { load_mesh(p); });
  EXPECT_NE(e.find("mesh 0 primitive 0 NORMAL (accessor 1) is stored as 5121 unsigned byte normalized, which glTF "
                   "does not allow there (allowed: float; with KHR_mesh_quantization also byte normalized, short "
                   "normalized)"),
            std::string::npos)
      << e;

  // TANGENT likewise; TEXCOORD_0 as unsigned int.
  p = with_accessor("tangent_u8.gltf", bytes, "TANGENT",
                    R"("componentType": 5121, "normalized": true, "count": 3, "type": "VEC4")");
  e = message_of([&] { load_mesh(p); });
  EXPECT_NE(e.find("TANGENT (accessor 1) is stored as 5121 unsigned byte normalized"), std::string::npos) << e;
  bytes.clear();
  append(bytes, std::vector<uint32_t>{0, 0, 1, 0, 0, 1});
  p = with_accessor("uv_uint.gltf", bytes, "TEXCOORD_0", R"("componentType": 5125, "count": 3, "type": "VEC2")");
  e = message_of([&] { load_mesh(p); });
  EXPECT_NE(e.find("TEXCOORD_0 (accessor 1) is stored as 5125 unsigned int, which glTF does not allow there (allowed: "
                   "float, unsigned byte normalized, unsigned short normalized; with KHR_mesh_quantization also byte, "
                   "byte normalized, unsigned byte, short, short normalized, unsigned short)"),
            std::string::npos)
      << e;

  // A morph target's POSITION displacements as unsigned bytes: they move one way only.
  bytes = float_bytes({0, 0, 0, 1, 0, 0, 0, 1, 0});
  bytes.insert(bytes.end(), {1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0});
  p = raw_fixture(temp_dir() / "morph_u8.gltf", bytes,
                  R"([{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                      {"buffer": 0, "byteOffset": 36, "byteLength": 12, "byteStride": 4}])",
                  R"([{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                      {"bufferView": 1, "componentType": 5121, "count": 3, "type": "VEC3"}])",
                  R"({"attributes": {"POSITION": 0}, "targets": [{"POSITION": 1}]})", R"([{"mesh": 0, "weights": [1]}])");
  e = message_of([&] { load_mesh(p); });
  EXPECT_NE(e.find("mesh 0 primitive 0 morph target 0 POSITION (accessor 1) is stored as 5121 unsigned byte, which "
                   "glTF does not allow there (allowed: float; with KHR_mesh_quantization also byte, byte normalized, "
                   "short, short normalized)"),
            std::string::npos)
      << e;
}

TEST(GltfAccessor, QuantizedAttributesLoadWithOrWithoutTheExtensionDeclared) {
  // POSITION as short (integers, placed by the node's scale as quantizers write them), NORMAL as
  // byte normalised, TEXCOORD_0 as unsigned short normalised (core glTF).
  std::vector<unsigned char> bytes;
  append(bytes, std::vector<int16_t>{0, 0, 0, 0, 100, 0, 0, 0, 0, 100, 0, 0});  // stride 8
  append(bytes, std::vector<int8_t>{0, 0, 127, 0, 0, 0, 127, 0, 0, 0, 127, 0});  // stride 4
  append(bytes, std::vector<uint16_t>{0, 0, 65535, 0, 0, 65535});
  const std::string views = R"([{"buffer": 0, "byteOffset": 0, "byteLength": 24, "byteStride": 8},
                                {"buffer": 0, "byteOffset": 24, "byteLength": 12, "byteStride": 4},
                                {"buffer": 0, "byteOffset": 36, "byteLength": 12}])";
  const std::string accessors = R"([{"bufferView": 0, "componentType": 5122, "count": 3, "type": "VEC3"},
      {"bufferView": 1, "componentType": 5120, "normalized": true, "count": 3, "type": "VEC3"},
      {"bufferView": 2, "componentType": 5123, "normalized": true, "count": 3, "type": "VEC2"}])";
  const std::string prim = R"({"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}})";
  // The declaration follows the accessors, which raw_fixture writes last in the top-level object.
  const std::string extension = R"(, "extensionsUsed": ["KHR_mesh_quantization"],
                                    "extensionsRequired": ["KHR_mesh_quantization"])";
  for (const std::string& declared : {std::string(), extension}) {
    std::string p = raw_fixture(temp_dir() / "quantized.gltf", bytes, views, accessors + declared, prim,
                                R"([{"mesh": 0, "scale": [0.01, 0.01, 0.01]}])");
    Mesh m = load_mesh(p);
    ASSERT_EQ(m.vertex_count(), 3u) << declared;
    expect_near(m.positions[1], {1, 0, 0}, 1e-6, "position" + declared);
    expect_near(m.normals[0], {0, 0, 1}, 1e-6, "normal" + declared);
    EXPECT_EQ(m.uvs[1], glm::vec2(1, 0)) << declared;
    EXPECT_FALSE(m.normals_computed) << declared;
  }
}

TEST(GltfAccessor, AComponentTypeGltfDoesNotDefineIsNamedWithTheValidOnes) {
  // 5130 (GL_DOUBLE): tinygltf gives it 8 bytes, and its values came out NaN: "not a finite
  // number" for POSITION, a silent "repair" for NORMAL.
  std::vector<unsigned char> bytes(72, 0);
  const std::string valid =
      " has unknown component type 5130 (valid: 5120 byte, 5121 unsigned byte, 5122 short, 5123 unsigned short, "
      "5125 unsigned int, 5126 float)";
  std::string p = raw_fixture(temp_dir() / "pos_double.gltf", bytes,
                              R"([{"buffer": 0, "byteOffset": 0, "byteLength": 72}])",
                              R"([{"bufferView": 0, "componentType": 5130, "count": 3, "type": "VEC3"}])",
                              R"({"attributes": {"POSITION": 0}})");
  std::string e = message_of([&] { load_mesh(p); });
  EXPECT_NE(e.find("pos_double.gltf': mesh 0 primitive 0 POSITION (accessor 0)" + valid), std::string::npos) << e;

  p = with_accessor("normal_double.gltf", bytes, "NORMAL", R"("componentType": 5130, "count": 3, "type": "VEC3")");
  e = message_of([&] { load_mesh(p); });
  EXPECT_NE(e.find("mesh 0 primitive 0 NORMAL (accessor 1)" + valid), std::string::npos) << e;
}

TEST(GltfAccessor, NormalisedIndicesAreRefused) {
  // glTF forbids normalised indices; read as fractions of 255 every index was 0 and every
  // triangle collapsed onto vertex 0.
  std::vector<unsigned char> bytes = {0, 1, 2};
  std::string p = with_accessor("idx_norm.gltf", bytes, "indices",
                                R"("componentType": 5121, "normalized": true, "count": 3, "type": "SCALAR")");
  std::string e = message_of([&] { load_mesh(p); });
  EXPECT_NE(e.find("idx_norm.gltf': mesh 0 primitive 0 indices (accessor 1) is stored as 5121 unsigned byte "
                   "normalized, which glTF does not allow there (allowed: unsigned byte, unsigned short, unsigned int)"),
            std::string::npos)
      << e;
  // The same without "normalized" is a triangle.
  p = with_accessor("idx.gltf", bytes, "indices", R"("componentType": 5121, "count": 3, "type": "SCALAR")");
  EXPECT_EQ(load_mesh(p).indices, (std::vector<uint32_t>{0, 1, 2}));
}
