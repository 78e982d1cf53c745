// Shared by the bindings that take networks (wrap_train.cpp, wrap_mlp_gl.cpp).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "lua/binding.h"
#include "nn/mlp.h"

namespace sn::lua {

// An Mlp, or a table of them, at `idx`; `where` names the option in errors ("sn.train option
// 'nets'").
std::vector<std::shared_ptr<nn::Mlp>> check_mlp_list(lua_State* L, int idx, const std::string& where);

}  // namespace sn::lua
