// The terminal a long script talks to: sn.isatty(), sn.terminal_width(), and a gentle Ctrl-C
// (sn.catch_interrupt([on]) / sn.interrupted()). Without it SIGINT kills the process at once; a
// sweep that catches it finishes the runs in flight, writes them, and stops; a second Ctrl-C
// still stops at once.
#include <csignal>
#include <cstdio>
#include <sys/ioctl.h>
#include <unistd.h>

#include "lua/binding.h"
#include "lua/module.h"

namespace sn::lua {

namespace {

volatile std::sig_atomic_t g_interrupts = 0;

extern "C" void on_sigint(int) {
  g_interrupts = g_interrupts + 1;
  // The second Ctrl-C gets the default action back: the process ends now.
  std::signal(SIGINT, SIG_DFL);
  static const char msg[] = "\ninterrupt: finishing the runs in flight, then stopping (Ctrl-C again to stop now)\n";
  ssize_t ignored = write(STDERR_FILENO, msg, sizeof msg - 1);
  (void)ignored;
}

int stream_fd(lua_State* L, int idx) {
  if (lua_isnoneornil(L, idx)) return STDOUT_FILENO;
  std::string s = check_string(L, idx, "sn.isatty stream");
  return check_choice(s, {"stdin", "stdout", "stderr"}, "stream");
}

// sn.isatty([stream = "stdout"]) -> true when the stream is a terminal ("stdin", "stdout", "stderr")
int w_isatty(lua_State* L) {
  lua_pushboolean(L, isatty(stream_fd(L, 1)) == 1);
  return 1;
}

// sn.terminal_width() -> columns of the terminal on stdout, or nil when it is not one
int w_terminal_width(lua_State* L) {
  winsize ws{};
  if (isatty(STDOUT_FILENO) != 1 || ioctl(STDOUT_FILENO, TIOCGWINSZ, &ws) != 0 || ws.ws_col == 0) {
    lua_pushnil(L);
  } else {
    lua_pushinteger(L, ws.ws_col);
  }
  return 1;
}

// sn.catch_interrupt([on = true]): from now on the first Ctrl-C only sets a flag (see
// sn.interrupted()); sn.catch_interrupt(false) gives Ctrl-C its default action back (stop now).
int w_catch_interrupt(lua_State* L) {
  bool on = lua_isnoneornil(L, 1) ? true : lua_toboolean(L, 1) != 0;
  if (on) {
    g_interrupts = 0;
    std::signal(SIGINT, on_sigint);
  } else {
    std::signal(SIGINT, SIG_DFL);
  }
  return 0;
}

// sn.interrupted() -> true once Ctrl-C was pressed after sn.catch_interrupt()
int w_interrupted(lua_State* L) {
  lua_pushboolean(L, g_interrupts > 0);
  return 1;
}

}  // namespace

void open_terminal(lua_State* L) {
  static const luaL_Reg fns[] = {SN_FN("isatty", w_isatty), SN_FN("terminal_width", w_terminal_width),
                                 SN_FN("catch_interrupt", w_catch_interrupt),
                                 SN_FN("interrupted", w_interrupted), {nullptr, nullptr}};
  luaL_register(L, nullptr, fns);
}

}  // namespace sn::lua
