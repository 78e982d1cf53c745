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
