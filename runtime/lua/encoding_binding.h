// Shared by sn.mlp (wrap_mlp.cpp) and sn.encoding (wrap_encoding.cpp): input encodings as
// scripts write them, { uv = { "frequency", bands = 8 }, normal = "sh" }, and back.
#pragma once
#include <string>
#include <vector>

#include "lua/binding.h"
#include "nn/encoding.h"

namespace sn::lua {

// A network's named inputs and the raw columns each takes.
struct InputGroups {
  std::vector<std::string> names;
  std::vector<int> widths;
  int offset(std::size_t i) const;
  int total() const;
};
// The encodings table at `idx` (keys: input names; values: an encoding name, or a table with
// the name first and its options) for a network with inputs `groups`. Identity entries are
// dropped; the rest come back in column order, checked (nn::check). `what` names the option in
// errors ("sn.mlp option 'encoding'").
std::vector<nn::InputEncoding> check_encodings(lua_State* L, int idx, const InputGroups& groups, const std::string& what);
// Pushes { input = { "name", count = n, include_input = b, range = {lo, hi} }, ... } (the options
// each encoding takes), the form check_encodings reads.
void push_encodings(lua_State* L, const std::vector<nn::InputEncoding>& encodings);

}  // namespace sn::lua
