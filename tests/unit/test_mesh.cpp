// Meshes: the real glTF sample files, hand-built glTF fixtures with known transforms, broken
// files, the procedural shapes against their formulas, .glb round trips and the GPU upload cache.
#include <gtest/gtest.h>
#include <tiny_gltf.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>

#include "gl/context.h"
#include "gl/program.h"
#include "gl/render_target.h"
#include "io/temp_dir.h"
#include "scene/camera.h"
#include "scene/gpu_mesh.h"
#include "scene/gltf.h"
#include "scene/mesh.h"
#include "scene/procedural.h"
#include "gltf_fixture.h"

namespace fs = std::filesystem;
using namespace sn::scene;
using namespace gltf_fixture;

namespace {

constexpr double kPi = 3.14159265358979323846;

std::string shared_meshes() {
  const char* s = std::getenv("SHADENET_SHARED");
  return std::string(s ? s : SHADENET_TEST_DIR "/../../shared") + "/meshes/";
}

fs::path temp_dir() {
  static const sn::io::TempDir dir("test_mesh");  // removed at exit
  return dir.path();
}

std::vector<unsigned char> read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_bytes(const fs::path& path, const void* data, size_t n) {
  std::ofstream out(path, std::ios::binary);
  out.write(static_cast<const char*>(data), std::streamsize(n));
}

// The message of the exception `f` throws ("" when it does not throw).
template <class F>
std::string error_of(F f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

// Every triangle must have area and face the way its vertices' normals point.
void expect_consistent_winding(const Mesh& m) {
  for (size_t t = 0; t < m.indices.size(); t += 3) {
    glm::dvec3 a(m.positions[m.indices[t]]), b(m.positions[m.indices[t + 1]]), c(m.positions[m.indices[t + 2]]);
    glm::dvec3 face = glm::cross(b - a, c - a);
    ASSERT_GT(glm::length(face), 0) << m.name << " triangle " << t / 3 << " has no area";
    glm::dvec3 n = glm::dvec3(m.normals[m.indices[t]]) + glm::dvec3(m.normals[m.indices[t + 1]]) +
                   glm::dvec3(m.normals[m.indices[t + 2]]);
    ASSERT_GT(glm::dot(face, n), 0) << m.name << " triangle " << t / 3 << " is wound against its normals";
  }
}

// One mesh under node B (matrix: translate 0,0,1) under root node A (TRS: translate (1,2,3),
// rotate 90 degrees about Y, scale (2,1,1)); its primitives use every index form and mode.
std::string transform_fixture(const fs::path& path) {
  Fixture f;
  auto& m = f.model;
  tinygltf::Mesh mesh;
  // 0: triangles, interleaved position + normal (byteStride 24), uint8 indices
  std::vector<float> inter = {0, 0, 0, 0, 0, 1, 1, 0, 0, 0, 0, 1, 0, 1, 0, 0, 0, 1};
  int iv = f.view(inter, 24);
  int p0 = f.accessor(iv, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, 3, 0);
  int n0 = f.accessor(iv, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, 3, 12);
  int i0 = f.accessor(f.view(std::vector<uint8_t>{0, 1, 2}), TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                      TINYGLTF_TYPE_SCALAR, 3);
  mesh.primitives.push_back(primitive(TINYGLTF_MODE_TRIANGLES, p0, n0, i0));
  // 1: a strip over a quad in the plane x + z = 0, facing (1,0,1)/sqrt2: a normal off the scale
  //    axes shows the inverse transpose at work; uint16 indices
  const float h = float(std::sqrt(0.5));
  int p1 = f.vec3s({0, 0, 0, 1, 0, -1, 0, 1, 0, 1, 1, -1});
  int n1 = f.vec3s({h, 0, h, h, 0, h, h, 0, h, h, 0, h});
  int i1 = f.accessor(f.view(std::vector<uint16_t>{0, 1, 2, 3}), TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                      TINYGLTF_TYPE_SCALAR, 4);
  mesh.primitives.push_back(primitive(TINYGLTF_MODE_TRIANGLE_STRIP, p1, n1, i1));
  // 2: triangles without indices and without normals (they get computed)
  int p2 = f.vec3s({0, 0, 9, 1, 0, 9, 0, 1, 9});
  mesh.primitives.push_back(primitive(TINYGLTF_MODE_TRIANGLES, p2));
  // 3: a fan with uint32 indices
  int p3 = f.vec3s({0, 0, -4, 1, 0, -4, 1, 1, -4, 0, 1, -4});
  int n3 = f.vec3s({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1});
  int i3 = f.accessor(f.view(std::vector<uint32_t>{0, 1, 2, 3}), TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
                      TINYGLTF_TYPE_SCALAR, 4);
  mesh.primitives.push_back(primitive(TINYGLTF_MODE_TRIANGLE_FAN, p3, n3, i3));
  // 4: points cover nothing and are skipped
  mesh.primitives.push_back(primitive(TINYGLTF_MODE_POINTS, p2));
  m.meshes.push_back(mesh);

  tinygltf::Node a, b;
  a.translation = {1, 2, 3};
  a.rotation = {0, std::sin(kPi / 4), 0, std::cos(kPi / 4)};
  a.scale = {2, 1, 1};
  a.children = {1};
  b.matrix = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 1, 1};
  b.mesh = 0;
  m.nodes = {a, b};
  tinygltf::Scene s;
  s.nodes = {0};
  m.scenes.push_back(s);
  m.defaultScene = 0;
  return f.write(path);
}

}  // namespace

// ---- the shared sample files ----

TEST(Mesh, DuckLoadsWithItsCountsNormalsUvsAndTexture) {
  Mesh m = load_mesh(shared_meshes() + "Duck.gltf");
  EXPECT_EQ(m.vertex_count(), 2399u);
  EXPECT_EQ(m.indices.size(), 12636u);
  EXPECT_TRUE(m.has_normals);
  EXPECT_FALSE(m.normals_computed);
  EXPECT_TRUE(m.has_uvs);
  ASSERT_TRUE(m.base_color.has_value());
  EXPECT_EQ(m.base_color->width, 512);
  EXPECT_EQ(m.base_color->height, 512);
  // The root node scales by 0.01: the accessor's min/max (SOURCES.md) times 0.01.
  expect_near(m.bounds.min, glm::dvec3(-69.29850006103516, 9.929369926452637, -61.32819747924805) * 0.01, 1e-6, "min");
  expect_near(m.bounds.max, glm::dvec3(96.17990112304688, 163.97000122070312, 53.92519760131836) * 0.01, 1e-6, "max");
  for (const auto& n : m.normals) ASSERT_NEAR(glm::length(n), 1.0, 1e-5);
  // The texture is the duck's yellow: its mean colour is far more red + green than blue.
  double r = 0, g = 0, b = 0;
  const auto& t = *m.base_color;
  for (int y = 0; y < t.height; ++y)
    for (int x = 0; x < t.width; ++x) r += t.at(x, y, 0), g += t.at(x, y, 1), b += t.at(x, y, 2);
  EXPECT_GT(r, 2 * b);
  EXPECT_GT(g, 1.5 * b);
}

TEST(Mesh, TextureDecodesOnFirstReadAndABadOneFailsThere) {
  // The duck with its embedded PNG swapped for a file of garbage beside it: the mesh loads (the
  // texture is not decoded yet), and each read of the texture is the decoder's error, naming it.
  fs::path d = temp_dir() / "bad_texture";
  fs::create_directories(d);
  std::string text(reinterpret_cast<const char*>(read_bytes(shared_meshes() + "Duck.gltf").data()),
                   read_bytes(shared_meshes() + "Duck.gltf").size());
  const size_t at = text.find("data:image/png;base64,");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, text.find('"', at) - at, "bad.png");
  write_bytes(d / "duck.gltf", text.data(), text.size());
  const std::string garbage = "not a PNG at all, only bytes";
  write_bytes(d / "bad.png", garbage.data(), garbage.size());

  Mesh m = load_mesh((d / "duck.gltf").string());
  ASSERT_TRUE(m.base_color.has_value());
  ASSERT_NE(m.base_color.encoded(), nullptr);
  EXPECT_EQ(std::string(m.base_color.encoded()->begin(), m.base_color.encoded()->end()), garbage);
  for (int read = 0; read < 2; ++read) {
    std::string e = error_of([&] { (void)m.base_color->width; });
    EXPECT_NE(e.find("mesh file '" + (d / "duck.gltf").string() + "': base-colour texture (image 0, 'bad.png')"),
              std::string::npos)
        << e;
  }

  // A good one is decoded once: copies (a transformed mesh) share its pixels.
  Mesh duck = load_mesh(shared_meshes() + "Duck.gltf");
  Mesh moved = transformed(duck, glm::dmat4(1.0));
  EXPECT_EQ(&*moved.base_color, &*duck.base_color);
  EXPECT_EQ(moved.base_color->width, 512);
  // One made from an image has no encoded bytes.
  EXPECT_EQ(Texture(sn::io::Image(2, 2, 3)).encoded(), nullptr);
  EXPECT_EQ(Texture(sn::io::Image(2, 2, 3))->width, 2);
  EXPECT_FALSE(Texture().has_value());
}

TEST(Mesh, BoxLoadsWithoutUvsAndKeepsItsBoundsAfterTheRootRotation) {
  Mesh m = load_mesh(shared_meshes() + "Box.gltf");
  EXPECT_EQ(m.vertex_count(), 24u);
  EXPECT_EQ(m.indices.size(), 36u);
  EXPECT_TRUE(m.has_normals);
  EXPECT_FALSE(m.normals_computed);
  EXPECT_FALSE(m.has_uvs);
  EXPECT_FALSE(m.base_color.has_value());
  expect_near(m.bounds.min, glm::dvec3(-0.5), 1e-7, "min");
  expect_near(m.bounds.max, glm::dvec3(0.5), 1e-7, "max");
  expect_consistent_winding(m);
  // Flat faces: every normal is an axis, and each face's 4 vertices lie on the plane it names.
  for (size_t i = 0; i < m.vertex_count(); ++i) {
    glm::dvec3 n(m.normals[i]), p(m.positions[i]);
    EXPECT_NEAR(glm::dot(n, p), 0.5, 1e-6) << "vertex " << i;
  }
}

// ---- node transforms, index types, primitive modes ----

TEST(Mesh, NodeTransformsIndexTypesAndModesFollowTheSpecification) {
  std::string path = transform_fixture(temp_dir() / "transforms.gltf");
  Mesh m = load_mesh(path);
  ASSERT_EQ(m.vertex_count(), 3u + 4u + 3u + 4u);
  ASSERT_EQ(m.indices.size(), 3u + 6u + 3u + 6u);
  EXPECT_TRUE(m.normals_computed);  // primitive 2 had none
  // Primitive 0, worked by hand: B moves z by 1, A scales x by 2, turns x -> -z and z -> x,
  // then moves by (1,2,3).
  expect_near(m.positions[0], {2, 2, 3}, 1e-6, "p0");
  expect_near(m.positions[1], {2, 2, 1}, 1e-6, "p1");
  expect_near(m.positions[2], {2, 3, 3}, 1e-6, "p2");
  expect_near(m.normals[0], {1, 0, 0}, 1e-6, "n0");
  // Primitive 1: normal (1,0,1)/sqrt2 through the inverse transpose R * S^-1 = (1, 0, -0.5) normalised.
  expect_near(m.normals[3], glm::dvec3(2, 0, -1) / std::sqrt(5.0), 1e-6, "strip normal");
  // The strip's triangles (0,1,2) and (2,1,3), offset by the 3 vertices before them.
  EXPECT_EQ(std::vector<uint32_t>(m.indices.begin() + 3, m.indices.begin() + 9),
            (std::vector<uint32_t>{3, 4, 5, 5, 4, 6}));
  // Primitive 2 (non-indexed): indices 7, 8, 9; the computed normal is its face normal.
  EXPECT_EQ(std::vector<uint32_t>(m.indices.begin() + 9, m.indices.begin() + 12), (std::vector<uint32_t>{7, 8, 9}));
  // face normal (0,0,1) in the file -> R * S^-1 -> (1, 0, 0)
  expect_near(m.normals[7], {1, 0, 0}, 1e-6, "computed normal");
  // Primitive 3 (fan): (0,1,2), (0,2,3), offset by 10.
  EXPECT_EQ(std::vector<uint32_t>(m.indices.begin() + 12, m.indices.end()),
            (std::vector<uint32_t>{10, 11, 12, 10, 12, 13}));
  expect_consistent_winding(m);
}

TEST(Mesh, AMirroringNodeFlipsTheWindingSoTrianglesStillFaceTheirNormals) {
  Fixture f;
  int p = f.vec3s({0, 0, 0, 1, 0, 0, 0, 1, 0});
  int n = f.vec3s({0, 0, 1, 0, 0, 1, 0, 0, 1});
  tinygltf::Mesh mesh;
  mesh.primitives.push_back(primitive(TINYGLTF_MODE_TRIANGLES, p, n));
  f.model.meshes.push_back(mesh);
  tinygltf::Node node;
  node.mesh = 0;
  node.scale = {1, 1, -1};  // mirror z: the normal flips to -z and the triangle must be rewound
  f.model.nodes.push_back(node);
  tinygltf::Scene s;
  s.nodes = {0};
  f.model.scenes.push_back(s);
  Mesh m = load_mesh(f.write(temp_dir() / "mirror.gltf"));
  expect_near(m.normals[0], {0, 0, -1}, 1e-7, "mirrored normal");
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 2, 1}));
  expect_consistent_winding(m);
}

// A cube of side 2 about the origin with a normal per face: 24 vertices, 36 uint16 indices.
int cube_mesh(Fixture& f) {
  std::vector<float> pos, nrm;
  std::vector<uint16_t> idx;
  for (int axis = 0; axis < 3; ++axis)
    for (float side : {1.0f, -1.0f}) {
      glm::vec3 n(0), u(0), v(0);
      n[axis] = side;
      u[(axis + 1) % 3] = 1, v[(axis + 2) % 3] = 1;
      if (side < 0) std::swap(u, v);  // u x v = n: counter-clockwise seen from outside
      const auto first = uint16_t(pos.size() / 3);
      for (glm::vec3 c : {n - u - v, n + u - v, n + u + v, n - u + v}) {
        pos.insert(pos.end(), {c.x, c.y, c.z});
        nrm.insert(nrm.end(), {n.x, n.y, n.z});
      }
      for (int k : {0, 1, 2, 0, 2, 3}) idx.push_back(uint16_t(first + k));
    }
  tinygltf::Mesh mesh;
  mesh.primitives.push_back(primitive(TINYGLTF_MODE_TRIANGLES, f.vec3s(pos), f.vec3s(nrm),
                                      f.accessor(f.view(idx), TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                                                 TINYGLTF_TYPE_SCALAR, idx.size())));
  f.model.meshes.push_back(mesh);
  return int(f.model.meshes.size()) - 1;
}

// A node scaled to zero along one axis flattens its mesh, and a glTF viewer draws it so: it used
// to vanish without a word (its normal matrix, the inverse transpose, does not exist).
TEST(Mesh, ANodeScaledToZeroAlongOneAxisDrawsItsMeshFlat) {
  for (double mirror : {1.0, -1.0}) {
    Fixture f;
    const int cube = cube_mesh(f);
    f.model.nodes[size_t(f.place(cube))].translation = {-3, 0, 0};
    tinygltf::Node& flat = f.model.nodes[size_t(f.place(cube))];
    flat.translation = {3, 0, 0};
    flat.rotation = {0, std::sin(kPi / 12), 0, std::cos(kPi / 12)};  // 30 degrees about y
    flat.scale = {mirror, 0, 1};
    const Mesh m = load_mesh(f.write(temp_dir() / "flat_node.gltf"));
    const std::string what = mirror < 0 ? "mirrored" : "plain";
    ASSERT_EQ(m.vertex_count(), 48u) << what;
    EXPECT_TRUE(m.notes.empty()) << what << ": " << m.notes[0];
    EXPECT_FALSE(m.normals_computed) << what;
    for (size_t i = 24; i < 48; ++i) {
      ASSERT_NEAR(m.positions[i].y, 0, 1e-6) << what << " vertex " << i;
      ASSERT_NEAR(glm::length(m.normals[i]), 1, 1e-6) << what << " vertex " << i;
    }
    // The faces that had area still do, lie in y = 0 and face the way their normals point: the
    // top (cube vertices 8..11) up and the bottom (12..15) down, the other way round under the
    // mirror, which turns their winding (a viewer does not rewind them: the determinant is 0).
    size_t with_area = 0;
    for (size_t t = 36; t < m.indices.size(); t += 3) {
      glm::dvec3 a(m.positions[m.indices[t]]), b(m.positions[m.indices[t + 1]]), c(m.positions[m.indices[t + 2]]);
      glm::dvec3 face = glm::cross(b - a, c - a);
      if (glm::length(face) < 1e-6) continue;  // a side, seen edge on
      ++with_area;
      for (int k = 0; k < 3; ++k)
        ASSERT_GT(glm::dot(face, glm::dvec3(m.normals[m.indices[t + k]])), 0) << what << " triangle " << t / 3;
    }
    EXPECT_EQ(with_area, 4u) << what;
    expect_near(m.normals[24 + 8], {0, mirror, 0}, 1e-6, what + " top");
    expect_near(m.normals[24 + 12], {0, -mirror, 0}, 1e-6, what + " bottom");
  }
}

// A mesh placed far from the origin (a georeferenced or CAD export: small local coordinates under
// a large translation) loses its shape to float's spacing once placed, and the mesh says so.
TEST(Mesh, AMeshFarFromTheOriginSaysItsVerticesLosePrecision) {
  auto placed_at = [](double x) {
    Fixture f;
    tinygltf::Mesh mesh;
    mesh.primitives.push_back(primitive(TINYGLTF_MODE_TRIANGLES, f.vec3s({0, 0, 0, 1, 0, 0, 0, 1, 0}),
                                        f.vec3s({0, 0, 1, 0, 0, 1, 0, 0, 1})));
    f.model.meshes.push_back(mesh);
    f.model.nodes[size_t(f.place(0))].translation = {x, 0, 0};
    return load_mesh(f.write(temp_dir() / "far.gltf"));
  };
  EXPECT_TRUE(placed_at(1e3).notes.empty());
  const Mesh far = placed_at(1e6);
  ASSERT_EQ(far.notes.size(), 1u);
  EXPECT_NE(far.notes[0].find("lies 1e+06 from the origin"), std::string::npos) << far.notes[0];
  EXPECT_NE(far.notes[0].find("are 0.0625 apart there"), std::string::npos) << far.notes[0];
}

TEST(Mesh, SparseAccessorsOverrideTheirBaseValues) {
  // positions 0..2 in the buffer, then one sparse index (ubyte 1, padded) and its value
  std::vector<unsigned char> bytes = float_bytes({0, 0, 0, 1, 0, 0, 0, 1, 0});
  bytes.insert(bytes.end(), {1, 0, 0, 0});
  auto v = float_bytes({7, 0, 0});
  bytes.insert(bytes.end(), v.begin(), v.end());
  std::string path = raw_fixture(
      temp_dir() / "sparse.gltf", bytes,
      R"([{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 1},
          {"buffer": 0, "byteOffset": 40, "byteLength": 12}])",
      R"([{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
           "sparse": {"count": 1, "indices": {"bufferView": 1, "componentType": 5121},
                      "values": {"bufferView": 2}}}])",
      R"({"attributes": {"POSITION": 0}})");
  Mesh m = load_mesh(path);
  expect_near(m.positions[1], {7, 0, 0}, 0, "sparse value");
  expect_near(m.positions[2], {0, 1, 0}, 0, "base value");
}

// ---- broken files: a clear message naming the file, never a crash ----

TEST(Mesh, MissingFileIsAClearError) {
  std::string e = error_of([] { load_mesh("no/such/mesh.gltf"); });
  char cwd[4096];
  ASSERT_NE(::getcwd(cwd, sizeof cwd), nullptr);
  EXPECT_EQ(e, "cannot read mesh file 'no/such/mesh.gltf': no such file (relative to the working directory " +
                   std::string(cwd) + ")");
  // Only regular files are read (/dev/zero used to be read until memory ran out).
  EXPECT_EQ(error_of([] { load_mesh("/dev/zero"); }), "cannot read mesh file '/dev/zero': not a regular file");
}

TEST(Mesh, GarbageFilesAreClearErrors) {
  fs::path d = temp_dir();
  std::vector<unsigned char> noise(4096);
  uint32_t s = 12345;
  for (auto& b : noise) b = (unsigned char)((s = s * 1664525u + 1013904223u) >> 24);
  noise[0] = 'x';
  write_bytes(d / "garbage.gltf", noise.data(), noise.size());
  std::string e = error_of([&] { load_mesh((d / "garbage.gltf").string()); });
  EXPECT_NE(e.find("mesh file '" + (d / "garbage.gltf").string() + "'"), std::string::npos) << e;
  EXPECT_NE(e.find("neither a glTF JSON file"), std::string::npos) << e;

  std::ofstream(d / "notjson.gltf") << "{ this is not JSON ]";
  e = error_of([&] { load_mesh((d / "notjson.gltf").string()); });
  EXPECT_NE(e.find("notjson.gltf': is not a valid glTF file (tinygltf:"), std::string::npos) << e;

  // A .glb magic followed by noise.
  std::memcpy(noise.data(), "glTF", 4);
  write_bytes(d / "garbage.glb", noise.data(), noise.size());
  e = error_of([&] { load_mesh((d / "garbage.glb").string()); });
  EXPECT_NE(e.find("garbage.glb': is not a valid binary glTF file"), std::string::npos) << e;

  std::ofstream(d / "empty.gltf").close();
  e = error_of([&] { load_mesh((d / "empty.gltf").string()); });
  EXPECT_NE(e.find("empty.gltf': is empty"), std::string::npos) << e;
}

// A .gltf's external buffers and images are read with the checks the file itself gets: a FIFO
// is refused at once (opening one waits for a writer: the load hung), a directory names itself
// (it was std::bad_alloc), a file above the size limit is refused before it is read (3 GiB were
// read whole). An image that cannot be read leaves the mesh loadable; reading the texture says why.
TEST(Mesh, ExternalFilesAreReadWithTheFileChecks) {
  fs::path d = temp_dir() / "external";
  fs::create_directories(d);
  auto tri = float_bytes({0, 0, 0, 1, 0, 0, 0, 1, 0});
  write_bytes(d / "tri.bin", tri.data(), tri.size());
  auto gltf = [&](const std::string& name, const std::string& buffer, const std::string& image) {
    std::ofstream(d / name) << R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
      "nodes": [{"mesh": 0}], "meshes": [{"primitives": [{"attributes": {"POSITION": 1, "TEXCOORD_0": 0}, "material": 0}]}],
      "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
      "textures": [{"source": 0}], "images": [{"uri": ")" << image << R"("}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC2"},
                    {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}],
      "bufferViews": [{"buffer": 0, "byteLength": 36}], "buffers": [{"uri": ")" << buffer << R"(", "byteLength": 36}]})";
    return (d / name).string();
  };
  ASSERT_EQ(mkfifo((d / "fifo.bin").c_str(), 0600), 0);
  std::string e = error_of([&] { load_mesh(gltf("fifo.gltf", "fifo.bin", "none.png")); });
  EXPECT_NE(e.find("cannot read file '" + (d / "fifo.bin").string() + "': not a regular file"), std::string::npos) << e;
  e = error_of([&] { load_mesh(gltf("dir.gltf", ".", "none.png")); });
  EXPECT_NE(e.find("it is a directory"), std::string::npos) << e;
  {
    std::ofstream big(d / "big.bin", std::ios::binary);
    big.write(reinterpret_cast<const char*>(tri.data()), 36);
  }
  fs::resize_file(d / "big.bin", (std::uintmax_t(1) << 30) + 1);  // sparse: no disk used
  e = error_of([&] { load_mesh(gltf("big.gltf", "big.bin", "none.png")); });
  EXPECT_NE(e.find("1073741825 bytes, above the limit"), std::string::npos) << e;

  // The buffer reads; the image is missing, a FIFO, a folder: the mesh loads, its texture throws.
  ASSERT_EQ(mkfifo((d / "fifo.png").c_str(), 0600), 0);
  for (const std::string image : {"none.png", "fifo.png", "."}) {
    Mesh m = load_mesh(gltf("tex.gltf", "tri.bin", image));
    EXPECT_EQ(m.triangle_count(), 1u);
    ASSERT_TRUE(m.base_color.has_value());
    e = error_of([&] { (void)m.base_color->width; });
    EXPECT_NE(e.find("base-colour texture (image 0, '" + image + "') could not be read"), std::string::npos) << e;
  }
}

// A file that requires an extension the loader lacks is refused naming it (glTF 2.0, 3.12):
// Draco-compressed geometry loaded as the uncompressed fallback's nothing, or failed as
// "invalid bufferView". One that only uses it, and KHR_mesh_quantization required, load.
TEST(Mesh, RequiredExtensionsTheLoaderLacksAreRefusedByName) {
  fs::path d = temp_dir();
  auto tri = float_bytes({0, 0, 0, 1, 0, 0, 0, 1, 0});
  auto file = [&](const std::string& name, const std::string& extensions, const std::string& view) {
    std::ofstream(d / name) << R"({"asset": {"version": "2.0"}, )" << extensions
                            << R"(, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
      "accessors": [{)" << view << R"(, "componentType": 5126, "count": 3, "type": "VEC3"}],
      "bufferViews": [{"buffer": 0, "byteLength": 36}],
      "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,)" << base64(tri) << R"("}]})";
    return (d / name).string();
  };
  const std::string draco = R"("extensionsUsed": ["KHR_draco_mesh_compression"], "extensionsRequired": ["KHR_draco_mesh_compression"])";
  std::string e = error_of([&] { load_mesh(file("draco.gltf", draco, R"("bufferView": 0)")); });
  EXPECT_NE(e.find("requires the glTF extension KHR_draco_mesh_compression, which shadenet does not read"),
            std::string::npos) << e;
  // With a view that is not there (as Draco's accessors point to compressed data) tinygltf
  // refuses the file first: the extension is still named.
  e = error_of([&] { load_mesh(file("draco_bare.gltf", draco, R"("bufferView": 7)")); });
  EXPECT_NE(e.find("requires the glTF extension KHR_draco_mesh_compression"), std::string::npos) << e;
  EXPECT_EQ(load_mesh(file("used.gltf", R"("extensionsUsed": ["KHR_draco_mesh_compression"])", R"("bufferView": 0)")).triangle_count(), 1u);
  EXPECT_EQ(load_mesh(file("quantized.gltf", R"("extensionsUsed": ["KHR_mesh_quantization"], "extensionsRequired": ["KHR_mesh_quantization"])",
                           R"("bufferView": 0)")).triangle_count(), 1u);
}

TEST(Mesh, TruncatedFilesAreClearErrorsAtEveryLength) {
  fs::path d = temp_dir();
  auto duck = read_bytes(shared_meshes() + "Duck.gltf");
  ASSERT_EQ(duck.size(), 162796u);
  write_bytes(d / "half.gltf", duck.data(), duck.size() / 2);
  std::string e = error_of([&] { load_mesh((d / "half.gltf").string()); });
  EXPECT_NE(e.find("mesh file '" + (d / "half.gltf").string() + "': is not a valid glTF file"), std::string::npos) << e;

  // The same file as .glb, cut at 97 lengths from the header to one byte short.
  save_glb(load_mesh(shared_meshes() + "Duck.gltf"), (d / "duck.glb").string());
  auto glb = read_bytes((d / "duck.glb").string());
  for (int k = 0; k <= 96; ++k) {
    size_t n = k == 96 ? glb.size() - 1 : glb.size() * size_t(k) / 96 + 1;
    write_bytes(d / "cut.glb", glb.data(), n);
    e = error_of([&] { load_mesh((d / "cut.glb").string()); });
    EXPECT_NE(e.find("mesh file '" + (d / "cut.glb").string() + "'"), std::string::npos) << n << " bytes: " << e;
  }
  for (int k = 1; k < 32; ++k) {
    write_bytes(d / "cut.gltf", duck.data(), duck.size() * size_t(k) / 32);
    EXPECT_NE(error_of([&] { load_mesh((d / "cut.gltf").string()); }).find("is not a valid glTF file"),
              std::string::npos)
        << k << "/32";
  }
}

TEST(Mesh, MalformedAccessorsIndicesAndNodesAreClearErrors) {
  fs::path d = temp_dir();
  auto tri = float_bytes({0, 0, 0, 1, 0, 0, 0, 1, 0});
  const std::string view = R"([{"buffer": 0, "byteOffset": 0, "byteLength": 36}])";
  const std::string acc = R"([{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}])";
  const std::string prim = R"({"attributes": {"POSITION": 0}})";

  // An accessor claiming more elements than its view holds.
  std::string p = raw_fixture(d / "long.gltf", tri, view,
                              R"([{"bufferView": 0, "componentType": 5126, "count": 4000000000, "type": "VEC3"}])", prim);
  std::string e = error_of([&] { load_mesh(p); });
  EXPECT_NE(e.find("POSITION: 4000000000 elements at byte offset 0 reach past the end of buffer view 0"),
            std::string::npos)
      << e;

  // An index past the vertices.
  auto bytes = tri;
  bytes.insert(bytes.end(), {0, 1, 7, 0});
  p = raw_fixture(d / "index.gltf", bytes,
                  R"([{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 3}])",
                  R"([{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                      {"bufferView": 1, "componentType": 5121, "count": 3, "type": "SCALAR"}])",
                  R"({"attributes": {"POSITION": 0}, "indices": 1})");
  e = error_of([&] { load_mesh(p); });
  EXPECT_NE(e.find("index 7 at position 2 is outside the 3 vertices"), std::string::npos) << e;

  // A node that is its own grandparent.
  p = raw_fixture(d / "cycle.gltf", tri, view, acc, prim, R"([{"mesh": 0, "children": [1]}, {"children": [0]}])");
  e = error_of([&] { load_mesh(p); });
  EXPECT_NE(e.find("cycle"), std::string::npos) << e;

  // Only points: nothing to draw.
  p = raw_fixture(d / "points.gltf", tri, view, acc, R"({"attributes": {"POSITION": 0}, "mode": 0})");
  e = error_of([&] { load_mesh(p); });
  EXPECT_NE(e.find("points.gltf': has no triangles"), std::string::npos) << e;
  EXPECT_EQ(e.find("scaled to zero"), std::string::npos) << e;

  // Its only node scaled to zero: the mesh is hidden, and the error says why.
  p = raw_fixture(d / "zero_scale.gltf", tri, view, acc, prim, R"([{"mesh": 0, "scale": [0, 0, 0]}])");
  e = error_of([&] { load_mesh(p); });
  EXPECT_NE(e.find("zero_scale.gltf': has no triangles (1 meshes, 0 primitives in the default scene, 1 mesh "
                   "placements hidden by a node scaled to zero;"),
            std::string::npos)
      << e;

  // Four indices in a triangle list: the whole triangle loads, the stray index is a note (it was
  // dropped without a word).
  {
    std::vector<unsigned char> bytes = tri;
    for (uint16_t i : {0, 1, 2, 1}) bytes.insert(bytes.end(), {static_cast<unsigned char>(i), 0});
    p = raw_fixture(d / "stray.gltf", bytes,
                    R"([{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 8}])",
                    R"([{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                        {"bufferView": 1, "componentType": 5123, "count": 4, "type": "SCALAR"}])",
                    R"({"attributes": {"POSITION": 0}, "indices": 1})");
    Mesh stray = load_mesh(p);
    EXPECT_EQ(stray.triangle_count(), 1u);
    ASSERT_EQ(stray.notes.size(), 2u);  // computed normals, then the stray index
    EXPECT_EQ(stray.notes[1], "has mesh 0 primitive 0 with 4 indices, not a multiple of 3: the last 1 (no whole triangle) left out");
  }

  // A rotation of length 0 (it was taken for no rotation at all).
  p = raw_fixture(d / "zero_quat.gltf", tri, view, acc, prim, R"([{"mesh": 0, "rotation": [0, 0, 0, 0]}])");
  e = error_of([&] { load_mesh(p); });
  EXPECT_NE(e.find("zero_quat.gltf': node 0 has a rotation of length 0, not a unit quaternion"), std::string::npos) << e;

  // A base-colour texture that is not in the file (it was ignored: the mesh loaded untextured).
  p = (d / "no_texture.gltf").string();
  {
    std::ofstream(p) << R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}],
      "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 5}}}],
      "bufferViews": )" << view << R"(, "accessors": )" << acc
                     << R"(, "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,)" << base64(tri)
                     << R"("}]})";
  }
  e = error_of([&] { load_mesh(p); });
  EXPECT_NE(e.find("material 0's base-colour texture is texture 5, but the file has 0"), std::string::npos) << e;

  // A NaN position.
  auto nan_tri = float_bytes({0, 0, 0, std::nanf(""), 0, 0, 0, 1, 0});
  p = raw_fixture(d / "nan.gltf", nan_tri, view, acc, prim);
  e = error_of([&] { load_mesh(p); });
  EXPECT_NE(e.find("POSITION 1 is not a finite number"), std::string::npos) << e;
}

// ---- .glb round trip ----

TEST(Mesh, SaveGlbRoundTripsEveryAttributeAndTheTexture) {
  fs::path d = temp_dir();
  Mesh duck = load_mesh(shared_meshes() + "Duck.gltf");
  std::string path = (d / "sub" / "duck.glb").string();  // the folder is created
  save_glb(duck, path);
  Mesh back = load_mesh(path);
  ASSERT_EQ(back.vertex_count(), duck.vertex_count());
  EXPECT_EQ(back.indices, duck.indices);
  EXPECT_EQ(back.positions, duck.positions);  // float32 both ways: bit exact
  EXPECT_EQ(back.uvs, duck.uvs);
  for (size_t i = 0; i < duck.vertex_count(); ++i) ASSERT_NEAR(glm::distance(back.normals[i], duck.normals[i]), 0, 1e-7);
  EXPECT_TRUE(back.has_uvs);
  EXPECT_FALSE(back.normals_computed);
  ASSERT_TRUE(back.base_color.has_value());
  EXPECT_EQ(back.base_color->width, 512);
  ASSERT_EQ(back.base_color->pixels.size(), duck.base_color->pixels.size());
  EXPECT_EQ(back.base_color->pixels, duck.base_color->pixels);  // 8-bit PNG in, 8-bit PNG out
  // Nothing but the file itself was left in the folder.
  int files = 0;
  for (auto& e : fs::directory_iterator(d / "sub")) {
    ++files;
    EXPECT_EQ(e.path().filename(), "duck.glb");
  }
  EXPECT_EQ(files, 1);

  Mesh box = load_mesh(shared_meshes() + "Box.gltf");
  save_glb(box, (d / "box.glb").string());
  Mesh box_back = load_mesh((d / "box.glb").string());
  EXPECT_FALSE(box_back.has_uvs);
  EXPECT_EQ(box_back.positions, box.positions);
}

TEST(Mesh, SaveGlbFailureLeavesNothingBehind) {
  fs::path d = temp_dir() / "blocked";
  fs::create_directories(d / "mesh.glb");  // a directory where the file should go
  std::string e = error_of([&] { save_glb(sphere(1, 8, 4), (d / "mesh.glb").string()); });
  EXPECT_NE(e.find("cannot write mesh '" + (d / "mesh.glb").string() + "'"), std::string::npos) << e;
  int entries = 0;
  for (auto& x : fs::directory_iterator(d)) (void)x, ++entries;
  EXPECT_EQ(entries, 1);  // just the directory that was in the way, no temporary file
}

// ---- procedural shapes against their formulas ----

TEST(Procedural, SphereNormalsAreUnitAndEqualPositionOverRadius) {
  const double r = 2.5;
  Mesh m = sphere(r, 24, 12);
  EXPECT_EQ(m.vertex_count(), size_t(25 * 13));
  EXPECT_EQ(m.indices.size(), size_t(24 * (12 - 1) * 2 * 3));  // the pole rows have one triangle per quad
  for (size_t i = 0; i < m.vertex_count(); ++i) {
    ASSERT_NEAR(glm::length(m.normals[i]), 1.0, 1e-6);
    ASSERT_NEAR(glm::distance(glm::dvec3(m.normals[i]), glm::dvec3(m.positions[i]) / r), 0.0, 1e-6) << i;
    ASSERT_TRUE(m.uvs[i].x >= 0 && m.uvs[i].x <= 1 && m.uvs[i].y >= 0 && m.uvs[i].y <= 1) << i;
  }
  expect_near(m.normals[0], {0, 1, 0}, 0, "north pole");
  expect_near(m.bounds.min, glm::dvec3(-r), 1e-6, "min");
  expect_near(m.bounds.max, glm::dvec3(r), 1e-6, "max");
  expect_consistent_winding(m);
  // The tessellated surface area approaches 4 pi r^2 from below.
  Mesh fine = sphere(1, 256, 128);
  double area = 0;
  for (size_t t = 0; t < fine.indices.size(); t += 3) {
    glm::dvec3 a(fine.positions[fine.indices[t]]), b(fine.positions[fine.indices[t + 1]]),
        c(fine.positions[fine.indices[t + 2]]);
    area += glm::length(glm::cross(b - a, c - a)) / 2;
  }
  EXPECT_LT(area, 4 * kPi);
  EXPECT_GT(area, 4 * kPi * 0.999);
}

TEST(Procedural, TorusNormalsPointFromTheTubeCentre) {
  const double R = 1.5, r = 0.4;
  Mesh m = torus(R, r, 32, 16);
  EXPECT_EQ(m.vertex_count(), size_t(33 * 17));
  EXPECT_EQ(m.indices.size(), size_t(32 * 16 * 6));
  for (size_t i = 0; i < m.vertex_count(); ++i) {
    glm::dvec3 p(m.positions[i]);
    glm::dvec3 ring = R * glm::normalize(glm::dvec3(p.x, 0, p.z));  // nearest point of the tube's centre line
    ASSERT_NEAR(glm::distance(p, ring), r, 1e-6);
    ASSERT_NEAR(glm::distance(glm::dvec3(m.normals[i]), (p - ring) / r), 0.0, 1e-6) << i;
  }
  expect_near(m.bounds.max, {R + r, r, R + r}, 1e-6, "max");
  expect_consistent_winding(m);
}

TEST(Procedural, PlaneFacesUpAndSpansItsSize) {
  Mesh m = plane(3, 4);
  EXPECT_EQ(m.vertex_count(), 25u);
  EXPECT_EQ(m.indices.size(), size_t(4 * 4 * 6));
  for (const auto& n : m.normals) ASSERT_EQ(n, glm::vec3(0, 1, 0));
  expect_near(m.bounds.min, {-1.5, 0, -1.5}, 1e-7, "min");
  expect_near(m.bounds.max, {1.5, 0, 1.5}, 1e-7, "max");
  expect_near(glm::dvec3(m.uvs[24], 0), {1, 1, 0}, 0, "last uv");
  expect_consistent_winding(m);
}

TEST(Procedural, BadSizesAreClearErrors) {
  EXPECT_EQ(error_of([] { sphere(1, 2, 8); }), "sphere: segments must be 3..4096, got 2");
  EXPECT_NE(error_of([] { sphere(-1); }).find("sphere: radius must be a positive number"), std::string::npos);
  EXPECT_NE(error_of([] { torus(1, std::nan("")); }).find("torus: minor must be a positive number"), std::string::npos);
  EXPECT_EQ(error_of([] { plane(1, 0); }), "plane: subdivisions must be 1..4096, got 0");
}

// ---- normals and transforms ----

TEST(Mesh, AreaWeightedNormalsWeighByTriangleArea) {
  // Two triangles share vertex 0: one of area 0.5 facing +Z, one of area 2 facing +Y.
  std::vector<glm::vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 2}, {2, 0, 0}};
  std::vector<uint32_t> idx = {0, 1, 2, 0, 3, 4};
  auto n = area_weighted_normals(p, idx);
  expect_near(n[0], glm::normalize(glm::dvec3(0, 4, 1)), 1e-7, "shared vertex");  // 2*area each: (0,0,1) and (0,4,0)
  expect_near(n[2], {0, 0, 1}, 1e-7, "first triangle only");
  expect_near(n[4], {0, 1, 0}, 1e-7, "second triangle only");
  // A vertex no triangle touches gets +Y rather than NaN.
  p.push_back({5, 5, 5});
  expect_near(area_weighted_normals(p, idx)[5], {0, 1, 0}, 0, "lonely vertex");
}

TEST(Mesh, AFileWithoutNormalsGetsFlatNormalsAsGltfRequires) {
  // An indexed cube of 8 shared corners, no normals: glTF 2.0 (3.7.2.1) requires flat normals.
  // Area-weighted vertex normals pointed along the diagonals and shaded it like a blob.
  Fixture f;
  int pos = f.vec3s({-1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1, -1, -1, 1, 1, -1, 1, 1, 1, 1, -1, 1, 1});
  std::vector<uint16_t> idx = {0, 3, 2, 0, 2, 1, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                               3, 7, 6, 3, 6, 2, 0, 4, 7, 0, 7, 3, 1, 2, 6, 1, 6, 5};
  int ia = f.accessor(f.view(idx), TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_SCALAR, idx.size());
  tinygltf::Mesh mesh;
  mesh.primitives.push_back(primitive(TINYGLTF_MODE_TRIANGLES, pos, -1, ia));
  f.model.meshes.push_back(mesh);
  f.place(0);
  Mesh m = load_mesh(f.write(temp_dir() / "cube_without_normals.gltf"));
  ASSERT_EQ(m.indices.size(), 36u);
  EXPECT_EQ(m.vertex_count(), 36u);  // each triangle's corners split from its neighbours'
  EXPECT_TRUE(m.normals_computed);
  expect_consistent_winding(m);
  for (size_t t = 0; t < m.indices.size(); t += 3) {
    glm::dvec3 n(m.normals[m.indices[t]]);
    // The face normal is the axis the face lies across: the one where all three corners agree.
    int axis = std::abs(n.x) > 0.5 ? 0 : std::abs(n.y) > 0.5 ? 1 : 2;
    for (int k = 0; k < 3; ++k) {
      ASSERT_NEAR(glm::distance(glm::dvec3(m.normals[m.indices[t + k]]), n), 0, 1e-7) << "triangle " << t / 3;
      ASSERT_NEAR(std::abs(n[axis]), 1, 1e-7) << "triangle " << t / 3;
      ASSERT_NEAR(m.positions[m.indices[t + k]][axis], n[axis], 1e-7) << "triangle " << t / 3;
    }
  }
  ASSERT_FALSE(m.notes.empty());
  EXPECT_NE(m.notes[0].find("has no normals in 1 of 1 primitives (mesh 0 primitive 0): computed flat normals"),
            std::string::npos)
      << m.notes[0];
}

// normals_computed says that some normals did not come from the file; zero ones the file has are
// repaired and counted in a note, but the file had normals (it said true, against its docs).
TEST(Mesh, RepairedNormalsAreANoteNotComputedNormals) {
  Fixture f;
  tinygltf::Mesh mesh;
  mesh.primitives.push_back(primitive(TINYGLTF_MODE_TRIANGLES, f.vec3s({0, 0, 0, 1, 0, 0, 0, 1, 0}),
                                      f.vec3s({0, 0, 1, 0, 0, 0, 0, 0, 1})));
  f.model.meshes.push_back(mesh);
  f.place(0);
  const Mesh m = load_mesh(f.write(temp_dir() / "zero_normal.gltf"));
  EXPECT_FALSE(m.normals_computed);
  expect_near(m.normals[1], {0, 0, 1}, 1e-7, "repaired normal");
  ASSERT_EQ(m.notes.size(), 1u);
  EXPECT_EQ(m.notes[0], "has 1 zero or non-finite normals: replaced by the area-weighted normals of the triangles "
                        "around them");
}

TEST(Mesh, TransformedUsesTheInverseTransposeForNormals) {
  // A sphere stretched to an ellipsoid x^2/4 + y^2 + z^2 = 1: its normal is the gradient (x/4, y, z).
  Mesh s = sphere(1, 32, 16);
  Mesh e = transformed(s, glm::scale(glm::dmat4(1.0), glm::dvec3(2, 1, 1)));
  for (size_t i = 0; i < e.vertex_count(); ++i) {
    glm::dvec3 p(e.positions[i]);
    ASSERT_NEAR(glm::distance(glm::dvec3(e.normals[i]), glm::normalize(glm::dvec3(p.x / 4, p.y, p.z))), 0, 1e-6);
  }
  expect_near(e.bounds.max, {2, 1, 1}, 1e-6, "stretched bounds");
  Mesh mirrored = transformed(s, glm::scale(glm::dmat4(1.0), glm::dvec3(-1, 1, 1)));
  expect_consistent_winding(mirrored);
  EXPECT_NE(error_of([&] { transformed(s, glm::dmat4(0.0)); }).find("singular"), std::string::npos);
}

// ---- GPU upload ----

TEST(GpuMesh, UploadsOnceAndDrawsFromTheCache) {
  sn::gl::current();
  Mesh m = sphere(1, 16, 8);
  size_t before = GpuMesh::uploads();
  GpuMesh& a = upload(m);
  GpuMesh& b = upload(m);
  EXPECT_EQ(&a, &b);
  EXPECT_EQ(GpuMesh::uploads(), before + 1);
  EXPECT_EQ(a.index_count(), m.indices.size());
  EXPECT_FALSE(a.has_base_color());
  EXPECT_NE(a.base_color_texture(), 0u);  // the 1x1 white stand-in
  m.gpu.reset();  // after an edit: the next draw uploads again
  upload(m);
  EXPECT_EQ(GpuMesh::uploads(), before + 2);
}

// The texture reaches the shader the glTF way round (uv (0,0) = the image's top-left): the
// colour drawn at each pixel equals the CPU twin's bilinear lookup of mesh.base_color at the uv
// drawn there (sample_lod0: level 0, the file's wrap, texel centres at (i + 0.5) / size).
TEST(GpuMesh, BaseColorTextureIsSampledAtTheMeshUvs) {
  sn::gl::current();
  Mesh duck = load_mesh(shared_meshes() + "Duck.gltf");
  const sn::io::Image& tex = *duck.base_color;
  Camera cam(duck.bounds.center() + glm::dvec3(1.2, 0.6, 1.8), duck.bounds.center());
  sn::gl::RenderTarget target(200, 200);
  auto render = [&](const char* frag) {
    auto p = sn::gl::get_program({"", "mesh.vert", std::string("tests/data/") + frag, {}});
    target.bind();
    target.clear();
    set_standard_uniforms(*p, cam, 1.0, glm::dmat4(1.0), upload(duck));
    draw(*p, upload(duck), glm::dmat4(1.0));
    return target.read();
  };
  sn::io::Image uv = render("uv.frag"), color = render("base_color.frag");
  auto texel = [&](int x, int y, int c) {
    return double(tex.at(wrap_texel(Wrap::repeat, x, tex.width), wrap_texel(Wrap::repeat, y, tex.height), c));
  };
  int covered = 0;
  double max_err = 0, sum_err = 0;
  for (int y = 0; y < uv.height; ++y)
    for (int x = 0; x < uv.width; ++x) {
      if (uv.at(x, y, 3) < 0.5) continue;
      ASSERT_EQ(color.at(x, y, 3), 1.f) << "u_has_base_color";
      for (int c = 0; c < 3; ++c) {
        double want = sample_lod0(tex, duck.base_color.sampler, uv.at(x, y, 0), uv.at(x, y, 1), c);
        double err = std::abs(color.at(x, y, c) - want);
        max_err = std::max(max_err, err);
        sum_err += err;
      }
      ++covered;
    }
  ASSERT_GT(covered, 5000);
  // GPUs blend with 8-bit weights: llvmpipe measured 0.0036 (under 1/255), mean 9e-6.
  EXPECT_LT(max_err, 4.0 / 255) << "mean " << sum_err / (3 * covered);
  // The same lookup with v flipped (the texture upside down) is far off (measured mean 0.05).
  double flipped = 0;
  for (int y = 0; y < uv.height; ++y)
    for (int x = 0; x < uv.width; ++x)
      if (uv.at(x, y, 3) > 0.5) {
        int tx = int(uv.at(x, y, 0) * tex.width) % tex.width, ty = int((1 - uv.at(x, y, 1)) * tex.height) % tex.height;
        flipped += std::abs(color.at(x, y, 0) - texel(tx, ty, 0));
      }
  EXPECT_GT(flipped / covered, 0.02);
}
