// Reading a glTF file's accessors with every check a malformed file could need (indices of views
// and buffers, byte ranges inside their buffers, component types, sparse values), for the loader
// (scene/gltf.cpp) and the vertex deformations it applies (scene/gltf_deform.h).
#pragma once
// Declarations only: Debian's libtinygltf.so carries the implementation (scene/gltf.cpp says why).
#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace sn::scene {

// Every load error names the file first.
struct FileError : std::runtime_error {
  FileError(const std::string& path, const std::string& reason)
      : std::runtime_error("mesh file '" + path + "': " + reason) {}
};

// One way an accessor may store its values: a component type, its integers normalised or not.
// `quantized`: allowed by KHR_mesh_quantization only, not by glTF 2.0 itself.
struct Storage {
  int type;
  bool normalized;
  bool quantized = false;
};
using Storages = std::vector<Storage>;

// What each accessor the loader reads may be stored as (glTF 2.0, 3.7.2.1, 3.7.3.3 and 3.11;
// the tables of KHR_mesh_quantization). Other types loaded as garbage: POSITION as unsigned int
// came out 1e9 wide, NORMAL as unsigned byte normalised (no negative directions) turned every
// normal.
//
// The quantized types are read whether or not the file lists KHR_mesh_quantization in
// extensionsUsed / extensionsRequired: their values decode the same either way, and viewers
// (three.js, Babylon.js) draw such files without the declaration, so refusing them would only
// lose meshes that show everywhere else.
namespace storages {
inline constexpr int kByte = TINYGLTF_COMPONENT_TYPE_BYTE, kUByte = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                     kShort = TINYGLTF_COMPONENT_TYPE_SHORT, kUShort = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                     kUInt = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT;
inline const Storages kPosition = {{kFloat, false},       {kByte, false, true},   {kByte, true, true},
                                   {kUByte, false, true}, {kUByte, true, true},   {kShort, false, true},
                                   {kShort, true, true},  {kUShort, false, true}, {kUShort, true, true}};
inline const Storages kTexcoord = {{kFloat, false},       {kUByte, true},        {kUShort, true},
                                   {kByte, false, true},  {kByte, true, true},   {kUByte, false, true},
                                   {kShort, false, true}, {kShort, true, true},  {kUShort, false, true}};
// NORMAL and TANGENT, and a morph target's NORMAL and TANGENT displacements: signed, normalised.
inline const Storages kDirection = {{kFloat, false}, {kByte, true, true}, {kShort, true, true}};
// A morph target's POSITION displacements: signed, as they move either way.
inline const Storages kMorphPosition = {
    {kFloat, false}, {kByte, false, true}, {kByte, true, true}, {kShort, false, true}, {kShort, true, true}};
// Never normalised: read as fractions, every index came out 0 and every triangle collapsed.
inline const Storages kIndex = {{kUByte, false}, {kUShort, false}, {kUInt, false}};
inline const Storages kJoints = {{kUByte, false}, {kUShort, false}};
inline const Storages kWeights = {{kFloat, false}, {kUByte, true}, {kUShort, true}};
inline const Storages kMatrix = {{kFloat, false}};
}  // namespace storages

// "unsigned byte", "short", ...; "" for a number glTF does not define.
inline const char* component_type_name(int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return "byte";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return "unsigned byte";
    case TINYGLTF_COMPONENT_TYPE_SHORT: return "short";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return "unsigned short";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return "unsigned int";
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return "float";
    default: return "";
  }
}

// Reads accessors with every check a malformed file could need: indices of views and
// buffers, byte ranges inside their buffers, component types the attribute may use.
class AccessorReader {
 public:
  // An accessor without a buffer view is all zeros (before sparse values); cap its size so a
  // corrupt count cannot ask for gigabytes.
  static constexpr size_t kMaxZeroFilled = size_t(1) << 26;

  AccessorReader(const tinygltf::Model& m, const std::string& path) : m_(m), path_(path) {}

  // `count` x `components` values as doubles, stored as one of `allowed` (storages:: above);
  // integer components of normalised accessors are mapped to [0,1] / [-1,1] as the glTF
  // specification says.
  std::vector<double> read(int index, int components, const std::string& what, const Storages& allowed) const {
    const tinygltf::Accessor& a = accessor(index, what);
    int n = tinygltf::GetNumComponentsInType(uint32_t(a.type));
    if (n != components)
      throw FileError(path_, what + " (accessor " + std::to_string(index) + ") has " + std::to_string(n) +
                                 " components, expected " + std::to_string(components));
    check_storage(a, what + " (accessor " + std::to_string(index) + ")", allowed);
    int csize = tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType));
    // Check every range before allocating: `count` comes from the file.
    const unsigned char* base = nullptr;
    size_t stride = 0;
    if (a.bufferView < -1)  // tinygltf's -1 is "absent" (zeros); anything lower is a broken file
      throw FileError(path_, what + " (accessor " + std::to_string(index) + ") has bufferView " +
                                 std::to_string(a.bufferView) + "; it must be a view's index or absent");
    if (a.bufferView >= 0) {
      const tinygltf::BufferView& bv = view(a.bufferView, what);
      size_t elem = size_t(csize) * size_t(components);
      stride = bv.byteStride ? bv.byteStride : elem;
      if (stride < elem)
        throw FileError(path_, what + ": buffer view " + std::to_string(a.bufferView) + " has byteStride " +
                                   std::to_string(stride) + ", smaller than one element (" + std::to_string(elem) +
                                   " bytes)");
      base = view_bytes(bv, a.bufferView, a.byteOffset, stride, elem, a.count, what);
    } else if (a.count > kMaxZeroFilled) {
      throw FileError(path_, what + " (accessor " + std::to_string(index) + ") has no buffer view and " +
                                 std::to_string(a.count) + " elements (at most " + std::to_string(kMaxZeroFilled) +
                                 " are zero-filled)");
    }
    std::vector<double> out(a.count * size_t(components), 0.0);
    if (base) {
      for (size_t i = 0; i < a.count; ++i)
        for (int c = 0; c < components; ++c)
          out[i * components + c] = component(base + i * stride + size_t(c) * csize, a.componentType, a.normalized);
    }
    if (a.sparse.isSparse) apply_sparse(a, components, csize, out, what);
    return out;
  }

  const tinygltf::Accessor& accessor(int index, const std::string& what) const {
    if (index < 0 || size_t(index) >= m_.accessors.size())
      throw FileError(path_, what + " refers to accessor " + std::to_string(index) + ", but the file has " +
                                 std::to_string(m_.accessors.size()));
    return m_.accessors[size_t(index)];
  }

 private:
  // Before the size: tinygltf gives 5130 (GL_DOUBLE, not glTF's) 8 bytes, and its values came
  // out NaN ("not a finite number" for POSITION, a NORMAL silently "repaired").
  void check_component_type(int type, const std::string& what) const {
    if (*component_type_name(type)) return;
    std::string valid;
    for (int t : {TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_SHORT,
                  TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
                  TINYGLTF_COMPONENT_TYPE_FLOAT})
      valid += (valid.empty() ? "" : ", ") + std::to_string(t) + " " + component_type_name(t);
    throw FileError(path_, what + " has unknown component type " + std::to_string(type) + " (valid: " + valid + ")");
  }

  void check_storage(const tinygltf::Accessor& a, const std::string& what, const Storages& allowed) const {
    check_component_type(a.componentType, what);
    // "normalized" on floats changes nothing (glTF forbids it; the values read the same), so they
    // count as float; on integers it changes every value.
    const bool normalized = a.normalized && a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT;
    for (const Storage& s : allowed)
      if (s.type == a.componentType && s.normalized == normalized) return;
    auto name = [](const Storage& s) {
      return std::string(component_type_name(s.type)) + (s.normalized ? " normalized" : "");
    };
    std::string core, quantized;
    for (const Storage& s : allowed) {
      std::string& list = s.quantized ? quantized : core;
      list += (list.empty() ? "" : ", ") + name(s);
    }
    throw FileError(path_, what + " is stored as " + std::to_string(a.componentType) + " " +
                               name({a.componentType, normalized}) + ", which glTF does not allow there (allowed: " +
                               core + (quantized.empty() ? "" : "; with KHR_mesh_quantization also " + quantized) +
                               ")");
  }

  static bool is_unsigned_integer(int t) {
    return t == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE || t == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
           t == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
  }

  const tinygltf::BufferView& view(int index, const std::string& what) const {
    if (index < 0 || size_t(index) >= m_.bufferViews.size())
      throw FileError(path_, what + " refers to buffer view " + std::to_string(index) + ", but the file has " +
                                 std::to_string(m_.bufferViews.size()));
    return m_.bufferViews[size_t(index)];
  }

  // Start of `count` elements of `elem` bytes every `stride` bytes at `offset` into view `bv`,
  // after checking the whole range lies inside the view and the view inside its buffer.
  const unsigned char* view_bytes(const tinygltf::BufferView& bv, int bv_index, size_t offset, size_t stride,
                                  size_t elem, size_t count, const std::string& what) const {
    if (bv.buffer < 0 || size_t(bv.buffer) >= m_.buffers.size())
      throw FileError(path_, what + ": buffer view " + std::to_string(bv_index) + " refers to buffer " +
                                 std::to_string(bv.buffer) + ", but the file has " + std::to_string(m_.buffers.size()));
    const auto& data = m_.buffers[size_t(bv.buffer)].data;
    if (bv.byteOffset > data.size() || bv.byteLength > data.size() - bv.byteOffset)
      throw FileError(path_, what + ": buffer view " + std::to_string(bv_index) + " (bytes " +
                                 std::to_string(bv.byteOffset) + ".." + std::to_string(bv.byteOffset + bv.byteLength) +
                                 ") reaches past the end of buffer " + std::to_string(bv.buffer) + " (" +
                                 std::to_string(data.size()) + " bytes)");
    // count is untrusted: compare before multiplying so a huge count cannot wrap around.
    // offset is untrusted too (a -1 in the file arrives as 2^64 - 1): no sum of it may wrap.
    if (offset > bv.byteLength)
      throw FileError(path_, what + ": byte offset " + std::to_string(offset) + " lies past the end of buffer view " +
                                 std::to_string(bv_index) + " (" + std::to_string(bv.byteLength) + " bytes)");
    if (count > 0 && (count - 1 > bv.byteLength / stride || elem > bv.byteLength - offset ||
                      (count - 1) * stride > bv.byteLength - offset - elem))
      throw FileError(path_, what + ": " + std::to_string(count) + " elements at byte offset " +
                                 std::to_string(offset) + " reach past the end of buffer view " +
                                 std::to_string(bv_index) + " (" + std::to_string(bv.byteLength) + " bytes)");
    return data.data() + bv.byteOffset + offset;
  }

  static double component(const unsigned char* p, int type, bool normalized) {
    switch (type) {
      case TINYGLTF_COMPONENT_TYPE_FLOAT: { float v; std::memcpy(&v, p, 4); return v; }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? p[0] / 255.0 : p[0];
      case TINYGLTF_COMPONENT_TYPE_BYTE: {
        double v = double(int8_t(p[0]));
        return normalized ? std::max(v / 127.0, -1.0) : v;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        uint16_t v; std::memcpy(&v, p, 2);
        return normalized ? v / 65535.0 : v;
      }
      case TINYGLTF_COMPONENT_TYPE_SHORT: {
        int16_t v; std::memcpy(&v, p, 2);
        return normalized ? std::max(v / 32767.0, -1.0) : v;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
        uint32_t v; std::memcpy(&v, p, 4);
        return normalized ? v / 4294967295.0 : v;
      }
      default: return std::nan("");
    }
  }

  void apply_sparse(const tinygltf::Accessor& a, int components, int csize, std::vector<double>& out,
                    const std::string& what) const {
    const auto& s = a.sparse;
    std::string w = what + " (sparse)";
    if (s.count < 0 || size_t(s.count) > a.count)
      throw FileError(path_, w + ": " + std::to_string(s.count) + " sparse values for " + std::to_string(a.count) +
                                 " elements");
    check_component_type(s.indices.componentType, w + " indices");
    int isize = tinygltf::GetComponentSizeInBytes(uint32_t(s.indices.componentType));
    if (!is_unsigned_integer(s.indices.componentType))
      throw FileError(path_, w + ": sparse indices must be unsigned integers");
    if (s.indices.byteOffset < 0 || s.values.byteOffset < 0)
      throw FileError(path_, w + ": a negative byteOffset");
    const auto& iv = view(s.indices.bufferView, w);
    const auto& vv = view(s.values.bufferView, w);
    size_t elem = size_t(csize) * components;
    const unsigned char* ip = view_bytes(iv, s.indices.bufferView, size_t(s.indices.byteOffset),
                                         size_t(isize), size_t(isize), size_t(s.count), w);
    const unsigned char* vp = view_bytes(vv, s.values.bufferView, size_t(s.values.byteOffset), elem,
                                         elem, size_t(s.count), w);
    for (int k = 0; k < s.count; ++k) {
      double target = component(ip + size_t(k) * isize, s.indices.componentType, false);
      if (!(target >= 0 && target < double(a.count)))
        throw FileError(path_, w + ": sparse index " + std::to_string((long long)target) + " outside 0.." +
                                   std::to_string(a.count - 1));
      for (int c = 0; c < components; ++c)
        out[size_t(target) * components + c] = component(vp + size_t(k) * elem + size_t(c) * csize, a.componentType,
                                                         a.normalized);
    }
  }

  const tinygltf::Model& m_;
  const std::string& path_;
};

}  // namespace sn::scene
