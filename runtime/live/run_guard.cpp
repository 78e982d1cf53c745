#include "live/run_guard.h"

#include <cstdio>

#include <luajit.h>

namespace sn::live {

namespace {
using Clock = std::chrono::steady_clock;
RunGuard* g_guard = nullptr;  // hooks and the profiler's callback take no user data we can trust
}  // namespace

RunGuard::RunGuard(lua_State* L, Check check) : L_(L), check_(std::move(check)) {
  if (g_guard) return;  // nested: the outer guard watches
  outer_ = true;
  g_guard = this;
  last_check_ = Clock::now();
  arm(kCount);
  char mode[16];
  std::snprintf(mode, sizeof mode, "li%d", kProfileMs);
  luaJIT_profile_start(L_, mode, profiled, this);
}

bool RunGuard::active() { return g_guard != nullptr; }

RunGuard::~RunGuard() {
  if (!outer_) return;
  luaJIT_profile_stop(L_);
  lua_sethook(L_, nullptr, 0, 0);
  g_guard = nullptr;
}

// Hooks are global to the Lua state in LuaJIT, whichever coroutine sets them.
void RunGuard::arm(int count) { lua_sethook(L_, hook, LUA_MASKCOUNT, count); }

// The profiler calls back from the interpreter (a trace has exited to it): the next instruction
// calls the hook. Its mask must already hold LUA_MASKCOUNT: the profiler puts the mask back as it
// was before the callback, but not the count.
void RunGuard::profiled(void* data, lua_State*, int, int) {
  auto* guard = static_cast<RunGuard*>(data);
  if (guard == g_guard) guard->arm(1);
}

void RunGuard::hook(lua_State* L, lua_Debug* ar) {
  RunGuard* guard = g_guard;
  if (!guard) return;
  if (ar->event != LUA_HOOKCOUNT) return;
  if (guard->stopping_.empty()) {
    guard->arm(kCount);  // after the profiler's count of one
    const auto now = Clock::now();
    if (std::chrono::duration<double>(now - guard->last_check_).count() < kCheckSeconds) return;
    guard->last_check_ = now;
    const char* why = guard->check_();
    if (!why) return;
    guard->stopping_ = why;
  }
  // From now on every instruction raises: a pcall that caught the error (in a loop of the
  // script's) gets it again at its very next instruction, outside that pcall.
  guard->arm(1);
  // The error names the line the script was on (level 0: the function the hook interrupted).
  lua_Debug here;
  char where[256] = "";
  if (lua_getstack(L, 0, &here) && lua_getinfo(L, "Sl", &here) && here.currentline > 0)
    std::snprintf(where, sizeof where, "%s:%d: ", here.short_src, here.currentline);
  lua_pushfstring(L, "%s%s", where, guard->stopping_.c_str());
  lua_error(L);  // nothing on this frame needs a destructor
}

}  // namespace sn::live
