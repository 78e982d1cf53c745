// Live mode's event loop (shadenet --watch, and --window after a script that called
// sn.live.show): re-runs the script in the same Lua state when it, a module it required or a
// shader it used is saved; runs console lines from stdin; turns mouse and keys into views; and
// redraws only when one of those changed, sleeping in between.
//
// Test hooks (environment):
//   SHADENET_LIVE_SNAPSHOT=path   save each redrawn frame (the view, without overlays) to path;
//                                 a "%d" in it is replaced by the frame number
//   SHADENET_LIVE_SHOWN=path      save what the window shows (the view with its overlays: error,
//                                 progress, counter, labels) each time it is shown, headless too
//   SHADENET_LIVE_EXIT_AFTER=s    leave the loop after s seconds
#pragma once
#include <string>
#include <vector>

#include <lua.hpp>

namespace sn::live {

struct LiveOptions {
  std::string script;                // the script to (re)run; arguments are in the global `arg`
  std::vector<std::string> args;
  bool watch = true;                 // reload on saves and read the console; false: view only
  bool already_ran = false;          // the script ran once already (view-only mode)
  int width = 0, height = 0;         // headless: the view's size (--size; 0: the script's, else 640x480)
};

// Runs until the window is closed, Esc/Q, sn.live.quit(), end of a terminal's stdin or the
// SHADENET_LIVE_EXIT_AFTER time. Returns the exit status (0; 1 when the loop cannot start).
int run_live(lua_State* L, const LiveOptions& options);

}  // namespace sn::live
