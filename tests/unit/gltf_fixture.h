// glTF files for tests, written two ways: Fixture through tinygltf's writer (an independent
// path from the loader's reader), raw_fixture as JSON text for what the writer cannot express
// (sparse accessors, invalid values).
#pragma once
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <glm/glm.hpp>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace gltf_fixture {

inline void expect_near(glm::dvec3 a, glm::dvec3 b, double tol, const std::string& what) {
  EXPECT_NEAR(a.x, b.x, tol) << what;
  EXPECT_NEAR(a.y, b.y, tol) << what;
  EXPECT_NEAR(a.z, b.z, tol) << what;
}

class Fixture {
 public:
  Fixture() {
    model.asset.version = "2.0";
    model.buffers.resize(1);
  }
  template <class T>
  int view(const std::vector<T>& data, int stride = 0) {
    auto& buf = model.buffers[0].data;
    buf.resize((buf.size() + 3) & ~size_t(3));
    tinygltf::BufferView v;
    v.buffer = 0;
    v.byteOffset = buf.size();
    v.byteLength = data.size() * sizeof(T);
    v.byteStride = size_t(stride);
    const auto* p = reinterpret_cast<const unsigned char*>(data.data());
    buf.insert(buf.end(), p, p + v.byteLength);
    model.bufferViews.push_back(v);
    return int(model.bufferViews.size()) - 1;
  }
  int accessor(int view, int component, int type, size_t count, size_t offset = 0) {
    tinygltf::Accessor a;
    a.bufferView = view;
    a.componentType = component;
    a.type = type;
    a.count = count;
    a.byteOffset = offset;
    model.accessors.push_back(a);
    return int(model.accessors.size()) - 1;
  }
  int vec3s(const std::vector<float>& v) {
    return accessor(view(v), TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, v.size() / 3);
  }
  int vec2s(const std::vector<float>& v) {
    return accessor(view(v), TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, v.size() / 2);
  }
  // One node holding mesh `mesh`, the only one in the default scene; returns the node's index.
  int place(int mesh) {
    tinygltf::Node n;
    n.mesh = mesh;
    model.nodes.push_back(n);
    if (model.scenes.empty()) model.scenes.resize(1);
    model.scenes[0].nodes.push_back(int(model.nodes.size()) - 1);
    model.defaultScene = 0;
    return int(model.nodes.size()) - 1;
  }
  std::string write(const std::filesystem::path& path) {
    std::ostringstream s;
    tinygltf::TinyGLTF w;
    EXPECT_TRUE(w.WriteGltfSceneToStream(&model, s, true, false));
    std::ofstream(path) << s.str();
    return path.string();
  }
  tinygltf::Model model;
};

inline tinygltf::Primitive primitive(int mode, int pos, int nrm = -1, int idx = -1) {
  tinygltf::Primitive p;
  p.mode = mode;
  p.attributes["POSITION"] = pos;
  if (nrm >= 0) p.attributes["NORMAL"] = nrm;
  p.indices = idx;
  return p;
}

// Base64 for hand-written fixtures (tinygltf cannot write sparse accessors).
inline std::string base64(const std::vector<unsigned char>& in) {
  static const char* t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < in.size(); i += 3) {
    unsigned v = unsigned(in[i]) << 16 | (i + 1 < in.size() ? unsigned(in[i + 1]) << 8 : 0) |
                 (i + 2 < in.size() ? in[i + 2] : 0);
    out += t[v >> 18 & 63];
    out += t[v >> 12 & 63];
    out += i + 1 < in.size() ? t[v >> 6 & 63] : '=';
    out += i + 2 < in.size() ? t[v & 63] : '=';
  }
  return out;
}

// A one-triangle file whose accessors are given as raw JSON, over one buffer `bytes`.
inline std::string raw_fixture(const std::filesystem::path& path, const std::vector<unsigned char>& bytes, const std::string& views,
                        const std::string& accessors, const std::string& primitive,
                        const std::string& nodes = R"([{"mesh": 0}])") {
  std::ofstream(path) << R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": )" << nodes
                      << R"(, "meshes": [{"primitives": [)" << primitive << R"(]}], "buffers": [{"byteLength": )"
                      << bytes.size() << R"(, "uri": "data:application/octet-stream;base64,)" << base64(bytes)
                      << R"("}], "bufferViews": )" << views << R"(, "accessors": )" << accessors << "}";
  return path.string();
}

inline std::vector<unsigned char> float_bytes(const std::vector<float>& v) {
  std::vector<unsigned char> b(v.size() * 4);
  std::memcpy(b.data(), v.data(), b.size());
  return b;
}

}  // namespace gltf_fixture
