// sn.fs.*: the few file-system calls results writers need and plain Lua lacks (creating
// folders, listing one, checking a path), through std::filesystem rather than a shell.
#include <algorithm>
#include <filesystem>
#include <system_error>

#include "lua/binding.h"
#include "lua/module.h"

namespace sn::lua {

namespace {

namespace fs = std::filesystem;

// sn.fs.mkdir(path): creates the folder and its parents; fine when it exists. -> path
int w_mkdir(lua_State* L) {
  std::string path = check_string(L, 1, "sn.fs.mkdir path");
  std::error_code ec;
  fs::create_directories(path, ec);
  if (ec || !fs::is_directory(path)) throw Error("cannot create folder '" + path + "': " + ec.message());
  lua_pushstring(L, path.c_str());
  return 1;
}

// sn.fs.list(dir) -> sorted names of the entries in dir (not recursive); error when dir is not
// a folder.
int w_list(lua_State* L) {
  std::string dir = check_string(L, 1, "sn.fs.list folder");
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw Error("'" + dir + "' is not a folder");
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir, ec)) names.push_back(e.path().filename().string());
  if (ec) throw Error("cannot list '" + dir + "': " + ec.message());
  std::sort(names.begin(), names.end());
  lua_createtable(L, int(names.size()), 0);
  for (size_t i = 0; i < names.size(); ++i) {
    lua_pushstring(L, names[i].c_str());
    lua_rawseti(L, -2, int(i + 1));
  }
  return 1;
}

// sn.fs.exists(path) -> "file", "folder", "other" or nil
int w_exists(lua_State* L) {
  std::string path = check_string(L, 1, "sn.fs.exists path");
  std::error_code ec;
  auto st = fs::status(path, ec);
  if (ec || !fs::exists(st)) lua_pushnil(L);
  else lua_pushstring(L, fs::is_directory(st) ? "folder" : fs::is_regular_file(st) ? "file" : "other");
  return 1;
}

}  // namespace

void open_files(lua_State* L) {
  static const luaL_Reg fns[] = {SN_FN("mkdir", w_mkdir), SN_FN("list", w_list), SN_FN("exists", w_exists),
                                 {nullptr, nullptr}};
  lua_newtable(L);
  luaL_register(L, nullptr, fns);
  lua_setfield(L, -2, "fs");
}

}  // namespace sn::lua
