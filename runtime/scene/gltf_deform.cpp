#include "scene/gltf_deform.h"

namespace sn::scene {

void add_morph_targets(const AccessorReader& reader, const tinygltf::Primitive& prim,
                       const std::vector<double>& weights, const std::string& what, const std::string& path,
                       std::vector<double>& pos, std::vector<double>& nrm) {
  for (std::size_t t = 0; t < prim.targets.size() && t < weights.size(); ++t) {
    const double w = weights[t];
    if (w == 0.0) continue;
    const std::string name = what + " morph target " + std::to_string(t);
    auto add = [&](const char* attribute, std::vector<double>& base) {
      auto it = prim.targets[t].find(attribute);
      if (it == prim.targets[t].end() || base.empty()) return;
      const std::vector<double> d = reader.read(it->second, 3, name + " " + attribute);
      if (d.size() != base.size())
        throw FileError(path, name + ": " + attribute + " has " + std::to_string(d.size() / 3) +
                                  " elements, the primitive " + std::to_string(base.size() / 3));
      for (std::size_t i = 0; i < d.size(); ++i) base[i] += w * d[i];
    };
    add("POSITION", pos);
    add("NORMAL", nrm);
  }
}

}  // namespace sn::scene
