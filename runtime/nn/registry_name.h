// The names the network registries (activations, encodings) accept: lower-case letters, digits
// and _, at most 40, not starting with a digit -- what a Lua key, a GLSL identifier suffix and a
// checkpoint entry can all hold.
#pragma once
#include <cctype>
#include <cstdint>
#include <string>

namespace sn::nn {

inline bool valid_registry_name(const std::string& s) {
  if (s.empty() || s.size() > 40 || !(std::islower(uint8_t(s[0])) || s[0] == '_')) return false;
  for (char c : s)
    if (!(std::islower(uint8_t(c)) || std::isdigit(uint8_t(c)) || c == '_')) return false;
  return true;
}

}  // namespace sn::nn
