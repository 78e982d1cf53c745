// Fuzz target: a sweep's run-file reader (scripts/lib/sweep.lua Sweep:record, through
// scripts/lib/json.lua): a resumed sweep reads every run file it finds, and a corrupt one must
// be reported and trained again, never enter the tables or stop the sweep.
// The reader is Lua, which the compiler does not instrument: a line hook feeds which lines of
// Lua ran to libFuzzer as extra coverage counters, so mutations that reach new lines are kept.
#include <exception>
#include <lua.hpp>
#include <string>

#include "fuzz_input.h"
#include "lua/module.h"

namespace {

// libFuzzer reads counters in this section after each input and clears them before the next.
__attribute__((section("__libfuzzer_extra_counters"))) uint8_t lua_line_counters[1 << 14];

void count_line(lua_State* L, lua_Debug* ar) {
  lua_getinfo(L, "S", ar);
  auto chunk = reinterpret_cast<uintptr_t>(ar->source);  // interned: one address per chunk
  std::size_t slot = (chunk * 0x9E3779B97F4A7C15ull ^ uint64_t(ar->currentline) * 0x85EBCA77ull) % sizeof lua_line_counters;
  if (lua_line_counters[slot] < 255) ++lua_line_counters[slot];
}

const char* const kDriver = R"lua(
local Sweep = require "lib.sweep"
local dir = ...
io.stderr = { write = function() end }   -- the reader's notices, thousands a second
local sweep = Sweep.new { dir = dir, runs = { { id = "run", config = { layers = 4, width = 6 } } } }
local run = sweep.runs[1]
return function(text)
  local f = assert(io.open(sweep:file(run), "wb"))
  f:write(text)
  f:close()
  local rec = sweep:record(run)
  if rec ~= nil and type(rec) ~= "table" then error("a record that is not a table") end
  for k, v in pairs(rec and type(rec.result) == "table" and rec.result or {}) do
    if type(k) == "string" and k:find("mse$") and type(v) == "number" and v < 0 then
      error("a negative " .. k .. " was accepted")
    end
  end
end
)lua";

lua_State* state() {
  static lua_State* L = [] {
    lua_State* s = luaL_newstate();
    luaL_openlibs(s);
    luaJIT_setmode(s, 0, LUAJIT_MODE_ENGINE | LUAJIT_MODE_OFF);  // hooks see every line
    sn::lua::install(s);
    lua_getglobal(s, "package");
    lua_pushstring(s, SHADENET_SOURCE_DIR "/scripts/?.lua");
    lua_setfield(s, -2, "path");
    lua_pop(s, 1);
    if (luaL_loadstring(s, kDriver) != 0) throw std::runtime_error(lua_tostring(s, -1));
    lua_pushstring(s, sn::fuzz::scratch_dir().c_str());
    if (lua_pcall(s, 1, 1, 0) != 0) throw std::runtime_error(lua_tostring(s, -1));
    lua_setfield(s, LUA_REGISTRYINDEX, "fuzz_read_run");
    lua_sethook(s, count_line, LUA_MASKLINE, 0);
    return s;
  }();
  return L;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  lua_State* L = state();
  lua_getfield(L, LUA_REGISTRYINDEX, "fuzz_read_run");
  lua_pushlstring(L, reinterpret_cast<const char*>(data), size);
  if (lua_pcall(L, 1, 0, 0) != 0) {
    // The reader reports and skips bad files; any error escaping it would stop a sweep.
    std::fprintf(stdout, "run-file reader raised: %s\n", lua_tostring(L, -1));
    __builtin_trap();
  }
  return 0;
}
