#include "scene/gltf.h"

// Debian's libtinygltf.so carries the implementation (built with its default options), so the
// header is only declarations here: no TINYGLTF_IMPLEMENTATION, no option macros that would
// change the classes' layout.
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <set>
#include <sstream>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "io/atomic_write.h"
#include "io/limits.h"
#include "io/read_file.h"
#include "io/text.h"
#include "scene/gltf_accessor.h"
#include "scene/gltf_deform.h"
#include "scene/tangents.h"
#include "scene/transform.h"

namespace sn::scene {

namespace fs = std::filesystem;

namespace {

// tinygltf reads an optional unsigned property that is negative or not an integer as absent
// ("byteOffset": -1 became 0 and read normals as positions; "bufferView": -1 became an all-zero
// accessor), and an optional index that is not an integer likewise. The raw JSON is at hand, so
// it is read once more (SAX: nothing stored) and every property of these the loader uses must be
// a non-negative integer where it appears. The same pass collects "extensionsRequired".
class JsonCheck : public nlohmann::json::json_sax_t {
 public:
  bool null() override { return scalar("null"); }
  bool boolean(bool v) override { return scalar(v ? "true" : "false"); }
  bool number_integer(number_integer_t v) override { return v >= 0 ? fine() : scalar(std::to_string(v)); }
  bool number_unsigned(number_unsigned_t) override { return fine(); }
  bool number_float(number_float_t, const string_t& text) override { return scalar(text); }
  bool string(string_t& v) override {
    if (stack_.size() == 2 && !stack_[1].object && stack_[0].key == "extensionsRequired") required_.push_back(v);
    return scalar("a string (\"" + v.substr(0, 40) + "\")");
  }
  bool binary(binary_t&) override { return scalar("binary"); }
  bool start_object(std::size_t) override {
    if (!scalar("an object")) return false;
    stack_.push_back({true, ""});
    return true;
  }
  bool key(string_t& k) override {
    stack_.back().key = k;
    return true;
  }
  bool end_object() override {
    stack_.pop_back();
    return true;
  }
  bool start_array(std::size_t) override {
    if (!scalar("an array")) return false;
    stack_.push_back({false, "", -1});
    return true;
  }
  bool end_array() override {
    stack_.pop_back();
    return true;
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override { return false; }

  const std::string& problem() const { return problem_; }
  // The top-level "extensionsRequired" strings read before the end or the first problem.
  const std::vector<std::string>& required() const { return required_; }

 private:
  struct Frame {
    bool object;
    std::string key;  // objects: the current key
    long index = -1;  // arrays: the current element
  };

  // A value is about to be read at the current position: advance an array's index.
  void advance() {
    if (!stack_.empty() && !stack_.back().object) ++stack_.back().index;
  }
  // A non-negative integer: right wherever one is required.
  bool fine() {
    advance();
    return true;
  }
  // A value that is not a non-negative integer: fine unless the glTF property here must be one.
  bool scalar(const std::string& what) {
    advance();
    if (!must_be_index()) return true;
    problem_ = where() + " is " + what + "; glTF requires a non-negative integer there";
    return false;
  }

  // The path's names, arrays' elements as "*".
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const Frame& f : stack_) out.push_back(f.object ? f.key : "*");
    return out;
  }
  std::string where() const {
    std::string out;
    for (const Frame& f : stack_)
      out += f.object ? (out.empty() ? "" : ".") + f.key : "[" + std::to_string(f.index) + "]";
    return out;
  }
  bool must_be_index() const {
    const std::vector<std::string> p = names();
    auto is = [&](std::initializer_list<const char*> pattern) {
      if (p.size() != pattern.size()) return false;
      std::size_t i = 0;
      for (const char* q : pattern) {
        if (std::strcmp(q, "?") != 0 && p[i] != q) return false;  // "?": any name
        ++i;
      }
      return true;
    };
    auto last_in = [&](std::initializer_list<const char*> keys) {
      for (const char* k : keys)
        if (p.back() == k) return true;
      return false;
    };
    if (p.empty()) return false;
    if (is({"scene"})) return true;
    if (is({"accessors", "*", "?"})) return last_in({"bufferView", "byteOffset", "count", "componentType"});
    if (is({"accessors", "*", "sparse", "?"})) return last_in({"count"});
    if (is({"accessors", "*", "sparse", "indices", "?"}) || is({"accessors", "*", "sparse", "values", "?"}))
      return last_in({"bufferView", "byteOffset", "componentType"});
    if (is({"bufferViews", "*", "?"})) return last_in({"buffer", "byteOffset", "byteLength", "byteStride"});
    if (is({"buffers", "*", "?"})) return last_in({"byteLength"});
    if (is({"meshes", "*", "primitives", "*", "?"})) return last_in({"indices", "material", "mode"});
    if (is({"meshes", "*", "primitives", "*", "attributes", "?"})) return true;
    if (is({"meshes", "*", "primitives", "*", "targets", "*", "?"})) return true;
    if (is({"nodes", "*", "?"})) return last_in({"mesh", "camera", "skin"});
    if (is({"nodes", "*", "children", "*"}) || is({"scenes", "*", "nodes", "*"})) return true;
    if (is({"textures", "*", "?"})) return last_in({"source", "sampler"});
    if (is({"images", "*", "?"})) return last_in({"bufferView"});
    if (is({"materials", "*", "pbrMetallicRoughness", "baseColorTexture", "?"})) return last_in({"index", "texCoord"});
    return false;
  }

  std::vector<Frame> stack_;
  std::string problem_;
  std::vector<std::string> required_;
};

// glTF 2.0 (section 3.12): a loader refuses a file that requires an extension it does not read.
// Draco or meshopt compressed geometry loaded as nothing, or failed as "invalid bufferView".
void check_required_extensions(const std::vector<std::string>& required, const std::string& path) {
  for (const std::string& e : required)
    if (e != "KHR_mesh_quantization")
      throw FileError(path, "requires the glTF extension " + e +
                            ", which shadenet does not read (of those a file may require, it reads KHR_mesh_quantization)");
}

// Throws naming an extension `json` (the file's JSON text or a .glb's JSON chunk) requires that
// the loader lacks or, unless `extensions_only`, the first property that glTF requires to be a
// non-negative integer and is not. JSON that does not parse throws nothing here.
void check_json(const char* json, std::size_t size, const std::string& path, bool extensions_only = false) {
  JsonCheck check;
  nlohmann::json::sax_parse(json, json + size, &check, nlohmann::json::input_format_t::json, false);
  check_required_extensions(check.required(), path);
  if (!extensions_only && !check.problem().empty()) throw FileError(path, check.problem());
}

// tinygltf's reasons can quote kilobytes of the file (a cut base64 buffer); keep the start.
std::string short_reason(std::string s) {
  constexpr size_t kMax = 240;
  if (s.size() > kMax) s = s.substr(0, kMax) + "...";
  while (!s.empty() && (s.back() == '\n' || s.back() == '\r' || s.back() == ' ')) s.pop_back();
  return s;
}

// tinygltf hands every image's encoded bytes (data: URI, external file or .glb buffer view) to
// this callback; we keep them as they are and decode only the texture the mesh uses, with
// OpenImageIO, instead of letting stb decode every image up front.
bool keep_image_bytes(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*) {
  image->image.assign(bytes, bytes + std::max(size, 0));
  image->as_is = true;
  return true;
}

// tinygltf reads a .gltf's external buffers and images through these: the checks the file itself
// gets (regular files only, the size limit, io/read_file.h), and nothing that opens a path to see
// whether it exists (opening a FIFO waits for a writer), nor expands it (tinygltf's own expands ~).
bool file_exists(const std::string& path, void*) {
  std::error_code ec;
  return fs::exists(path, ec);
}
std::string path_as_is(const std::string& path, void*) { return path; }
bool read_whole_file(std::vector<unsigned char>* out, std::string* err, const std::string& path, void*) {
  try {
    const std::string bytes = io::read_file(path, "file");
    out->assign(bytes.begin(), bytes.end());
    return true;
  } catch (const std::exception& e) {
    if (err) *err += std::string(e.what()) + "\n";
    return false;
  }
}
bool no_writes(std::string* err, const std::string& path, const std::vector<unsigned char>&, void*) {
  if (err) *err += "loading '" + path + "' does not write files\n";
  return false;
}

// The node's local transform; `why` gets what is wrong with it ("" when nothing is).
glm::dmat4 node_transform(const tinygltf::Node& n, std::string& why) {
  if (n.matrix.size() == 16) return glm::make_mat4(n.matrix.data());  // column-major, as in GLM
  glm::dmat4 t(1.0), r(1.0), s(1.0);
  if (n.translation.size() == 3) t[3] = glm::dvec4(n.translation[0], n.translation[1], n.translation[2], 1.0);
  if (n.rotation.size() == 4) {
    // glTF stores (x, y, z, w); glm::dquat's constructor takes w first. A unit quaternion, up to
    // rounding; one of length 0 is no rotation at all (it was taken for the identity).
    glm::dquat q(n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2]);
    if (!(glm::length(q) > 1e-6)) why = "a rotation of length " + io::number_text(glm::length(q)) + ", not a unit quaternion";
    else r = glm::mat4_cast(glm::normalize(q));
  }
  if (n.scale.size() == 3) s = glm::scale(glm::dmat4(1.0), glm::dvec3(n.scale[0], n.scale[1], n.scale[2]));
  return t * r * s;
}

// Primitives a note is about, counted per placement, the first three names kept for the text.
struct PrimitiveList {
  std::size_t count = 0;
  std::vector<std::string> names;
  void add(const std::string& name) {
    ++count;
    if (names.size() < 3 && std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  }
  bool empty() const { return count == 0; }
  std::string text() const { return io::join(names) + (count > names.size() ? ", ..." : ""); }
};

// Turns one primitive's index list (or 0..count-1) into triangles per its mode.
std::vector<uint32_t> triangles_of(int mode, const std::vector<uint32_t>& in) {
  std::vector<uint32_t> out;
  if (mode == TINYGLTF_MODE_TRIANGLES || mode == -1) {
    out.assign(in.begin(), in.begin() + (in.size() / 3) * 3);
  } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
    for (size_t i = 2; i < in.size(); ++i) {
      // every other triangle of a strip is wound the other way round
      if (i % 2 == 0) out.insert(out.end(), {in[i - 2], in[i - 1], in[i]});
      else out.insert(out.end(), {in[i - 1], in[i - 2], in[i]});
    }
  } else if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
    for (size_t i = 2; i < in.size(); ++i) out.insert(out.end(), {in[0], in[i - 1], in[i]});
  }
  return out;
}

class GltfLoader {
 public:
  GltfLoader(const tinygltf::Model& m, const std::string& path, const std::string& warnings)
      : m_(m), path_(path), warnings_(warnings), reader_(m, path) {}

  Mesh load() {
    mesh_.name = path_;
    std::vector<int> roots;
    int scene = m_.defaultScene >= 0 ? m_.defaultScene : (m_.scenes.empty() ? -1 : 0);
    if (scene >= int(m_.scenes.size()))
      throw FileError(path_, "default scene " + std::to_string(scene) + " does not exist (the file has " +
                                 std::to_string(m_.scenes.size()) + ")");
    if (scene >= 0) {
      roots = m_.scenes[size_t(scene)].nodes;
    } else {
      // No scene: every node nobody lists as a child is a root.
      std::set<int> children;
      for (const auto& n : m_.nodes) children.insert(n.children.begin(), n.children.end());
      for (int i = 0; i < int(m_.nodes.size()); ++i)
        if (!children.count(i)) roots.push_back(i);
      if (m_.nodes.empty())
        for (int i = 0; i < int(m_.meshes.size()); ++i) add_mesh(i, glm::dmat4(1.0), {}, -1);
    }
    for (int r : roots) walk(r, glm::dmat4(1.0));

    if (mesh_.indices.empty())
      throw FileError(path_, "has no triangles (" + std::to_string(m_.meshes.size()) + " meshes, " +
                                 std::to_string(primitives_seen_) + " primitives in the default scene" +
                                 (placements_hidden_ ? ", " + std::to_string(placements_hidden_) +
                                                           " mesh placements hidden by a node scaled to zero"
                                                     : std::string()) +
                                 "; points and lines are not drawn)");
    mesh_.has_normals = true;
    // A primitive without texture coordinates (a textured body's untextured eyes) keeps (0, 0)
    // rather than taking the others' away: they used to be zeroed too, drawing one flat colour.
    // The note comes wherever uvs matter: the mesh has a texture (it was missing when no
    // primitive had the set its texture reads) or other primitives have uvs.
    mesh_.has_uvs = primitives_with_uvs_ > 0;
    mesh_.uv_sets = io::join(std::vector<std::string>(uv_sets_.begin(), uv_sets_.end()));
    if ((mesh_.has_uvs || texture_image_ >= 0) && !primitives_without_uvs_.empty()) {
      // At uv (0, 0), the corner where the four corner texels meet: repeat and linear blend them.
      mesh_.notes.push_back("has " + std::to_string(primitives_without_uvs_.count) + " of " +
                            std::to_string(primitives_used_) + " primitives without texture coordinates (" +
                            primitives_without_uvs_.text() +
                            "): their uvs are (0, 0), where a texture shows one flat colour (the average of its "
                            "four corner texels under repeat wrapping and linear filtering, else its top-left "
                            "texel); give them texture coordinates in the file");
    }
    // The file's tangents are used when every primitive has them (a degenerate one is replaced by
    // the generated frame); otherwise all are generated alike when drawn (tangents.h).
    if (primitives_with_tangents_ == primitives_used_) {
      std::vector<glm::vec4> generated = uv_tangents(mesh_);
      for (std::size_t i = 0; i < file_tangents_.size(); ++i)
        if (file_tangents_[i].w == 0.0f) file_tangents_[i] = generated[i];
      mesh_.tangents = std::move(file_tangents_);
      mesh_.tangent_source = "file";
    }
    mesh_.bounds = compute_bounds(mesh_.positions);
    // Positions are floats once placed: far from the origin their spacing (float's at the largest
    // coordinate) becomes visible in the shape (a unit sphere placed at 1e6 is lumpy).
    const glm::dvec3 reach = glm::max(glm::abs(mesh_.bounds.min), glm::abs(mesh_.bounds.max));
    const double far = std::max({reach.x, reach.y, reach.z}), size = 2 * mesh_.bounds.radius();
    const double spacing = far > 0 ? std::ldexp(1.0, std::ilogb(far) - 23) : 0;
    if (spacing > 1e-3 * size)
      mesh_.notes.push_back("lies " + io::number_text(far) + " from the origin, " + io::number_text(far / size) +
                            " times its size: its vertices, floats once placed, are " + io::number_text(spacing) +
                            " apart there (" + io::number_text(spacing / size) +
                            " of its size), which can show in the shape; move it to the origin in the file");
    if (texture_image_ >= 0) {
      mesh_.base_color = texture(texture_image_);
      mesh_.base_color.sampler = sampler_;
    }
    if (unweighted_vertices_)
      mesh_.notes.push_back("has " + std::to_string(unweighted_vertices_) +
                            " skinned vertices whose joint weights are all zero: drawn where the file puts them, "
                            "unskinned; give them weights in the file");
    if (normals_repaired_)
      mesh_.notes.insert(mesh_.notes.begin(), "has " + std::to_string(normals_repaired_) +
                                                  " zero or non-finite normals: replaced by the area-weighted "
                                                  "normals of the triangles around them");
    if (!primitives_flat_.empty())
      mesh_.notes.insert(mesh_.notes.begin(),
                         "has no normals in " + std::to_string(primitives_flat_.count) + " of " +
                             std::to_string(primitives_used_) + " primitives (" + primitives_flat_.text() +
                             "): computed flat normals as glTF 2.0 requires (3.7.2.1), each triangle its face "
                             "normal on vertices of its own; give the file normals for smooth shading");
    return std::move(mesh_);
  }

 private:
  void walk(int node, const glm::dmat4& parent, int depth = 1) {
    if (node < 0 || size_t(node) >= m_.nodes.size())
      throw FileError(path_, "refers to node " + std::to_string(node) + ", but the file has " +
                                 std::to_string(m_.nodes.size()));
    // Bounded before anything is added: a chain 30,000 nodes deep overflowed the stack, one node
    // listed 200,000 times grew the mesh to 23 GB.
    if (depth > kMaxNodeDepth)
      throw FileError(path_, "nests nodes more than " + std::to_string(kMaxNodeDepth) + " deep (the limit, scene/gltf.h)");
    if (++node_visits_ > limits_.node_placements)
      throw FileError(path_, "places nodes more than " + std::to_string(limits_.node_placements) +
                                 " times (a node listed many times?)" + io::raise_hint("node_placements"));
    if (!on_path_.insert(node).second)
      throw FileError(path_, "node " + std::to_string(node) + " is its own ancestor (a cycle in the node tree)");
    const tinygltf::Node& n = m_.nodes[size_t(node)];
    std::string why;
    glm::dmat4 world = parent * node_transform(n, why);
    if (!why.empty()) throw FileError(path_, "node " + std::to_string(node) + " has " + why);
    if (!is_finite(world)) throw FileError(path_, "node " + std::to_string(node) + " has a non-finite transform");
    // A skinned mesh is placed by its joints alone: glTF 3.7.3 says its node's transform MUST be
    // ignored (it was applied, on top of no skinning at all).
    if (n.mesh >= 0) add_mesh(n.mesh, n.skin >= 0 ? glm::dmat4(1.0) : world, n.weights, n.skin);
    for (int c : n.children) walk(c, world, depth + 1);
    on_path_.erase(node);
  }

  // `node_weights`: the placing node's morph weights, which override the mesh's (glTF 3.7.2.2).
  // `skin`: the placing node's skin, or -1.
  void add_mesh(int index, const glm::dmat4& world, const std::vector<double>& node_weights, int skin) {
    if (size_t(index) >= m_.meshes.size())
      throw FileError(path_, "refers to mesh " + std::to_string(index) + ", but the file has " +
                                 std::to_string(m_.meshes.size()));
    const glm::dmat3 linear(world);
    // A node scaled to zero along one axis flattens its mesh, which is drawn flat as a glTF viewer
    // draws it (it vanished: the inverse transpose does not exist, the cofactor matrix does). One
    // scaled to zero along two or three leaves no area that could cover a pixel.
    const glm::dmat3 normals = normal_matrix(linear);
    if (normals == glm::dmat3(0.0)) {
      ++placements_hidden_;
      return;
    }
    const tinygltf::Mesh& mesh = m_.meshes[size_t(index)];
    const std::vector<double>& weights = node_weights.empty() ? mesh.weights : node_weights;
    for (size_t p = 0; p < mesh.primitives.size(); ++p)
      add_primitive(mesh.primitives[p], "mesh " + std::to_string(index) + " primitive " + std::to_string(p), world,
                    normals, glm::determinant(linear) < 0, weights, skin);
  }

  void add_primitive(const tinygltf::Primitive& prim, const std::string& what, const glm::dmat4& world,
                     const glm::dmat3& normal_matrix, bool mirrored, const std::vector<double>& morph_weights,
                     int skin) {
    ++primitives_seen_;
    int mode = prim.mode;
    if (mode != -1 && mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
        mode != TINYGLTF_MODE_TRIANGLE_FAN)
      return;  // points and lines cover no area
    auto pos_it = prim.attributes.find("POSITION");
    if (pos_it == prim.attributes.end()) throw FileError(path_, what + " has no POSITION attribute");
    std::vector<double> pos = reader_.read(pos_it->second, 3, what + " POSITION", storages::kPosition);
    size_t count = pos.size() / 3;
    if (count == 0) return;

    std::vector<double> nrm, uv;
    if (auto it = prim.attributes.find("NORMAL"); it != prim.attributes.end()) {
      nrm = reader_.read(it->second, 3, what + " NORMAL", storages::kDirection);
      if (nrm.size() != pos.size())
        throw FileError(path_, what + ": NORMAL has " + std::to_string(nrm.size() / 3) + " elements, POSITION " +
                                   std::to_string(count));
    }
    std::vector<double> tan;
    if (auto it = prim.attributes.find("TANGENT"); it != prim.attributes.end()) {
      tan = reader_.read(it->second, 4, what + " TANGENT", storages::kDirection);
      if (tan.size() != count * 4)
        throw FileError(path_, what + ": TANGENT has " + std::to_string(tan.size() / 4) + " elements, POSITION " +
                                   std::to_string(count));
    }
    // The rest shape includes the morph targets at their default weights (they were ignored).
    add_morph_targets(reader_, prim, morph_weights, what, path_, pos, nrm, tan);
    // The set the material's base-colour texture names (texCoord n: TEXCOORD_n); it was always 0.
    const tinygltf::TextureInfo* texture = base_color_texture(prim);
    const std::string uv_set = "TEXCOORD_" + std::to_string(texture ? texture->texCoord : 0);
    if (auto it = prim.attributes.find(uv_set); it != prim.attributes.end()) {
      uv = reader_.read(it->second, 2, what + " " + uv_set, storages::kTexcoord);
      if (uv.size() != count * 2)
        throw FileError(path_, what + ": " + uv_set + " has " + std::to_string(uv.size() / 2) + " elements, POSITION " +
                                   std::to_string(count));
    }

    // Skinned: every vertex through its own skin matrix, into world space (world is the identity).
    std::vector<char> skin_mirrors;  // per vertex
    if (skin >= 0) {
      const auto skins = skin_matrices(reader_, m_, skin, prim, globals(), count, what, path_, unweighted_vertices_);
      skin_mirrors = apply_skin(skins, pos, nrm, tan);
    }

    std::vector<uint32_t> local;
    if (prim.indices >= 0) {
      std::vector<double> idx = reader_.read(prim.indices, 1, what + " indices", storages::kIndex);
      local.resize(idx.size());
      for (size_t i = 0; i < idx.size(); ++i) {
        if (idx[i] >= double(count))
          throw FileError(path_, what + ": index " + std::to_string((unsigned long long)idx[i]) + " at position " +
                                     std::to_string(i) + " is outside the " + std::to_string(count) + " vertices");
        local[i] = uint32_t(idx[i]);
      }
    } else {
      local.resize(count);
      for (size_t i = 0; i < count; ++i) local[i] = uint32_t(i);
    }
    std::vector<uint32_t> tris = triangles_of(mode, local);
    if ((mode == TINYGLTF_MODE_TRIANGLES || mode == -1) && local.size() % 3)
      mesh_.notes.push_back("has " + what + " with " + std::to_string(local.size()) +
                            " indices, not a multiple of 3: the last " + std::to_string(local.size() % 3) +
                            " (no whole triangle) left out");
    if (tris.empty()) return;
    ++primitives_used_;
    // A mirror turns the winding; under a skin, the mirror is the first corner's skin matrix's.
    for (size_t t = 0; t < tris.size(); t += 3)
      if (mirrored != (!skin_mirrors.empty() && skin_mirrors[tris[t]])) std::swap(tris[t + 1], tris[t + 2]);
    // glTF 2.0 (3.7.2.1): without normals, flat ones. Each triangle gets three vertices of its own,
    // so its face normal is not averaged with its neighbours' (a cube came out as a blob).
    if (nrm.empty()) {
      auto split = [&](std::vector<double>& a, size_t k) {
        if (a.empty()) return;
        std::vector<double> out;
        out.reserve(tris.size() * k);
        for (uint32_t i : tris) out.insert(out.end(), a.begin() + i * k, a.begin() + (i + 1) * k);
        a = std::move(out);
      };
      split(pos, 3), split(uv, 2), split(tan, 4);
      count = tris.size();
      for (size_t i = 0; i < count; ++i) tris[i] = uint32_t(i);
      primitives_flat_.add(what);
      mesh_.normals_computed = true;
    }

    size_t base = mesh_.positions.size();
    if (base + count > limits_.mesh_vertices)
      throw FileError(path_, "has more than " + std::to_string(limits_.mesh_vertices) + " vertices (at " + what +
                                 ", after its nodes' placements)" + io::raise_hint("mesh_vertices"));
    if (mesh_.indices.size() + tris.size() > limits_.mesh_indices)
      throw FileError(path_, "has more than " + std::to_string(limits_.mesh_indices) + " indices (at " + what +
                                 ", after its nodes' placements)" + io::raise_hint("mesh_indices"));
    if (base + count > size_t(UINT32_MAX)) throw FileError(path_, "has more than 2^32 vertices");
    std::vector<glm::vec3> world_pos(count);
    for (size_t i = 0; i < count; ++i) {
      glm::dvec4 w = world * glm::dvec4(pos[3 * i], pos[3 * i + 1], pos[3 * i + 2], 1.0);
      if (!std::isfinite(w.x) || !std::isfinite(w.y) || !std::isfinite(w.z))
        throw FileError(path_, what + ": POSITION " + std::to_string(i) + " is not a finite number");
      world_pos[i] = glm::vec3(w);
    }
    // Normals the file lacks come from the geometry: on the split vertices above, the area-weighted
    // normal is the face normal. Zero or non-finite ones in a file that has normals are repaired
    // from the triangles around them.
    std::vector<glm::vec3> computed;
    auto fallback = [&](size_t i) {
      if (computed.empty()) computed = area_weighted_normals(world_pos, tris);
      return computed[i];
    };
    for (size_t i = 0; i < count; ++i) {
      glm::vec3 n;
      if (!nrm.empty()) {
        const glm::dvec3 file(nrm[3 * i], nrm[3 * i + 1], nrm[3 * i + 2]);
        const double file_len = glm::length(file);
        const glm::dvec3 d = normal_matrix * file;
        const double len = glm::length(d);
        if (!(std::isfinite(file_len) && file_len > 1e-12)) {
          n = fallback(i);
          ++normals_repaired_;
        } else if (len > 1e-9 * file_len) {
          n = glm::vec3(d / len);
        } else {
          n = fallback(i);  // a face a flattening node turned edge on: it covers no pixel
        }
      } else {
        n = fallback(i);
      }
      mesh_.positions.push_back(world_pos[i]);
      mesh_.normals.push_back(n);
      // Tangents move with the surface (the linear part, not the inverse transpose), are made
      // perpendicular to the normal again, and a mirror flips their handedness.
      glm::vec4 t(0.0f);  // w = 0: none from the file
      if (!tan.empty()) {
        glm::dvec3 d = glm::dmat3(world) * glm::dvec3(tan[4 * i], tan[4 * i + 1], tan[4 * i + 2]);
        d -= glm::dvec3(n) * glm::dot(glm::dvec3(n), d);
        double len = glm::length(d);
        if (std::isfinite(len) && len > 1e-12)
          t = glm::vec4(glm::vec3(d / len), float((tan[4 * i + 3] < 0 ? -1.0 : 1.0) * (mirrored ? -1.0 : 1.0)));
      }
      file_tangents_.push_back(t);
      mesh_.uvs.push_back(uv.empty() ? glm::vec2(0) : glm::vec2(float(uv[2 * i]), float(uv[2 * i + 1])));
    }
    uv_sets_.insert(uv_set);
    if (!uv.empty()) ++primitives_with_uvs_;
    else primitives_without_uvs_.add(what + " (" + uv_set + ")");
    if (!tan.empty()) ++primitives_with_tangents_;
    for (uint32_t i : tris) mesh_.indices.push_back(uint32_t(base) + i);

    // The merged mesh carries one texture: the first base-colour texture met in the scene.
    if (texture_image_ < 0 && texture) {
      const tinygltf::Texture& t = m_.textures[size_t(texture->index)];
      if (t.source >= 0 && size_t(t.source) < m_.images.size()) {
        texture_image_ = t.source;
        sampler_ = sampler(texture->index, t.sampler);
      }
    }
  }

  // How texture `texture` is sampled: its sampler's wrap modes and filters.
  Sampler sampler(int texture, int index) {
    Sampler out;
    if (index < 0) return out;  // no sampler: glTF's default, repeat
    if (size_t(index) >= m_.samplers.size())
      throw FileError(path_, "texture " + std::to_string(texture) + "'s sampler is sampler " + std::to_string(index) +
                                 ", but the file has " + std::to_string(m_.samplers.size()));
    // The enum value whose OpenGL number (gl_value) `value` is, as glTF writes them; -1
    // (undefined) gives `fallback`, and so does any other number, with a note.
    auto from_gl = [&](int value, auto fallback, int count, const char* name, const char* valid, const char* instead) {
      using E = decltype(fallback);
      for (int i = 0; i < count; ++i)
        if (gl_value(E(i)) == value) return E(i);
      if (value != -1)
        mesh_.notes.push_back("has sampler " + std::to_string(index) + " with " + name + " " + std::to_string(value) +
                              ", which glTF does not define (" + valid + "): " + instead + " there");
      return fallback;
    };
    const tinygltf::Sampler& s = m_.samplers[size_t(index)];
    const char* wraps = "10497 repeat, 33071 clamp to edge, 33648 mirrored repeat";
    out.s = from_gl(s.wrapS, Wrap::repeat, 3, "wrapS", wraps, "the texture repeats");
    out.t = from_gl(s.wrapT, Wrap::repeat, 3, "wrapT", wraps, "the texture repeats");
    out.mag = from_gl(s.magFilter, MagFilter::linear, 2, "magFilter", "9728 nearest, 9729 linear", "linear");
    out.min = from_gl(s.minFilter, MinFilter::linear_mipmap_linear, 6, "minFilter", "9728, 9729, 9984-9987", "trilinear");
    return out;
  }

  // Every node's world transform (its parents' times its own): a skin's joints may sit anywhere in
  // the tree, in the default scene or not. Computed once, when the first skin needs them.
  const std::vector<glm::dmat4>& globals() {
    if (!globals_.empty()) return globals_;
    std::vector<int> parent(m_.nodes.size(), -1);
    for (size_t n = 0; n < m_.nodes.size(); ++n)
      for (int c : m_.nodes[n].children)
        if (c >= 0 && size_t(c) < parent.size()) parent[size_t(c)] = int(n);
    globals_.resize(m_.nodes.size());
    std::vector<char> done(m_.nodes.size(), 0);
    for (size_t n = 0; n < m_.nodes.size(); ++n) {
      if (done[n]) continue;
      std::vector<int> chain;  // n and its ancestors up to one already done
      for (int k = int(n); k >= 0 && !done[size_t(k)]; k = parent[size_t(k)]) {
        chain.push_back(k);
        if (chain.size() > size_t(kMaxNodeDepth))  // a cycle, or a chain deeper than the walk allows
          throw FileError(path_, "nests nodes more than " + std::to_string(kMaxNodeDepth) + " deep above node " +
                                     std::to_string(n) + " (the limit, scene/gltf.h; a cycle?)");
      }
      const int above = parent[size_t(chain.back())];
      glm::dmat4 g = above >= 0 ? globals_[size_t(above)] : glm::dmat4(1.0);
      for (auto k = chain.rbegin(); k != chain.rend(); ++k) {
        std::string why;
        g = g * node_transform(m_.nodes[size_t(*k)], why);
        if (!why.empty()) throw FileError(path_, "node " + std::to_string(*k) + " has " + why);
        if (!is_finite(g)) throw FileError(path_, "node " + std::to_string(*k) + " has a non-finite transform");
        globals_[size_t(*k)] = g;
        done[size_t(*k)] = 1;
      }
    }
    return globals_;
  }

  // The primitive's material's base-colour texture, or null when it has none.
  const tinygltf::TextureInfo* base_color_texture(const tinygltf::Primitive& prim) const {
    if (prim.material < 0 || size_t(prim.material) >= m_.materials.size()) return nullptr;
    const tinygltf::TextureInfo& t = m_.materials[size_t(prim.material)].pbrMetallicRoughness.baseColorTexture;
    if (t.index >= 0 && size_t(t.index) >= m_.textures.size())  // it was ignored: the mesh came out untextured
      throw FileError(path_, "material " + std::to_string(prim.material) + "'s base-colour texture is texture " +
                                 std::to_string(t.index) + ", but the file has " + std::to_string(m_.textures.size()));
    return t.index >= 0 ? &t : nullptr;
  }

  // Its bytes, decoded when first read (scene/texture.h).
  Texture texture(int index) {
    const tinygltf::Image& img = m_.images[size_t(index)];
    std::string what = "mesh file '" + path_ + "': base-colour texture (image " + std::to_string(index) +
                       (img.uri.empty() || img.uri.rfind("data:", 0) == 0 ? std::string() : ", '" + img.uri + "'") + ")";
    if (img.image.empty()) {
      // tinygltf says why in a warning that names the image's file (it goes on without it).
      std::string why;
      std::istringstream lines(warnings_);
      for (std::string line; std::getline(lines, line);)
        if (!img.uri.empty() && line.find(img.uri) != std::string::npos) why += (why.empty() ? "" : "; ") + line;
      return Texture::unreadable(what + " could not be read" + (why.empty() ? " (it has no data)" : ": " + short_reason(why)));
    }
    return Texture(img.image, what);
  }

  const tinygltf::Model& m_;
  const std::string& path_;
  const std::string& warnings_;  // tinygltf's, one per line
  AccessorReader reader_;
  Mesh mesh_;
  std::set<int> on_path_;
  int texture_image_ = -1;
  Sampler sampler_;  // texture_image_'s
  std::vector<glm::dmat4> globals_;  // every node's world transform, once a skin needs them
  std::size_t unweighted_vertices_ = 0;  // skinned vertices whose weights are all zero
  int placements_hidden_ = 0;  // meshes placed by a node whose transform is singular (scaled to zero)
  int primitives_seen_ = 0, primitives_used_ = 0, primitives_with_uvs_ = 0, primitives_with_tangents_ = 0;
  PrimitiveList primitives_without_uvs_;  // "mesh 0 primitive 1 (TEXCOORD_0)"
  std::set<std::string> uv_sets_;         // the sets the drawn primitives read: Mesh::uv_sets
  PrimitiveList primitives_flat_;         // without normals
  std::size_t normals_repaired_ = 0;      // zero or non-finite in the file
  std::vector<glm::vec4> file_tangents_;
  std::size_t node_visits_ = 0;
  const io::Limits limits_ = io::limits();
};

// PNG bytes of `img` (8 bits per channel, values clamped to [0,1]) for embedding in a .glb.
std::vector<unsigned char> encode_png(const io::Image& img, const std::string& what) {
  try {
    return io::encode_image(img, "texture.png");
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(what + ": cannot encode the texture as PNG (" + e.what() + ")");
  }
}

// Appends `bytes` to the buffer (4-byte aligned, as accessors need) and adds a view onto them.
int add_view(tinygltf::Model& m, const void* bytes, size_t size, int target) {
  auto& data = m.buffers[0].data;
  data.resize((data.size() + 3) & ~size_t(3), 0);
  tinygltf::BufferView v;
  v.buffer = 0;
  v.byteOffset = data.size();
  v.byteLength = size;
  v.target = target;
  const auto* p = static_cast<const unsigned char*>(bytes);
  data.insert(data.end(), p, p + size);
  m.bufferViews.push_back(v);
  return int(m.bufferViews.size()) - 1;
}

int add_accessor(tinygltf::Model& m, int view, int component_type, int type, size_t count) {
  tinygltf::Accessor a;
  a.bufferView = view;
  a.byteOffset = 0;
  a.componentType = component_type;
  a.type = type;
  a.count = count;
  m.accessors.push_back(a);
  return int(m.accessors.size()) - 1;
}

}  // namespace

Mesh load_mesh(const std::string& path) {
  // Regular files only, at most 1 GiB (io/read_file.h): /dev/zero used to be read until memory ran out.
  const std::string text = io::read_file(path, "mesh file");
  std::vector<unsigned char> bytes(text.begin(), text.end());
  if (bytes.empty()) throw FileError(path, "is empty");
  tinygltf::TinyGLTF gltf;
  gltf.SetImageLoader(keep_image_bytes, nullptr);
  gltf.SetFsCallbacks({file_exists, path_as_is, read_whole_file, no_writes, nullptr});
  tinygltf::Model model;
  std::string err, warn;
  bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
  std::string base_dir = fs::path(path).parent_path().string();
  bool ok;
  if (binary) {
    ok = gltf.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), unsigned(bytes.size()), base_dir);
  } else {
    // A .gltf is JSON; anything else (an image, random bytes) is not a mesh.
    size_t i = 0;
    while (i < bytes.size() && std::isspace(bytes[i])) ++i;
    if (i == bytes.size() || bytes[i] != '{')
      throw FileError(path, "is neither a glTF JSON file (.gltf, starts with '{') nor a binary glTF (.glb, starts "
                            "with 'glTF')");
    ok = gltf.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<const char*>(bytes.data()),
                                  unsigned(bytes.size()), base_dir);
  }
  // The JSON: a .glb's first chunk (header 12 bytes, chunk length and type 8), a .gltf whole. A
  // file tinygltf refused is read for the extensions it requires only (a compressed file fails
  // in tinygltf with a reason that does not name its extension).
  auto json = [&]() -> std::pair<const char*, std::size_t> {
    if (!binary) return {text.data(), text.size()};
    uint32_t json_size = 0;
    if (bytes.size() >= 20) std::memcpy(&json_size, bytes.data() + 12, 4);
    if (bytes.size() < 20 || json_size > bytes.size() - 20) return {nullptr, 0};
    return {reinterpret_cast<const char*>(bytes.data()) + 20, json_size};
  };
  const auto [json_text, json_size] = json();
  if (!ok) {
    if (json_text) check_json(json_text, json_size, path, true);
    throw FileError(path, std::string("is not a valid ") + (binary ? "binary glTF" : "glTF") + " file (" +
                              (err.empty() ? "tinygltf gave no reason" : "tinygltf: " + short_reason(err)) + ")");
  }
  if (json_text) check_json(json_text, json_size, path);
  Mesh mesh = GltfLoader(model, path, warn).load();
  validate(mesh);
  return mesh;
}

void save_glb(const Mesh& m, const std::string& path) {
  validate(m);
  if (m.indices.empty()) throw std::runtime_error("cannot save mesh '" + m.name + "' to '" + path + "': it has no triangles");
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "shadenet";
  model.buffers.resize(1);

  tinygltf::Primitive prim;
  prim.mode = TINYGLTF_MODE_TRIANGLES;
  size_t n = m.positions.size();
  int pv = add_view(model, m.positions.data(), n * sizeof(glm::vec3), TINYGLTF_TARGET_ARRAY_BUFFER);
  int pa = add_accessor(model, pv, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, n);
  Bounds b = compute_bounds(m.positions);  // the stored bounds may be stale after an edit
  model.accessors[size_t(pa)].minValues = {b.min.x, b.min.y, b.min.z};
  model.accessors[size_t(pa)].maxValues = {b.max.x, b.max.y, b.max.z};
  prim.attributes["POSITION"] = pa;
  if (m.has_normals) {
    int nv = add_view(model, m.normals.data(), n * sizeof(glm::vec3), TINYGLTF_TARGET_ARRAY_BUFFER);
    prim.attributes["NORMAL"] = add_accessor(model, nv, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, n);
  }
  if (!m.tangents.empty()) {
    int tv = add_view(model, m.tangents.data(), n * sizeof(glm::vec4), TINYGLTF_TARGET_ARRAY_BUFFER);
    prim.attributes["TANGENT"] = add_accessor(model, tv, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC4, n);
  }
  if (m.has_uvs) {
    int uv = add_view(model, m.uvs.data(), n * sizeof(glm::vec2), TINYGLTF_TARGET_ARRAY_BUFFER);
    prim.attributes["TEXCOORD_0"] = add_accessor(model, uv, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, n);
  }
  int iv = add_view(model, m.indices.data(), m.indices.size() * 4, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  prim.indices =
      add_accessor(model, iv, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, m.indices.size());

  if (m.base_color) {
    std::vector<unsigned char> png = encode_png(*m.base_color, "cannot save mesh to '" + path + "'");
    tinygltf::Image image;
    image.mimeType = "image/png";
    image.bufferView = add_view(model, png.data(), png.size(), 0);
    model.images.push_back(image);
    tinygltf::Texture tex;
    tex.source = 0;
    if (!(m.base_color.sampler == Sampler())) {
      tinygltf::Sampler s;
      s.wrapS = gl_value(m.base_color.sampler.s);
      s.wrapT = gl_value(m.base_color.sampler.t);
      s.magFilter = gl_value(m.base_color.sampler.mag);
      s.minFilter = gl_value(m.base_color.sampler.min);
      model.samplers.push_back(s);
      tex.sampler = 0;
    }
    model.textures.push_back(tex);
    tinygltf::Material mat;
    mat.pbrMetallicRoughness.baseColorTexture.index = 0;
    mat.pbrMetallicRoughness.metallicFactor = 0.0;
    model.materials.push_back(mat);
    prim.material = 0;
  }
  model.buffers[0].data.resize((model.buffers[0].data.size() + 3) & ~size_t(3), 0);

  tinygltf::Mesh mesh;
  mesh.primitives.push_back(prim);
  model.meshes.push_back(mesh);
  tinygltf::Node node;
  node.mesh = 0;
  model.nodes.push_back(node);
  tinygltf::Scene scene;
  scene.nodes = {0};
  model.scenes.push_back(scene);
  model.defaultScene = 0;

  std::ostringstream glb;
  tinygltf::TinyGLTF gltf;
  if (!gltf.WriteGltfSceneToStream(&model, glb, false, true))
    throw std::runtime_error("cannot save mesh to '" + path + "': tinygltf could not serialise it");
  std::string bytes = glb.str();

  io::write_file_atomic(path, bytes, "mesh");
}

}  // namespace sn::scene
