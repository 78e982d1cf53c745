// sn.fs.*: the few file-system calls results writers need and plain Lua lacks (creating
// folders, listing one, checking a path, reading and writing a file whole, a scratch folder, a
// lock), through
// std::filesystem and io/atomic_write rather than a shell or io.open; and sn.limits, the
// loaders' resource limits (io/limits.h).
#include <algorithm>
#include <filesystem>
#include <system_error>

#include "io/atomic_write.h"
#include "io/file_lock.h"
#include "io/limits.h"
#include "io/numbered_path.h"
#include "io/read_file.h"
#include "io/temp_dir.h"
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
  push_strings(L, names);
  return 1;
}

// sn.fs.read(path) -> content: the whole file (io::read_file: a FIFO, device or folder is an
// error naming it, where io.open would wait on a FIFO for ever).
int w_read(lua_State* L) {
  const std::string bytes = io::read_file(check_string(L, 1, "sn.fs.read path"));
  lua_pushlstring(L, bytes.data(), bytes.size());
  return 1;
}

// sn.fs.write(path, content) -> path: the whole file at once, never half-written (a temporary
// file, every write, flush, fsync and close checked, then renamed over `path`; folders created).
// On a full disk or any other failure the old file is untouched and the error names the cause.
int w_write(lua_State* L) {
  std::string path = check_string(L, 1, "sn.fs.write path");
  if (lua_type(L, 2) != LUA_TSTRING) throw Error("sn.fs.write content: string expected, got " + type_name_at(L, 2));
  std::size_t n = 0;
  const char* bytes = lua_tolstring(L, 2, &n);  // any bytes, NUL included
  io::write_file_atomic(path, std::string(bytes, n));
  lua_pushstring(L, path.c_str());
  return 1;
}

// sn.fs.write_all{ [path] = content, ... } -> the paths, sorted: each file as sn.fs.write writes
// one, flushed to the disk together (io::write_files_atomic: one syncfs instead of an fsync each).
int w_write_all(lua_State* L) {
  if (!lua_istable(L, 1)) throw Error("sn.fs.write_all: a table { [path] = content, ... } expected, got " + type_name_at(L, 1));
  std::vector<std::pair<std::string, std::string>> files;
  lua_pushnil(L);
  while (lua_next(L, 1)) {
    if (lua_type(L, -2) != LUA_TSTRING || lua_type(L, -1) != LUA_TSTRING)
      throw Error("sn.fs.write_all: every entry must be path = content (strings), got " + type_name_at(L, -2) + " = " +
                  type_name_at(L, -1));
    std::size_t n = 0;
    const char* bytes = lua_tolstring(L, -1, &n);
    files.emplace_back(lua_tostring(L, -2), std::string(bytes, n));
    lua_pop(L, 1);
  }
  std::sort(files.begin(), files.end());
  io::write_files_atomic(files);
  std::vector<std::string> paths;
  for (const auto& f : files) paths.push_back(f.first);
  push_strings(L, paths);
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

// sn.fs.remove_stale_temporaries(dir [, seconds = 60]) -> count: the temporary files that killed
// writers left in dir (".NAME.tmpDIGITS"), older than `seconds` (io::remove_stale_temporaries).
int w_remove_stale_temporaries(lua_State* L) {
  const std::string dir = check_string(L, 1, "sn.fs.remove_stale_temporaries folder");
  const double seconds = lua_isnoneornil(L, 2) ? 60.0 : check_number(L, 2, "sn.fs.remove_stale_temporaries seconds");
  if (!(seconds >= 0)) throw Error("sn.fs.remove_stale_temporaries seconds must be >= 0");
  lua_pushinteger(L, io::remove_stale_temporaries(dir, seconds));
  return 1;
}

// sn.fs.claim(dir, stem [, ext]) -> path: creates dir/stem-NNNN<ext> (a file; with no ext a
// folder) with the first free number, exclusively, so two processes never get the same one.
int w_claim(lua_State* L) {
  std::string dir = check_string(L, 1, "sn.fs.claim folder");
  std::string stem = check_string(L, 2, "sn.fs.claim stem");
  std::string path = lua_isnoneornil(L, 3) ? io::claim_numbered_dir(dir, stem)
                                            : io::claim_numbered_file(dir, stem, check_string(L, 3, "sn.fs.claim ext"));
  lua_pushstring(L, path.c_str());
  return 1;
}

// sn.fs.lock(path [, { shared = false, wait = true }]) -> Lock, or nil, "busy" when `wait` is false
// and another process holds a conflicting lock: an advisory flock on an existing file or folder,
// held until lock:release(), the Lock's collection or the process' end (however it ends).
// lock:held() -> true, or false and why where the file system keeps no locks (callers go on
// unlocked); lock:share() turns an exclusive lock into a shared one.
constexpr const char* kLock = "Lock";

struct Lock {
  io::FileLock lock;
  std::string path;
  bool shared = false;
};

int w_lock(lua_State* L) {
  const std::string path = check_string(L, 1, "sn.fs.lock path");
  bool shared = false, wait = true;
  if (!lua_isnoneornil(L, 2)) {
    Options o(L, 2, "sn.fs.lock", {"shared", "wait"});
    shared = o.boolean("shared", false);
    wait = o.boolean("wait", true);
  }
  auto l = std::make_shared<Lock>();
  l->lock = io::FileLock::acquire(path, shared ? io::FileLock::Mode::shared : io::FileLock::Mode::exclusive, wait);
  l->path = path;
  l->shared = shared;
  if (l->lock.state() == io::FileLock::State::busy) {
    lua_pushnil(L);
    lua_pushstring(L, "busy");
    return 2;
  }
  push(L, l, kLock);
  return 1;
}

int w_lock_held(lua_State* L) {
  auto& l = check<Lock>(L, 1, kLock);
  lua_pushboolean(L, l.lock.held());
  if (l.lock.held()) return 1;
  lua_pushstring(L, l.lock.why().empty() ? "released" : l.lock.why().c_str());
  return 2;
}

int w_lock_share(lua_State* L) {
  auto& l = check<Lock>(L, 1, kLock);
  l.lock.share();
  l.shared = true;
  return 0;
}

int w_lock_tostring(lua_State* L) {
  auto& l = check<Lock>(L, 1, kLock);
  const std::string s = "Lock(" + l.path + ", " + (l.lock.held() ? (l.shared ? "shared" : "exclusive") : "not held") + ")";
  lua_pushstring(L, s.c_str());
  return 1;
}

// sn.fs.tempdir([tag]) -> path of a new, empty folder TMPDIR/shadenet-TAG-XXXXXX, removed with
// its contents when the script's Lua state closes. The registry holds each one until then, so
// no collection removes a folder a script still writes into.
constexpr const char* kTempDirs = "shadenet.tempdirs";

int tempdir_gc(lua_State* L) {
  auto** dir = static_cast<io::TempDir**>(lua_touserdata(L, 1));
  delete *dir;
  *dir = nullptr;
  return 0;
}

int w_tempdir(lua_State* L) {
  std::string tag = lua_isnoneornil(L, 1) ? "script" : check_string(L, 1, "sn.fs.tempdir tag");
  lua_getfield(L, LUA_REGISTRYINDEX, kTempDirs);
  if (lua_isnil(L, -1)) {
    lua_pop(L, 1);
    lua_newtable(L);
    lua_pushvalue(L, -1);
    lua_setfield(L, LUA_REGISTRYINDEX, kTempDirs);
  }
  // The holder first, so a Lua error after the folder exists cannot lose it.
  auto** dir = static_cast<io::TempDir**>(lua_newuserdata(L, sizeof(io::TempDir*)));
  *dir = nullptr;
  lua_newtable(L);
  lua_pushcfunction(L, tempdir_gc);
  lua_setfield(L, -2, "__gc");
  lua_setmetatable(L, -2);
  lua_rawseti(L, -2, int(lua_objlen(L, -2)) + 1);
  lua_pop(L, 1);
  *dir = new io::TempDir(tag);
  lua_pushstring(L, (*dir)->path().c_str());
  return 1;
}

// The limits sn.limits reads and sets, by name.
struct LimitField {
  const char* name;
  std::uint64_t io::Limits::*field;
};
constexpr LimitField kLimitFields[] = {
    {"file_bytes", &io::Limits::file_bytes},         {"shader_bytes", &io::Limits::shader_bytes},
    {"image_pixels", &io::Limits::image_pixels},     {"image_channels", &io::Limits::image_channels},
    {"node_placements", &io::Limits::node_placements}, {"mesh_vertices", &io::Limits::mesh_vertices},
    {"mesh_indices", &io::Limits::mesh_indices},     {"dataset_cache_bytes", &io::Limits::dataset_cache_bytes},
};

void push_limits(lua_State* L, const io::Limits& l) {
  lua_createtable(L, 0, int(std::size(kLimitFields)));
  for (const LimitField& f : kLimitFields) {
    lua_pushnumber(L, double(l.*f.field));
    lua_setfield(L, -2, f.name);
  }
}

// sn.limits([{ file_bytes = n, shader_bytes = n, image_pixels = n, image_channels = n,
//              node_placements = n, mesh_vertices = n, mesh_indices = n, dataset_cache_bytes = n }])
//   -> the limits before
// the call (all of them, so sn.limits(old) puts them back). Process-wide; each a whole number
// in 1..2^53.
int w_limits(lua_State* L) {
  const io::Limits old = io::limits();
  if (!lua_isnoneornil(L, 1)) {
    Options o(L, 1, "sn.limits", {"file_bytes", "shader_bytes", "image_pixels", "image_channels", "node_placements",
                                  "mesh_vertices", "mesh_indices", "dataset_cache_bytes"});
    io::Limits next = old;
    for (const LimitField& f : kLimitFields) {
      if (!o.has(f.name)) continue;
      const long long v = o.integer(f.name);
      if (v < 1) throw Error(o.where(f.name) + " must be at least 1, got " + std::to_string(v));
      next.*f.field = std::uint64_t(v);
    }
    io::set_limits(next);
  }
  push_limits(L, old);
  return 1;
}

}  // namespace

void open_files(lua_State* L) {
  lua_pushcfunction(L, wrap<w_limits>);
  lua_setfield(L, -2, "limits");
  static const luaL_Reg fns[] = {SN_FN("mkdir", w_mkdir), SN_FN("list", w_list), SN_FN("exists", w_exists), SN_FN("read", w_read), SN_FN("write", w_write), SN_FN("write_all", w_write_all),
                                 SN_FN("claim", w_claim), SN_FN("tempdir", w_tempdir),
                                 SN_FN("remove_stale_temporaries", w_remove_stale_temporaries),
                                 SN_FN("lock", w_lock), {nullptr, nullptr}};
  static const luaL_Reg lock_methods[] = {SN_FN("held", w_lock_held), SN_FN("share", w_lock_share), {nullptr, nullptr}};
  define_box_type<Lock>(L, kLock, lock_methods, wrap<w_lock_tostring>);
  lua_newtable(L);
  luaL_register(L, nullptr, fns);
  lua_setfield(L, -2, "fs");
}

}  // namespace sn::lua
