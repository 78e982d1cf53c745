// Stopping Lua that runs too long in a live session. Plain Lua (`while true do end` in the script
// or at the console) gives the loop no chance to read its input, so while a RunGuard lives:
//
// - a count hook asks `check` every kCount instructions, at most every kCheckSeconds (a clock
//   read between), whether to stop; `check` reads the window's events and the Ctrl-C flag;
// - LuaJIT runs compiled loops (traces) without calling hooks at all. Its profiler, in line mode,
//   compiles an exit check into every trace and calls back every kProfileMs of CPU time; the
//   callback makes the next instruction call the hook. (The profiler is one per process: a
//   script's own jit.profile stops this one until the next guard.)
//
// When `check` gives a reason, the hook raises the Lua error "FILE:LINE: <reason>", and again at
// every later instruction until the guard ends, so a pcall inside the script cannot swallow it. Guards nest: an inner one does nothing. (LuaJIT delivers return hooks only without a count
// hook: a guarded run has none.)
#pragma once
#include <chrono>
#include <functional>
#include <string>

#include <lua.hpp>

namespace sn::live {

class RunGuard {
 public:
  using Check = std::function<const char*()>;  // why to stop now, or nullptr
  RunGuard(lua_State* L, Check check);
  ~RunGuard();
  RunGuard(const RunGuard&) = delete;
  RunGuard& operator=(const RunGuard&) = delete;
  static bool active();  // a guard lives (an inner one would do nothing)

  static constexpr int kCount = 10000;
  static constexpr double kCheckSeconds = 0.04;
  static constexpr int kProfileMs = 10;

 private:
  static void hook(lua_State* L, lua_Debug* ar);
  static void profiled(void* data, lua_State* L, int samples, int vmstate);
  void arm(int count);

  lua_State* L_;
  Check check_;
  bool outer_ = false;
  std::string stopping_;  // the reason once `check` gave one
  std::chrono::steady_clock::time_point last_check_;
};

}  // namespace sn::live
