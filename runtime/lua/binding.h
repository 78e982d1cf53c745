// How C++ meets Lua. Every binding body runs inside `guarded`, which turns a C++ exception into
// a Lua error carrying the script's file:line (never luaL_error inside a catch: the longjmp
// would skip destructors). Objects are shared_ptr userdata with __gc and :release(); options
// tables are strict (unknown keys and enum strings are errors listing the valid ones).
#pragma once
#include <lua.hpp>

#include <algorithm>
#include <initializer_list>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/text.h"

namespace sn::lua {

// lua_absindex is Lua 5.2; LuaJIT speaks 5.1.
inline int absindex(lua_State* L, int i) { return (i > 0 || i <= LUA_REGISTRYINDEX) ? i : lua_gettop(L) + i + 1; }

// A script-facing error; thrown anywhere below a binding.
struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};
// An error whose message already starts with the script's file:line: `guarded` raises it as it is
// (each binding it unwinds through would prefix its own line again).
struct LocatedError : Error {
  using Error::Error;
};

// Lua called from C++ (a defined model's twin or bound, an encoding's or activation's Lua
// function, a training job's progress function) that calls back into C++ that calls Lua again
// nests C++ frames Lua cannot count: a twin that shades its own model recursed until the C stack
// ran out. One NestedCall per such call; past kMaxNestedCalls it throws "WHAT: more than N
// nested calls ...". While that error unwinds, pcall_or_throw passes it up unchanged.
constexpr int kMaxNestedCalls = 100;
class NestedCall {
 public:
  explicit NestedCall(const std::string& what);
  ~NestedCall();
  NestedCall(const NestedCall&) = delete;
  NestedCall& operator=(const NestedCall&) = delete;
  // True while the error of a call too deep is on its way out.
  static bool unwinding();
};

// Runs f(L); a C++ exception becomes a Lua error "file.lua:LINE: message".
int guarded(lua_State* L, int (*f)(lua_State*));
// The Lua thread (main or coroutine) of the binding running now, else `fallback`: C++ that calls
// back into Lua (a defined model's twin) uses it, never a thread saved earlier that may be dead.
lua_State* running_state(lua_State* fallback);
template <int (*F)(lua_State*)>
int wrap(lua_State* L) {
  return guarded(L, F);
}
// luaL_Reg-style table whose functions all go through `wrap`.
#define SN_FN(name, fn) {name, ::sn::lua::wrap<fn>}

// ---- objects ----
template <class T>
struct Box {
  std::shared_ptr<T> ptr;
};

// Creates the metatable `type` ("Buffer", "Program", ...) with `methods` as __index, __gc and a
// :release() method. `tostring_fn` may be null (prints "Buffer: 0x...").
void define_type(lua_State* L, const char* type, const luaL_Reg* methods, lua_CFunction tostring_fn = nullptr,
                 const luaL_Reg* metamethods = nullptr);

// Bytes an object owns outside its userdata (an image's pixels). Lua's collector sees only the
// userdata's few bytes: without telling it, a sweep's thousands of discarded renders pile up as
// garbage (Table 4.1 peaked at 2 GB, every fresh page zeroed by the kernel).
template <class T>
std::size_t owned_bytes(const T& t) {
  if constexpr (requires { t.pixels.size(); })
    return t.pixels.size() * sizeof(t.pixels[0]);
  else
    return 0;
}

// Tells the collector that `bytes` more are held by new userdata (owned_bytes). Stepping it as if
// they were Lua's own allocations made it run a full cycle every dozen renders (the Lua heap
// is a few MB, a render a few hundred KB): a fifth of a table's unseen-mesh evaluation. It
// collects once the owned bytes since its last full cycle reach 64 MB or the Lua heap's size.
void owned_allocated(lua_State* L, std::size_t bytes);

template <class T>
void push(lua_State* L, std::shared_ptr<T> p, const char* type) {
  if (p) owned_allocated(L, owned_bytes(*p));
  void* mem = lua_newuserdata(L, sizeof(Box<T>));
  new (mem) Box<T>{std::move(p)};
  luaL_getmetatable(L, type);
  if (lua_isnil(L, -1)) throw Error(std::string("internal: type ") + type + " not defined");
  lua_setmetatable(L, -2);
}

// Internal: the userdata at idx if its metatable is `type`, else null.
void* test_type(lua_State* L, int idx, const char* type);
std::string type_name_at(lua_State* L, int idx);

// Pushes a user definition's key (16 hex digits hashing `parts`, each length-prefixed), or nil
// for a built-in (`parts` empty): what sn.lighting.key and the like return, so an experiment's
// run records tell a changed definition from the one they were trained with.
// The parts the keys hash are what changes what a network sees: the GLSL every gl path runs,
// and where the cpu backend runs a Lua twin instead (an encoding's), that twin
// (function_fingerprint). A lighting model's twin and an activation's are oracles only (data is
// shaded on the GPU; the cpu backend runs an activation's translated GLSL), so their keys leave
// them out.
void push_definition_key(lua_State* L, const std::vector<std::string>& parts);
// What identifies the Lua function at idx in a key, the same in every run and process: its
// bytecode without debug information (string.dump(f, true): moving it to another line changes
// nothing) and the values it closes over, which the bytecode leaves out (a twin reading
// `local scale = 2` had one key for every scale): numbers, strings and booleans by value, Lua
// functions the same way in turn, tables and C functions by their type only (modules such as
// sn.vec3; a table of constants a twin reads is not looked into, nor are the globals it calls).
std::string function_fingerprint(lua_State* L, int idx);

template <class T>
std::shared_ptr<T>& check_box(lua_State* L, int idx, const char* type) {
  void* ud = test_type(L, idx, type);
  if (!ud) throw Error(std::string(type) + " expected, got " + type_name_at(L, idx));
  auto& p = static_cast<Box<T>*>(ud)->ptr;
  if (!p) throw Error(std::string("this ") + type + " was released; it can no longer be used");
  return p;
}
template <class T>
T& check(lua_State* L, int idx, const char* type) {
  return *check_box<T>(L, idx, type);
}
template <class T>
std::shared_ptr<T> check_shared(lua_State* L, int idx, const char* type) {
  return check_box<T>(L, idx, type);
}
// :release() for Box<T>: frees the C++ object once; later use is a clear error. The type name is
// the closure's upvalue: b.release(io.stdout) (a '.' for ':') must not free a FILE* as a Box.
template <class T>
int release(lua_State* L) {
  const char* type = lua_tostring(L, lua_upvalueindex(1));
  void* ud = test_type(L, 1, type);
  if (!ud)
    throw Error(std::string(type) + ":release: " + type + " expected, got " + type_name_at(L, 1) +
                " (call it with ':', obj:release())");
  static_cast<Box<T>*>(ud)->ptr.reset();
  return 0;
}
// __gc for Box<T>; Lua calls it on the type's own userdata only, but a script can reach it through
// getmetatable(obj).__gc, so it checks too.
template <class T>
int gc(lua_State* L) {
  if (void* ud = test_type(L, 1, lua_tostring(L, lua_upvalueindex(1)))) static_cast<Box<T>*>(ud)->~Box<T>();
  return 0;
}
// define_type for a Box<T>: wires __gc and :release to the right destructor.
template <class T>
void define_box_type(lua_State* L, const char* type, const luaL_Reg* methods, lua_CFunction tostring_fn = nullptr,
                     const luaL_Reg* metamethods = nullptr) {
  define_type(L, type, methods, tostring_fn, metamethods);
  luaL_getmetatable(L, type);
  lua_pushstring(L, type);
  lua_pushcclosure(L, gc<T>, 1);
  lua_setfield(L, -2, "__gc");
  lua_getfield(L, -1, "__index");
  if (lua_istable(L, -1)) {
    lua_pushstring(L, type);
    lua_pushcclosure(L, wrap<release<T>>, 1);
    lua_setfield(L, -2, "release");
  }
  lua_pop(L, 2);
}

// The script line calling the running C function and a space, "file.lua:12 " (empty when not
// known: called through pcall).
std::string caller_line(lua_State* L);
// lua_pcall under a NestedCall; an error becomes std::runtime_error("WHAT failed: message"),
// popped (a too-deep nesting's error goes up as it is, a LocatedError).
void pcall_or_throw(lua_State* L, int nargs, int nresults, const std::string& what);

// ---- plain values ----
double check_number(lua_State* L, int idx, const char* what);
long long check_integer(lua_State* L, int idx, const char* what);  // within +-2^53
int check_int32(lua_State* L, int idx, const char* what);           // within +-(2^31 - 1)
std::string check_string(lua_State* L, int idx, const char* what);
bool check_boolean(lua_State* L, int idx, const char* what);  // true or false, nothing else
// Every number of v finite, and with `as_float` within a float's range (it is stored as one): a
// NaN colour or direction spreads into every pixel or value computed from it. Else
// "WHAT: element I is nan; it must be finite" (no element number for a single value).
void check_finite(const std::vector<double>& v, const std::string& what, bool as_float = false);
// A random seed: a whole number in 0..max (2^53, where Lua numbers stop being whole; the
// shuffle's seeds are 32-bit). One rule for every seed of the API, none wrapped.
constexpr double kSeedMax = 9007199254740992.0, kSeed32Max = 4294967295.0;
uint64_t check_seed(double v, const std::string& what, double max = kSeedMax);
// The length n of the Lua list ({a, b, c}) at idx, a table: a key outside 1..n (a named option
// among the elements, an element after a nil) is an error naming it, "WHAT: a list expected
// ...", with `hint` in brackets after it. lua_objlen alone would drop such elements unseen.
int check_list(lua_State* L, int idx, const std::string& what, const std::string& hint = "");
// A Lua array of numbers ({1,2,3}); `n` = required length or -1.
std::vector<double> check_numbers(lua_State* L, int idx, const char* what, int n = -1);
// Picks `value` from `valid`; throws "unknown WHAT 'value' (valid: a, b, c)".
int check_choice(const std::string& value, std::initializer_list<const char*> valid, const char* what);
using io::join;  // io/text.h
// Pushes {"a", "b", ...}, a Lua array of the strings.
void push_strings(lua_State* L, const std::vector<std::string>& items);

// ---- option tables ----
// Reads a table argument of named options; unknown keys are an error listing the valid keys.
class Options {
 public:
  Options(lua_State* L, int idx, const char* what, std::initializer_list<const char*> valid);
  bool has(const char* key) const;
  double number(const char* key, double def) const;
  double number(const char* key) const;  // required
  long long integer(const char* key, long long def) const;
  long long integer(const char* key) const;
  int int32(const char* key, int def) const;  // an integer within +-(2^31 - 1)
  int int32(const char* key) const;           // required
  bool boolean(const char* key, bool def) const;
  std::string string(const char* key, const std::string& def) const;
  std::string string(const char* key) const;
  int choice(const char* key, std::initializer_list<const char*> valid, int def) const;
  std::vector<double> numbers(const char* key, int n = -1) const;
  std::vector<double> finite_numbers(const char* key, int n = -1, bool as_float = false) const;  // check_finite
  uint64_t seed(const char* key, uint64_t def, double max = kSeedMax) const;  // check_seed
  // Pushes the raw value (nil when absent) and returns its stack index (absolute).
  int push(const char* key) const;
  lua_State* state() const { return L_; }
  const char* what() const { return what_; }
  std::string where(const char* key) const;  // "sn.buffer option 'size'"

 private:
  lua_State* L_;
  int idx_;
  const char* what_;
};

}  // namespace sn::lua
