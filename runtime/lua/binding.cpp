#include "lua/binding.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/hash.h"
#include "io/text.h"

namespace sn::lua {

namespace {
thread_local lua_State* g_running = nullptr;  // the thread of the innermost guarded call
thread_local int g_nested = 0;                // NestedCalls alive on this thread
thread_local bool g_too_deep = false;         // one of them threw; cleared when all have ended
}  // namespace

NestedCall::NestedCall(const std::string& what) {
  if (g_nested >= kMaxNestedCalls) {
    g_too_deep = true;
    throw Error(what + ": more than " + std::to_string(kMaxNestedCalls) +
                " nested calls from Lua into shadenet and back (does it call itself, e.g. its own model:shade?)");
  }
  ++g_nested;
}
NestedCall::~NestedCall() {
  if (--g_nested == 0) g_too_deep = false;
}
bool NestedCall::unwinding() { return g_too_deep; }

lua_State* running_state(lua_State* fallback) { return g_running ? g_running : fallback; }

void owned_allocated(lua_State* L, std::size_t bytes) {
  // Garbage held at most: 64 MB (a few hundred of a table's renders), or the Lua heap's size
  // where that is larger, so a big heap is traversed no more often than its own growth would
  // make the collector do.
  if (bytes == 0) return;
  const double limit = std::max(64.0 * (1 << 20), 1024.0 * lua_gc(L, LUA_GCCOUNT, 0));
  static const char kKey = 0;  // its address keys the count in the registry
  lua_pushlightuserdata(L, const_cast<char*>(&kKey));
  lua_rawget(L, LUA_REGISTRYINDEX);
  double since = lua_tonumber(L, -1) + double(bytes);
  lua_pop(L, 1);
  if (since >= limit) {
    lua_gc(L, LUA_GCCOLLECT, 0);
    since = 0;
  }
  lua_pushlightuserdata(L, const_cast<char*>(&kKey));
  lua_pushnumber(L, since);
  lua_rawset(L, LUA_REGISTRYINDEX);
}

int guarded(lua_State* L, int (*f)(lua_State*)) {
  lua_State* outer = g_running;
  g_running = L;
  bool failed = false;
  int results = 0;
  try {
    results = f(L);
  } catch (const LocatedError& e) {
    lua_pushstring(L, e.what());
    failed = true;
  } catch (const std::bad_alloc&) {  // its what() says only "std::bad_alloc"
    luaL_where(L, 1);
    lua_pushstring(L, "out of memory: the process could not allocate what this call needs (a smaller image or "
                      "dataset, fewer networks, or a higher memory limit, ulimit -v, would help)");
    lua_concat(L, 2);
    failed = true;
  } catch (const std::exception& e) {
    luaL_where(L, 1);
    lua_pushstring(L, e.what());
    lua_concat(L, 2);
    failed = true;
  }
  g_running = outer;
  // Outside the catch: every C++ destructor has run before the longjmp.
  return failed ? lua_error(L) : results;
}

std::string caller_line(lua_State* L) {
  luaL_where(L, 1);
  std::string where = lua_tostring(L, -1);
  lua_pop(L, 1);
  if (where.size() > 2 && where.compare(where.size() - 2, 2, ": ") == 0) where.pop_back(), where.back() = ' ';
  return where;
}

void pcall_or_throw(lua_State* L, int nargs, int nresults, const std::string& what) {
  bool too_deep = false;
  {
    NestedCall nested(what);
    if (lua_pcall(L, nargs, nresults, 0) == 0) return;
    too_deep = NestedCall::unwinding();  // read before `nested` ends: the outermost one clears it
  }
  std::string msg = lua_isstring(L, -1) ? lua_tostring(L, -1) : "(error object is not a string)";
  lua_pop(L, 1);
  // The innermost call's message names the line that nests; a hundred "failed:" around it would not help.
  if (too_deep) throw LocatedError(msg);
  throw std::runtime_error(what + " failed: " + msg);
}

void define_type(lua_State* L, const char* type, const luaL_Reg* methods, lua_CFunction tostring_fn,
                 const luaL_Reg* metamethods) {
  luaL_newmetatable(L, type);
  lua_pushstring(L, type);
  lua_setfield(L, -2, "__name");
  lua_newtable(L);
  for (const luaL_Reg* r = methods; r && r->name; ++r) {
    lua_pushcfunction(L, r->func);
    lua_setfield(L, -2, r->name);
  }
  lua_setfield(L, -2, "__index");
  if (tostring_fn) {
    lua_pushcfunction(L, tostring_fn);
    lua_setfield(L, -2, "__tostring");
  }
  for (const luaL_Reg* r = metamethods; r && r->name; ++r) {
    lua_pushcfunction(L, r->func);
    lua_setfield(L, -2, r->name);
  }
  lua_pop(L, 1);
}

void* test_type(lua_State* L, int idx, const char* type) {
  void* p = lua_touserdata(L, idx);
  if (!p || !lua_getmetatable(L, idx)) return nullptr;
  luaL_getmetatable(L, type);
  bool same = lua_rawequal(L, -1, -2);
  lua_pop(L, 2);
  return same ? p : nullptr;
}

namespace {

// The name under which package.loaded.shadenet (or a table of it: sn.lighting, sn.mesh, ...)
// holds the function at idx, or "".
std::string shadenet_name_of(lua_State* L, int idx) {
  idx = absindex(L, idx);
  const int top = lua_gettop(L);
  std::string found;
  lua_getfield(L, LUA_REGISTRYINDEX, "_LOADED");
  lua_getfield(L, -1, "shadenet");
  if (lua_istable(L, -1)) {
    const int sn = lua_gettop(L);
    lua_pushnil(L);
    while (found.empty() && lua_next(L, sn)) {
      if (lua_type(L, -2) == LUA_TSTRING) {
        const std::string key = lua_tostring(L, -2);
        if (lua_rawequal(L, -1, idx)) {
          found = "sn." + key;
        } else if (lua_istable(L, -1)) {
          const int sub = lua_gettop(L);
          lua_pushnil(L);
          while (found.empty() && lua_next(L, sub)) {
            if (lua_type(L, -2) == LUA_TSTRING && lua_rawequal(L, -1, idx))
              found = "sn." + key + "." + lua_tostring(L, -2);
            lua_pop(L, 1);
          }
        }
      }
      lua_pop(L, 1);
    }
  }
  lua_settop(L, top);
  return found;
}

}  // namespace

void push_definition_key(lua_State* L, const std::vector<std::string>& parts) {
  if (parts.empty()) {
    lua_pushnil(L);
    return;
  }
  io::Fnv1a f;
  for (const std::string& p : parts) {
    const uint64_t n = p.size();
    f.bytes(&n, sizeof n);
    f.text(p);
  }
  const std::string key = io::hex64(f.h);
  lua_pushlstring(L, key.data(), key.size());
}

namespace {

void fingerprint(lua_State* L, int idx, std::vector<const void*>& seen, std::string& out) {
  idx = absindex(L, idx);
  const void* self = lua_topointer(L, idx);
  if (auto at = std::find(seen.begin(), seen.end(), self); at != seen.end()) {  // a local function calling itself
    out += "(seen " + std::to_string(at - seen.begin()) + ")";
    return;
  }
  seen.push_back(self);
  // string.dump from the library itself (a script may have replaced the global).
  lua_getfield(L, LUA_REGISTRYINDEX, "_LOADED");
  lua_getfield(L, -1, "string");
  lua_getfield(L, -1, "dump");
  lua_pushvalue(L, idx);
  lua_pushboolean(L, 1);
  if (lua_pcall(L, 2, 1, 0) == 0 && lua_type(L, -1) == LUA_TSTRING) {
    std::size_t n = 0;
    const char* bytes = lua_tolstring(L, -1, &n);
    out += "function " + std::to_string(n) + ":";
    out.append(bytes, n);
  } else {
    out += "function (no bytecode)";
  }
  lua_pop(L, 3);
  for (int i = 1; lua_getupvalue(L, idx, i); ++i) {
    out += "\nupvalue " + std::to_string(i) + " ";
    switch (lua_type(L, -1)) {
      case LUA_TNUMBER: out += io::exact_text(lua_tonumber(L, -1)); break;
      case LUA_TSTRING: {
        std::size_t n = 0;
        const char* s = lua_tolstring(L, -1, &n);
        out += "string " + std::to_string(n) + ":";
        out.append(s, n);
        break;
      }
      case LUA_TBOOLEAN: out += lua_toboolean(L, -1) ? "true" : "false"; break;
      case LUA_TFUNCTION:
        if (lua_iscfunction(L, -1)) out += "C function";
        else fingerprint(L, -1, seen, out);
        break;
      default: out += luaL_typename(L, -1);
    }
    lua_pop(L, 1);
  }
}

}  // namespace

std::string function_fingerprint(lua_State* L, int idx) {
  std::vector<const void*> seen;
  std::string out;
  fingerprint(L, idx, seen, out);
  return out;
}

std::string type_name_at(lua_State* L, int idx) {
  // An object's constructor left uncalled (target = sn.lighting.phong): say how to call it.
  if (lua_type(L, idx) == LUA_TFUNCTION) {
    const std::string name = shadenet_name_of(L, idx);
    // Lighting models and mesh shapes have a default for every option; sn.mlp{} and the like do not.
    const bool defaults = name.rfind("sn.lighting.", 0) == 0 || name.rfind("sn.mesh.", 0) == 0;
    if (!name.empty())
      return "the function " + name + " (call it: " + name + " {...}" + (defaults ? ", or " + name + " {} for its defaults" : "") +
             ")";
  }
  if (lua_getmetatable(L, idx)) {
    lua_getfield(L, -1, "__name");
    if (lua_isstring(L, -1)) {
      std::string n = lua_tostring(L, -1);
      lua_pop(L, 2);
      return n;
    }
    lua_pop(L, 1);
    // A metatable without __name (LuaJIT's files: io.stdout) is named by its registry key, "FILE*".
    std::string found;
    lua_pushnil(L);
    while (found.empty() && lua_next(L, LUA_REGISTRYINDEX)) {
      if (lua_type(L, -2) == LUA_TSTRING && lua_rawequal(L, -1, -3)) found = lua_tostring(L, -2);
      lua_pop(L, 1);
    }
    if (!found.empty()) lua_pop(L, 1);  // lua_next left the key
    lua_pop(L, 1);
    if (!found.empty()) return found;
  }
  return luaL_typename(L, idx);
}

double check_number(lua_State* L, int idx, const char* what) {
  if (lua_type(L, idx) != LUA_TNUMBER)
    throw Error(std::string(what) + ": number expected, got " + type_name_at(L, idx));
  return lua_tonumber(L, idx);
}

long long check_integer(lua_State* L, int idx, const char* what) {
  double v = check_number(L, idx, what);
  if (std::floor(v) != v) throw Error(std::string(what) + ": integer expected, got " + io::number_text(v));
  // Beyond 2^53 a Lua number no longer holds every integer, and the cast would be undefined
  // for infinities: both are errors, never a wrapped or rounded count.
  if (!(std::abs(v) <= 9007199254740992.0))
    throw Error(std::string(what) + ": integer within -2^53..2^53 expected, got " + io::whole_text(v));
  return (long long)v;
}

uint64_t check_seed(double v, const std::string& what, double max) {
  if (!(v >= 0 && v <= max && v == std::floor(v)))
    throw Error(what + " must be a whole number in 0.." + (max == kSeedMax ? "2^53" : std::to_string(uint64_t(max))) +
                ", got " + io::whole_text(v));
  return uint64_t(v);
}

int check_int32(lua_State* L, int idx, const char* what) {
  long long v = check_integer(L, idx, what);
  // Symmetric, so that callers may add or subtract 1 (1-based indices) without overflow.
  if (v < -INT32_MAX || v > INT32_MAX)
    throw Error(std::string(what) + ": integer within +-(2^31 - 1) expected, got " + std::to_string(v));
  return int(v);
}

std::string check_string(lua_State* L, int idx, const char* what) {
  if (lua_type(L, idx) != LUA_TSTRING)
    throw Error(std::string(what) + ": string expected, got " + type_name_at(L, idx));
  std::size_t len = 0;
  const char* s = lua_tolstring(L, idx, &len);
  // A NUL would silently cut a path or a name short where C++ meets the file system.
  if (std::strlen(s) != len) throw Error(std::string(what) + ": the string holds a NUL byte (\\0)");
  return std::string(s, len);
}

void check_finite(const std::vector<double>& v, const std::string& what, bool as_float) {
  for (std::size_t i = 0; i < v.size(); ++i) {
    const bool finite = std::isfinite(v[i]), fits = !as_float || std::isfinite(float(v[i]));
    if (finite && fits) continue;
    throw Error(what + (v.size() > 1 ? ": element " + std::to_string(i + 1) : "") + " is " + io::number_text(v[i]) +
                (finite ? ", beyond a float's range (3.4e38)" : "") + "; it must be finite");
  }
}

bool check_boolean(lua_State* L, int idx, const char* what) {
  if (!lua_isboolean(L, idx)) throw Error(std::string(what) + ": boolean expected, got " + type_name_at(L, idx));
  return lua_toboolean(L, idx);
}

void push_strings(lua_State* L, const std::vector<std::string>& items) {
  lua_createtable(L, int(items.size()), 0);
  for (std::size_t i = 0; i < items.size(); ++i) {
    lua_pushlstring(L, items[i].data(), items[i].size());
    lua_rawseti(L, -2, int(i + 1));
  }
}

int check_list(lua_State* L, int idx, const std::string& what, const std::string& hint) {
  idx = absindex(L, idx);
  if (!lua_istable(L, idx)) throw Error(what + ": a list expected, got " + type_name_at(L, idx));
  const int n = int(lua_objlen(L, idx));  // a border: t[n] is not nil, t[n + 1] is
  int count = 0;
  lua_pushnil(L);
  while (lua_next(L, idx)) {
    const double k = lua_type(L, -2) == LUA_TNUMBER ? lua_tonumber(L, -2) : 0;
    if (k >= 1 && k <= n && k == std::floor(k)) ++count;
    else {
      const int t = lua_type(L, -2);
      std::string key = t == LUA_TSTRING ? "'" : "[";
      key.append(t == LUA_TSTRING ? lua_tostring(L, -2) : t == LUA_TNUMBER ? io::number_text(k) : luaL_typename(L, -2));
      key.append(t == LUA_TSTRING ? "'" : "]");
      if (t == LUA_TNUMBER && k > n && k == std::floor(k)) key += " after a nil at [" + std::to_string(n + 1) + "]";
      lua_pop(L, 2);
      throw Error(what + ": a list expected, got a table with the key " + key + (hint.empty() ? "" : " (" + hint + ")"));
    }
    lua_pop(L, 1);
  }
  for (int i = 1; count < n && i <= n; ++i) {  // a nil inside 1..n: the list has a hole
    lua_rawgeti(L, idx, i);
    const bool hole = lua_isnil(L, -1);
    lua_pop(L, 1);
    if (hole) throw Error(what + ": a list expected, got a nil at [" + std::to_string(i) + "] before [" + std::to_string(n) + "]");
  }
  return n;
}

std::vector<double> check_numbers(lua_State* L, int idx, const char* what, int n) {
  idx = absindex(L, idx);
  if (lua_type(L, idx) == LUA_TNUMBER && n <= 1) return {lua_tonumber(L, idx)};
  if (!lua_istable(L, idx))
    throw Error(std::string(what) + ": " +
                (n == 1 ? "a number" : n <= 0 ? "a number or a table of numbers" : "a table of " + std::to_string(n) + " numbers") +
                " expected, got " + type_name_at(L, idx));
  int len = check_list(L, idx, what);
  if (n >= 0 && len != n)
    throw Error(std::string(what) + ": " + std::to_string(n) + " numbers expected, got " + std::to_string(len));
  std::vector<double> v(len);
  for (int i = 1; i <= len; ++i) {
    lua_rawgeti(L, idx, i);
    if (lua_type(L, -1) != LUA_TNUMBER) {
      std::string t = type_name_at(L, -1);
      lua_pop(L, 1);
      throw Error(std::string(what) + ": element " + std::to_string(i) + " is " + t + ", not a number");
    }
    v[i - 1] = lua_tonumber(L, -1);
    lua_pop(L, 1);
  }
  return v;
}

int check_choice(const std::string& value, std::initializer_list<const char*> valid, const char* what) {
  int i = 0;
  std::vector<std::string> names;
  for (const char* v : valid) {
    if (value == v) return i;
    names.push_back(v);
    ++i;
  }
  throw Error(std::string("unknown ") + what + " '" + value + "' (valid: " + join(names) + ")");
}

Options::Options(lua_State* L, int idx, const char* what, std::initializer_list<const char*> valid)
    : L_(L), idx_(absindex(L, idx)), what_(what) {
  if (!lua_istable(L, idx_)) throw Error(std::string(what) + ": options table expected, got " + type_name_at(L, idx_));
  lua_pushnil(L);
  while (lua_next(L, idx_)) {
    lua_pop(L, 1);
    bool ok = false;
    if (lua_type(L, -1) == LUA_TSTRING) {
      std::string k = lua_tostring(L, -1);
      for (const char* v : valid) ok = ok || k == v;
      if (!ok) {
        std::vector<std::string> names(valid.begin(), valid.end());
        lua_pop(L, 1);
        throw Error(std::string(what) + ": unknown option '" + k + "' (valid: " + join(names) + ")");
      }
    } else {
      lua_pop(L, 1);
      throw Error(std::string(what) + ": options must be named (key = value)");
    }
  }
}

int Options::push(const char* key) const {
  lua_getfield(L_, idx_, key);
  return lua_gettop(L_);
}

bool Options::has(const char* key) const {
  push(key);
  bool r = !lua_isnil(L_, -1);
  lua_pop(L_, 1);
  return r;
}

std::string Options::where(const char* key) const { return std::string(what_) + " option '" + key + "'"; }

double Options::number(const char* key) const {
  if (!has(key)) throw Error(where(key) + " is required");
  return number(key, 0);
}
double Options::number(const char* key, double def) const {
  int i = push(key);
  double v = lua_isnil(L_, i) ? def : check_number(L_, i, where(key).c_str());
  lua_pop(L_, 1);
  return v;
}
long long Options::integer(const char* key) const {
  if (!has(key)) throw Error(where(key) + " is required");
  return integer(key, 0);
}
int Options::int32(const char* key) const {
  if (!has(key)) throw Error(where(key) + " is required");
  return int32(key, 0);
}
int Options::int32(const char* key, int def) const {
  int i = push(key);
  int v = lua_isnil(L_, i) ? def : check_int32(L_, i, where(key).c_str());
  lua_pop(L_, 1);
  return v;
}
long long Options::integer(const char* key, long long def) const {
  int i = push(key);
  long long v = lua_isnil(L_, i) ? def : check_integer(L_, i, where(key).c_str());
  lua_pop(L_, 1);
  return v;
}
uint64_t Options::seed(const char* key, uint64_t def, double max) const {
  const int i = push(key);
  const uint64_t v = lua_isnil(L_, i) ? def : check_seed(check_number(L_, i, where(key).c_str()), where(key), max);
  lua_pop(L_, 1);
  return v;
}
bool Options::boolean(const char* key, bool def) const {
  int i = push(key);
  const bool v = lua_isnil(L_, i) ? def : check_boolean(L_, i, where(key).c_str());
  lua_pop(L_, 1);
  return v;
}
std::string Options::string(const char* key) const {
  if (!has(key)) throw Error(where(key) + " is required");
  return string(key, "");
}
std::string Options::string(const char* key, const std::string& def) const {
  int i = push(key);
  std::string v;
  try {
    v = lua_isnil(L_, i) ? def : check_string(L_, i, where(key).c_str());
  } catch (...) {
    lua_pop(L_, 1);
    throw;
  }
  lua_pop(L_, 1);
  return v;
}
std::vector<double> Options::finite_numbers(const char* key, int n, bool as_float) const {
  std::vector<double> v = numbers(key, n);
  check_finite(v, where(key), as_float);
  return v;
}
int Options::choice(const char* key, std::initializer_list<const char*> valid, int def) const {
  if (!has(key)) return def;
  return check_choice(string(key), valid, where(key).c_str());
}
std::vector<double> Options::numbers(const char* key, int n) const {
  int i = push(key);
  std::vector<double> v;
  try {
    v = check_numbers(L_, i, where(key).c_str(), n);
  } catch (...) {
    lua_pop(L_, 1);
    throw;
  }
  lua_pop(L_, 1);
  return v;
}

}  // namespace sn::lua
