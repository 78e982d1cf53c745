#include "scene/gltf_deform.h"

#include <cmath>

#include <glm/gtc/type_ptr.hpp>

#include "scene/transform.h"

namespace sn::scene {

void add_morph_targets(const AccessorReader& reader, const tinygltf::Primitive& prim,
                       const std::vector<double>& weights, const std::string& what, const std::string& path,
                       std::vector<double>& pos, std::vector<double>& nrm, std::vector<double>& tan) {
  const std::size_t count = pos.size() / 3;
  for (std::size_t t = 0; t < prim.targets.size() && t < weights.size(); ++t) {
    const double w = weights[t];
    if (w == 0.0) continue;
    const std::string name = what + " morph target " + std::to_string(t);
    // A target's displacements are 3 components, also a tangent's (its w, the handedness, stays).
    auto add = [&](const char* attribute, std::vector<double>& base, std::size_t stride, const Storages& allowed) {
      auto it = prim.targets[t].find(attribute);
      if (it == prim.targets[t].end() || base.empty()) return;
      const std::vector<double> d = reader.read(it->second, 3, name + " " + attribute, allowed);
      if (d.size() != count * 3)
        throw FileError(path, name + ": " + attribute + " has " + std::to_string(d.size() / 3) +
                                  " elements, the primitive " + std::to_string(count));
      for (std::size_t i = 0; i < count; ++i)
        for (std::size_t c = 0; c < 3; ++c) base[i * stride + c] += w * d[i * 3 + c];
    };
    add("POSITION", pos, 3, storages::kMorphPosition);
    add("NORMAL", nrm, 3, storages::kDirection);
    add("TANGENT", tan, 4, storages::kDirection);
  }
}

std::vector<glm::dmat4> skin_matrices(const AccessorReader& reader, const tinygltf::Model& model, int skin,
                                      const tinygltf::Primitive& prim, const std::vector<glm::dmat4>& globals,
                                      std::size_t count, const std::string& what, const std::string& path,
                                      std::size_t& unweighted) {
  if (skin < 0 || std::size_t(skin) >= model.skins.size())
    throw FileError(path, what + " is placed with skin " + std::to_string(skin) + ", but the file has " +
                              std::to_string(model.skins.size()));
  const tinygltf::Skin& s = model.skins[std::size_t(skin)];
  const std::string skin_name = "skin " + std::to_string(skin);
  std::vector<double> inverse_bind;
  if (s.inverseBindMatrices >= 0) {
    inverse_bind = reader.read(s.inverseBindMatrices, 16, skin_name + " inverseBindMatrices", storages::kMatrix);
    if (inverse_bind.size() < s.joints.size() * 16)
      throw FileError(path, skin_name + " has " + std::to_string(s.joints.size()) + " joints but " +
                                std::to_string(inverse_bind.size() / 16) + " inverse bind matrices");
  }
  // Each joint's global(joint) * inverseBind, once.
  std::vector<glm::dmat4> joint(s.joints.size());
  for (std::size_t j = 0; j < s.joints.size(); ++j) {
    const int node = s.joints[j];
    if (node < 0 || std::size_t(node) >= globals.size())
      throw FileError(path, skin_name + " joint " + std::to_string(j) + " is node " + std::to_string(node) +
                                ", but the file has " + std::to_string(globals.size()));
    const glm::dmat4 ibm = inverse_bind.empty() ? glm::dmat4(1.0) : glm::make_mat4(&inverse_bind[16 * j]);
    joint[j] = globals[std::size_t(node)] * ibm;
  }

  std::vector<glm::dmat4> out(count, glm::dmat4(0.0));
  std::vector<double> total(count, 0.0);
  for (int set = 0;; ++set) {
    const std::string js = "JOINTS_" + std::to_string(set), ws = "WEIGHTS_" + std::to_string(set);
    auto j_it = prim.attributes.find(js), w_it = prim.attributes.find(ws);
    if (j_it == prim.attributes.end() || w_it == prim.attributes.end()) {
      if (set == 0)
        throw FileError(path, what + " is skinned (its node has " + skin_name + ") but lacks " +
                                  (j_it == prim.attributes.end() ? js : ws) + ", which glTF 2.0 requires of it");
      break;
    }
    const std::vector<double> joints = reader.read(j_it->second, 4, what + " " + js, storages::kJoints);
    const std::vector<double> weights = reader.read(w_it->second, 4, what + " " + ws, storages::kWeights);
    if (joints.size() != count * 4 || weights.size() != count * 4)
      throw FileError(path, what + ": " + js + " and " + ws + " have " + std::to_string(joints.size() / 4) + " and " +
                                std::to_string(weights.size() / 4) + " elements, POSITION " + std::to_string(count));
    for (std::size_t i = 0; i < count * 4; ++i) {
      const double w = weights[i];
      if (!(w > 0)) continue;  // zero (or a broken negative / NaN) weighs nothing
      if (!(joints[i] < double(joint.size())))
        throw FileError(path, what + ": " + js + " " + std::to_string(i / 4) + " names joint " +
                                  std::to_string((long long)joints[i]) + ", but " + skin_name + " has " +
                                  std::to_string(joint.size()));
      out[i / 4] += w * joint[std::size_t(joints[i])];
      total[i / 4] += w;
    }
  }
  for (std::size_t v = 0; v < count; ++v) {
    if (total[v] > 0) {
      out[v] /= total[v];  // exporters round the weights; the spec asks for a sum of 1
    } else {
      out[v] = glm::dmat4(1.0);
      ++unweighted;
    }
  }
  return out;
}

std::vector<char> apply_skin(const std::vector<glm::dmat4>& skins, std::vector<double>& pos,
                             std::vector<double>& nrm, std::vector<double>& tan) {
  std::vector<char> mirrors(skins.size());
  for (std::size_t i = 0; i < skins.size(); ++i) {
    const glm::dmat3 linear(skins[i]);
    const double det = glm::determinant(linear);
    mirrors[i] = det < 0;
    const glm::dvec4 p = skins[i] * glm::dvec4(pos[3 * i], pos[3 * i + 1], pos[3 * i + 2], 1.0);
    for (int k = 0; k < 3; ++k) pos[3 * i + k] = p[k];
    const glm::dmat3 normals = nrm.empty() ? glm::dmat3(0.0) : normal_matrix(linear);
    if (normals != glm::dmat3(0.0)) {  // a vertex collapsed to a line or a point keeps its normal
      const glm::dvec3 n = normals * glm::dvec3(nrm[3 * i], nrm[3 * i + 1], nrm[3 * i + 2]);
      for (int k = 0; k < 3; ++k) nrm[3 * i + k] = n[k];
    }
    if (!tan.empty()) {
      const glm::dvec3 t = linear * glm::dvec3(tan[4 * i], tan[4 * i + 1], tan[4 * i + 2]);
      for (int k = 0; k < 3; ++k) tan[4 * i + k] = t[k];
      if (det < 0) tan[4 * i + 3] = -tan[4 * i + 3];
    }
  }
  return mirrors;
}

}  // namespace sn::scene
