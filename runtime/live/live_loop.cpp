#include "live/live_loop.h"

#include <GLFW/glfw3.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <regex>
#include <set>
#include <sstream>
#include <utility>

#include "live/error_report.h"
#include "live/file_watcher.h"
#include "live/hud.h"
#include "live/input.h"
#include "live/repl.h"
#include "live/run_guard.h"
#include "gl/buffer.h"  // gl::finish
#include "gl/context.h"
#include "gl/program.h"
#include "gl/render_target.h"
#include "gl/shader_source.h"
#include "io/image.h"
#include "lua/binding.h"
#include "lua/interrupt.h"

namespace sn::live {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// The test hooks' file for picture `n`: every "%d" in `pattern` becomes n, the rest stays as it
// is (the pattern was a printf format: "50%off.png" lost its sign and "%s" crashed).
std::string numbered(const std::string& pattern, long n) {
  std::string path;
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    if (pattern.compare(i, 2, "%d") == 0) path += std::to_string(n), ++i;
    else path += pattern[i];
  }
  return path;
}

std::string read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return in ? ss.str() : std::string("\x01missing");
}

// The script's top-level locals (`local net = ...`), so that console lines can name them as the
// script does. The script runs with a call to this function appended (kLocalsCall): at its end
// every top-level local is in scope. (A return hook saw them too, but LuaJIT delivers return
// hooks only without the count hook that lets Esc stop a loop: run_guard.h.)
constexpr const char* kLocalsCall = "__shadenet_live_locals";
int g_locals_ref = LUA_NOREF;
int capture_locals(lua_State* L) {
  lua_Debug ar;
  if (!lua_getstack(L, 1, &ar)) return 0;  // level 1: the main chunk that called it
  lua_newtable(L);
  for (int i = 1;; ++i) {
    const char* name = lua_getlocal(L, &ar, i);
    if (!name) break;
    if (name[0] == '(') lua_pop(L, 1);  // temporaries such as "(for index)"
    else lua_setfield(L, -2, name);
  }
  if (g_locals_ref != LUA_NOREF) luaL_unref(L, LUA_REGISTRYINDEX, g_locals_ref);
  g_locals_ref = luaL_ref(L, LUA_REGISTRYINDEX);
  return 0;
}

// Loads the script with the call to capture_locals at its end, on its last line's own line (the
// lines keep their numbers). A script that ends in a top-level `return` gets the call before it;
// one that returns from inside a block, or that cannot take the call, runs as it is and the
// console keeps the locals of the last run that could.
bool load_with_locals(lua_State* L, std::string source, const std::string& chunkname) {
  if (!source.empty() && source[0] == '#') source.insert(0, "--");  // a #! line, as luaL_loadfile skips it
  std::string call = std::string(kLocalsCall) + "()";
  std::string with = source + "\n" + call + "\n";
  if (luaL_loadbuffer(L, with.data(), with.size(), chunkname.c_str()) == 0) return true;
  lua_pop(L, 1);
  static const std::regex last_return(R"((^|\n)return\b[^\n]*\s*$)");
  std::smatch m;
  if (std::regex_search(source, m, last_return)) {
    with = source;
    with.insert(size_t(m.position(0)) + m[1].length(), call + " ");
    if (luaL_loadbuffer(L, with.data(), with.size(), chunkname.c_str()) == 0) return true;
    lua_pop(L, 1);
  }
  return false;
}

int traceback(lua_State* L) {
  const char* msg = lua_tostring(L, 1);
  if (!msg) msg = lua_pushfstring(L, "(error object is a %s value)", luaL_typename(L, 1));
  luaL_traceback(L, L, msg, 1);
  return 1;
}

// The loop's wake-up call from the watcher and console threads: an empty GLFW event for a
// window, a condition variable headless.
class Waker {
 public:
  explicit Waker(bool window) : window_(window) {}
  void wake() {
    if (window_) {
      glfwPostEmptyEvent();
      return;
    }
    std::lock_guard<std::mutex> lock(mutex_);
    woken_ = true;
    cv_.notify_one();
  }
  // Sleeps until woken or `timeout` seconds (headless only; a window waits in poll()).
  void wait(double timeout) {
    std::unique_lock<std::mutex> lock(mutex_);
    cv_.wait_for(lock, std::chrono::duration<double>(timeout), [&] { return woken_; });
    woken_ = false;
  }

 private:
  bool window_;
  std::mutex mutex_;
  std::condition_variable cv_;
  bool woken_ = false;
};

// While one lives, Esc in the window and Ctrl-C at the terminal stop the Lua it runs with the
// error "FILE:LINE: interrupted by the user (...)" (run_guard.h, lua/interrupt.h).
struct Watch {
  Watch(lua_State* L, RunGuard::Check check) : guard(L, std::move(check)) {}
  lua::LiveInterrupt ctrl_c;  // made first, gone last: the handler outlives the hook
  RunGuard guard;
};

// How the user asked to quit: each asks first when console edits would be lost.
enum class QuitBy { key, esc, close, ctrl_d };

class Loop {
 public:
  Loop(lua_State* L, const LiveOptions& o) : L_(L), o_(o), ctx_(gl::current()), waker_(ctx_.windowed()) {}
  ~Loop() {
    if (live_ref_ != LUA_NOREF) {  // the loop's tick must not outlive it
      lua_rawgeti(L_, LUA_REGISTRYINDEX, live_ref_);
      lua_pushnil(L_);
      lua_setfield(L_, -2, "_tick");
      lua_pop(L_, 1);
    }
    gl::set_shader_file_observer(nullptr);
    gl::set_program_fallback(nullptr);
    if (target_ref_ != LUA_NOREF) luaL_unref(L_, LUA_REGISTRYINDEX, target_ref_);
    if (live_ref_ != LUA_NOREF) luaL_unref(L_, LUA_REGISTRYINDEX, live_ref_);
  }
  int run();

 private:
  bool push_live(const char* fn);  // pushes sn.live[fn]; false (nothing pushed) when missing
  bool call(const char* fn, int nargs, int nresults, std::string* error = nullptr);
  void run_script();
  void sync_view(bool force_reset);
  void update_watch_set();
  bool files_changed();
  void console();
  void take_requests();
  void redraw();
  void present();
  const char* tick(const std::string& text, double fraction);
  // Lua runs from here on until the result is gone: Esc and Ctrl-C stop it; `what` is shown in
  // the window's bar when it runs for long.
  std::unique_ptr<Watch> watch(const std::string& what);
  const char* check_run();
  const char* check_stop();
  // What the view is drawn at: the window's framebuffer, or headless the --size given (0 x 0:
  // the script's size, sn.live.show{ size = ... }, else 640 x 480).
  std::pair<int, int> view_size() const {
    return ctx_.windowed() ? ctx_.framebuffer_size() : std::pair<int, int>{o_.width, o_.height};
  }
  static int tick_thunk(lua_State* L);
  void end_busy();
  void update_probe();
  void prompt() {
    if (stdin_ && console_) stdin_->prompt(console_->prompt());
  }
  void actions();
  void ask_quit(QuitBy by);
  void update_binds();
  void set_status();
  void report(const std::string& message);

  lua_State* L_;
  LiveOptions o_;
  gl::Context& ctx_;
  Waker waker_;
  Input input_;
  Hud hud_;
  std::unique_ptr<FileWatcher> watcher_;
  std::unique_ptr<StdinReader> stdin_;
  std::unique_ptr<Console> console_;
  int live_ref_ = LUA_NOREF, target_ref_ = LUA_NOREF;

  std::set<std::string> shader_files_;           // every shader file a program read
  std::vector<std::string> fallback_errors_;     // broken programs replaced by their last good build
  std::map<std::string, std::string> contents_;  // watched file -> content when last run
  std::vector<std::string> watched_;
  bool missed_save_ = false;  // a file changed between its run and its watch: reload

  std::string script_error_, frame_error_, shader_error_, last_reported_, title_;
  std::string snapshot_, shown_path_;
  long shown_count_ = 0;
  bool present_due_ = false;
  Clock::time_point last_tick_{}, ticked_at_{};
  std::string running_;  // what the outermost watch runs ("examples/x.lua", "the console line")
  Clock::time_point running_since_{}, running_shown_{};
  Clock::time_point busy_since_{}, busy_ended_{};  // when the last progress bar came and went
  bool stopped_ = false;            // the user stopped that work (Esc, Ctrl-C, closing the window)
  Clock::time_point started_{};     // of the session (SHADENET_LIVE_EXIT_AFTER)
  static constexpr std::chrono::milliseconds kLateEsc{2000};
  double exit_after_ = 0, frame_ms_ = 0, view_error_scale_ = 0.25;
  bool dirty_ = true, quit_ = false, prompt_after_frame_ = false;
  std::string shown_title_;
  long frame_ = 0, probed_frame_ = 0;
  std::array<double, 9> initial_{};  // eye, target, light dir of the script's view
  std::string initial_mode_;
  double initial_fov_ = 0;
  std::pair<int, int> drawn_size_{0, 0};
  bool reload_pending_ = false;
  Clock::time_point reload_at_;
  static constexpr std::chrono::milliseconds kSettle{40};
  bool unsaved_ = false;  // console edits since the last run: Q asks before they are lost
  Clock::time_point confirm_until_{};
  static constexpr std::chrono::seconds kConfirm{3};
};

bool Loop::push_live(const char* fn) {
  lua_rawgeti(L_, LUA_REGISTRYINDEX, live_ref_);
  lua_pushstring(L_, fn);
  lua_rawget(L_, -2);  // raw: sn.live's __index raises an error for a missing name, outside any pcall here
  lua_remove(L_, -2);
  if (lua_isfunction(L_, -1)) return true;
  lua_pop(L_, 1);
  return false;
}

// Calls sn.live[fn] with the nargs values on the stack; on error returns false with the message.
bool Loop::call(const char* fn, int nargs, int nresults, std::string* error) {
  if (!push_live(fn)) {
    lua_pop(L_, nargs);
    if (error) *error = std::string("internal: sn.live.") + fn + " is missing";
    return false;
  }
  lua_insert(L_, -nargs - 1);
  lua_pushcfunction(L_, traceback);
  lua_insert(L_, -nargs - 2);
  int base = lua_gettop(L_) - nargs - 2;
  if (lua_pcall(L_, nargs, nresults, base + 1) != 0) {
    if (error) *error = lua_tostring(L_, -1) ? lua_tostring(L_, -1) : "(error)";
    lua_settop(L_, base);
    return false;
  }
  lua_remove(L_, base + 1);  // the traceback function; the results stay
  return true;
}

// The terminal gets the overlay's text (headline, source line, context), then the traceback.
void Loop::report(const std::string& message) {
  // Closing the window stops the work it was waiting on: the error that stops is no news.
  if (message == last_reported_ || quit_) return;
  if (!message.empty()) {
    ErrorReport r = report_error(message);
    std::string text;
    for (const auto& l : report_lines(r, size_t(-1))) text += (text.empty() ? "" : "\n") + l;
    fprintf(stderr, "[live] error: %s\n%s", text.c_str(), r.traceback.empty() ? "" : (r.traceback + "\n").c_str());
  } else {
    fprintf(stderr, "[live] fixed: the error is gone\n");
  }
  last_reported_ = message;
  hud_.set_error(message);
  present_due_ = true;  // the overlay shows or clears over the picture as it is
  fflush(stderr);
}

void Loop::set_status() {
  // The error a user must see first: the script's, then the frame's, then a shader's.
  std::string err = !script_error_.empty() ? script_error_ : !frame_error_.empty() ? frame_error_ : shader_error_;
  report(err);
  char ms[32] = "";
  if (frame_ms_ > 0) snprintf(ms, sizeof ms, " · %.1f ms", frame_ms_);
  std::string title = (err.empty() ? "" : "ERROR " + report_error(err).headline + " | ") + (title_.empty() ? "shadenet" : title_) + ms;
  if (title != shown_title_) ctx_.set_title(title), shown_title_ = title;
  lua_pushstring(L_, title.c_str());
  lua_pushstring(L_, err.c_str());
  call("_set_status", 2, 0);
}

void Loop::update_watch_set() {
  if (!watcher_) return;
  std::vector<std::string> files = {o_.script};
  if (call("_watched", 0, 1) && lua_istable(L_, -1)) {
    for (int i = 1; i <= int(lua_objlen(L_, -1)); ++i) {
      lua_rawgeti(L_, -1, i);
      if (const char* s = lua_tostring(L_, -1)) files.push_back(s);
      lua_pop(L_, 1);
    }
  }
  lua_settop(L_, 0);
  files.insert(files.end(), shader_files_.begin(), shader_files_.end());
  if (files == watched_) return;
  watched_ = files;
  watcher_->watch(files);  // in place on return: every later save is seen
  // A save between the run's read and the watch is seen here: the run read what contents_ holds
  // (the script: run_script's own read; a file first watched now: as it is now).
  for (const auto& f : files) {
    std::string now = read_all(f);
    if (contents_.count(f) && contents_[f] != now) missed_save_ = true;
    contents_[f] = now;
  }
}

// True when a watched file now differs from what the last run read (a save that rewrote the
// same bytes is no reason to reload).
bool Loop::files_changed() {
  if (!watcher_) return false;
  bool any = std::exchange(missed_save_, false);
  std::set<std::string> changed;
  for (const auto& f : watcher_->take_changed()) changed.insert(f);
  if (changed.empty()) return any;
  for (const auto& f : watched_) {
    std::error_code ec;
    std::string canon = std::filesystem::weakly_canonical(std::filesystem::absolute(f), ec).string();
    if (!changed.count(canon)) continue;
    std::string now = read_all(f);
    if (now != contents_[f]) contents_[f] = now, any = true;
  }
  return any;
}

void Loop::run_script() {
  auto t0 = Clock::now();
  for (const auto& f : watched_) contents_[f] = read_all(f);
  // A syntax error changes nothing: the last good state stays, networks included. The files
  // are still watched (the first run may be the broken one), so the fix is seen.
  std::string source = read_all(o_.script);
  contents_[o_.script] = source;  // what this run reads (update_watch_set compares with it)
  bool empty = source.find_first_not_of(" \t\r\n") == std::string::npos;
  if (empty || luaL_loadfile(L_, o_.script.c_str()) != 0) {
    // An empty file is a save in progress (truncated, not yet written) or a mistake, never a good run.
    script_error_ = !empty ? lua_tostring(L_, -1)
                   : source == "\x01missing" ? o_.script + ": cannot read the script (missing?); waiting for it"
                                             : o_.script + ": the script is empty; waiting for the next save";
    lua_settop(L_, 0);
    update_watch_set();
    set_status();
    return;
  }
  // The same script with the call that takes its locals, where it can have one.
  if (load_with_locals(L_, source, "@" + o_.script)) lua_remove(L_, -2);
  // Kept networks go back to their snapshot (console edits are gone); the view's size goes to Lua
  // for what the run shows before the first frame (a screenshot taken by the script itself).
  auto [vw, vh] = view_size();
  lua_pushinteger(L_, vw), lua_pushinteger(L_, vh);
  call("_begin_run", 2, 0);
  unsaved_ = false;
  fallback_errors_.clear();
  lua_pushcfunction(L_, traceback);
  lua_insert(L_, -2);
  for (const auto& a : o_.args) lua_pushstring(L_, a.c_str());
  if (g_locals_ref != LUA_NOREF) luaL_unref(L_, LUA_REGISTRYINDEX, g_locals_ref), g_locals_ref = LUA_NOREF;
  lua_pushcfunction(L_, capture_locals);
  lua_setglobal(L_, kLocalsCall);
  bool ok = false;
  {
    auto watching = watch(o_.script);
    ok = lua_pcall(L_, int(o_.args.size()), 0, 1) == 0;
  }
  lua_pushnil(L_);
  lua_setglobal(L_, kLocalsCall);
  if (ok && g_locals_ref != LUA_NOREF) {  // the console sees this run's locals from now on
    lua_rawgeti(L_, LUA_REGISTRYINDEX, g_locals_ref);
    luaL_unref(L_, LUA_REGISTRYINDEX, g_locals_ref);
    g_locals_ref = LUA_NOREF;
    call("_set_locals", 1, 0);
  }
  script_error_ = ok ? "" : lua_tostring(L_, -1) ? lua_tostring(L_, -1) : "(error)";
  lua_settop(L_, 0);
  lua_pushboolean(L_, ok);
  call("_end_run", 1, 0);
  shader_error_ = fallback_errors_.empty() ? "" : fallback_errors_.front();
  update_watch_set();
  if (ok) {
    fprintf(stderr, "[live] ran %s in %.0f ms\n", o_.script.c_str(), seconds_since(t0) * 1e3);
    sync_view(false);
    dirty_ = true;
  }
  take_requests();
  end_busy();
  update_binds();
  set_status();
}

// Takes the script's camera, light and mode into the controls. What the user moved survives a
// reload unless the script now asks for a different camera, light or mode.
void Loop::sync_view(bool force_reset) {
  if (!call("_initial_view", 0, 6)) return;
  if (lua_isnil(L_, 1)) return (void)lua_settop(L_, 0);
  auto vec = [&](int idx, double* out) {
    for (int i = 0; i < 3; ++i) {
      lua_rawgeti(L_, idx, i + 1);
      out[i] = lua_tonumber(L_, -1);
      lua_pop(L_, 1);
    }
  };
  std::array<double, 9> v{};
  vec(1, &v[0]), vec(2, &v[3]), vec(4, &v[6]);
  double fov = lua_tonumber(L_, 3);
  std::string mode = lua_tostring(L_, 5) ? lua_tostring(L_, 5) : "network";
  lua_settop(L_, 0);
  // Each part resets only when the script changed that part: a new light keeps the mode the
  // user picked, a new mode keeps the camera the user moved.
  auto differs = [&](int from, int to) { return !std::equal(v.begin() + from, v.begin() + to, initial_.begin() + from); };
  bool reset_camera = force_reset || differs(0, 6) || fov != initial_fov_;
  bool reset_light = force_reset || differs(6, 9);
  bool reset_mode = force_reset || mode != initial_mode_;
  initial_ = v, initial_mode_ = mode, initial_fov_ = fov;
  Mode m = Mode::network;
  parse_mode(mode, m);
  Orbit cam = Orbit::from({v[3], v[4], v[5]}, {v[0], v[1], v[2]});
  Orbit light = Orbit::from({0, 0, 0}, {v[6], v[7], v[8]});
  light.distance = 1;
  input_.set_initial(cam, fov, light, m, {reset_camera, reset_light, reset_mode});
}

void Loop::take_requests() {
  if (!call("_take_requests", 0, 3)) return;
  if (lua_toboolean(L_, 1)) quit_ = true;
  if (lua_toboolean(L_, 2)) dirty_ = true;
  if (lua_istable(L_, 3)) {  // sn.live.set_view{...}: as if the keys and mouse had done it
    ViewState& v = input_.view();
    auto vec = [&](const char* key, std::array<double, 3>& out) {
      lua_getfield(L_, 3, key);
      bool has = lua_istable(L_, -1);
      for (int i = 0; has && i < 3; ++i) {
        lua_rawgeti(L_, -1, i + 1);
        out[size_t(i)] = lua_tonumber(L_, -1);
        lua_pop(L_, 1);
      }
      lua_pop(L_, 1);
      return has;
    };
    lua_getfield(L_, 3, "mode");
    if (const char* m = lua_tostring(L_, -1)) parse_mode(m, v.mode);
    lua_pop(L_, 1);
    std::array<double, 3> eye{}, target{}, light{};
    if (vec("eye", eye) && vec("target", target)) {
      v.camera = Orbit::from(target, eye);
      lua_getfield(L_, 3, "fov");
      v.fov = lua_tonumber(L_, -1);
      lua_pop(L_, 1);
      v.camera_moved = true;
    }
    if (vec("light", light)) {
      v.light = Orbit::from({0, 0, 0}, light);
      v.light.distance = 1;
      v.light_moved = true;
    }
    dirty_ = true;
  }
  lua_settop(L_, 0);
}

void Loop::console() {
  if (!stdin_) return;
  std::string line;
  while (stdin_->take(line)) {
    bool ok = false, ran = false;
    call("_line_begin", 0, 0);  // what a line that fails puts back
    {
      auto watching = watch("the console line");
      ran = console_->execute(line, &ok);
    }
    if (!ran) {
      prompt();
      continue;
    }
    lua_settop(L_, 0);
    lua_pushboolean(L_, ok);
    call("_line_end", 1, 0);  // a line that failed changed no network (nor the view)
    end_busy();
    update_binds();
    // A line that ran may have changed anything the view depends on; one that failed may have
    // changed what is not a network before its error.
    dirty_ = true;
    if (ok && !console_->printed_values()) unsaved_ = true;  // lost at the next reload or quit
    take_requests();
    prompt_after_frame_ = true;  // after the redraw, so the prompt follows its messages
  }
  // Ctrl-D at a terminal ends the session, as in lua, asking first when console edits would be
  // lost; a pipe that ran dry just ends the console.
  if (stdin_->take_ctrl_d()) {
    ask_quit(QuitBy::ctrl_d);
    if (!quit_) prompt();
  }
  if (stdin_->at_end()) {
    stdin_.reset();
    if (StdinReader::interactive()) quit_ = true;
  }
}

void Loop::redraw() {
  lua_settop(L_, 0);
  if (!call("_has_view", 0, 1)) return;
  bool has = lua_toboolean(L_, -1);
  lua_settop(L_, 0);
  if (!has) {
    title_ = "shadenet — nothing to show: call sn.live.show{...}";
    return set_status();
  }
  auto [w, h] = view_size();
  if (ctx_.windowed() && (w < 1 || h < 1)) return;  // minimised
  const ViewState& v = input_.view();
  lua_createtable(L_, 0, 8);
  lua_pushstring(L_, mode_name(v.mode)), lua_setfield(L_, -2, "mode");
  if (w > 0) lua_pushinteger(L_, w), lua_setfield(L_, -2, "width"), lua_pushinteger(L_, h), lua_setfield(L_, -2, "height");
  auto push3 = [&](const std::array<double, 3>& a, const char* key) {
    lua_createtable(L_, 3, 0);
    for (int i = 0; i < 3; ++i) lua_pushnumber(L_, a[i]), lua_rawseti(L_, -2, i + 1);
    lua_setfield(L_, -2, key);
  };
  if (v.camera_moved) {
    push3(v.camera.position(), "eye");
    push3(v.camera.center, "target");
    lua_pushnumber(L_, v.fov), lua_setfield(L_, -2, "fov");
  }
  if (v.light_moved) push3(v.light.position(), "light");
  lua_pushnumber(L_, v.error_scale_factor), lua_setfield(L_, -2, "error_scale_factor");

  fallback_errors_.clear();
  auto t0 = Clock::now();
  std::string err;
  bool drawn = false;
  {
    auto watching = watch("the view's functions");
    drawn = call("_frame", 1, 3, &err);
  }
  end_busy();  // a bar shown while a slow view function ran
  if (!drawn) {
    frame_error_ = err;
    update_watch_set();  // a module the frame required (and that broke) must stay watched
    return set_status();
  }
  frame_error_.clear();
  // A frame that did not build the broken program proves nothing: the error stays until a run
  // after the next save (every shader save re-runs the script) builds without one.
  if (!fallback_errors_.empty()) shader_error_ = fallback_errors_.front();
  auto& target = lua::check<gl::RenderTarget>(L_, 1, "Target");
  title_ = lua_tostring(L_, 2) ? lua_tostring(L_, 2) : "";
  view_error_scale_ = lua_isnumber(L_, 3) ? lua_tonumber(L_, 3) : 0.25;
  gl::finish();
  frame_ms_ = seconds_since(t0) * 1e3;
  ++frame_;
  if (target_ref_ != LUA_NOREF) luaL_unref(L_, LUA_REGISTRYINDEX, target_ref_);
  lua_pushvalue(L_, 1);
  target_ref_ = luaL_ref(L_, LUA_REGISTRYINDEX);  // shown again when the window is uncovered
  present_due_ = true;
  if (!snapshot_.empty()) {
    const std::string path = numbered(snapshot_, frame_);
    try {
      io::save_image(target.read(), path);
    } catch (const std::exception& e) {
      fprintf(stderr, "[live] SHADENET_LIVE_SNAPSHOT: %s\n", e.what());
    }
  }
  lua_settop(L_, 0);
  lua_gc(L_, LUA_GCCOLLECT, 0);  // the frame's targets are GPU memory the collector cannot see
  update_watch_set();            // the first frame may have read new shader files
  set_status();
}

// sn.live._tick(text, fraction) -> why the work must stop, or false: called by long work
// (shadenet.live.busy.lua).
int Loop::tick_thunk(lua_State* L) {
  auto* self = static_cast<Loop*>(lua_touserdata(L, lua_upvalueindex(1)));
  const char* text = luaL_checkstring(L, 1);
  double fraction = luaL_optnumber(L, 2, 0);
  if (const char* why = self->tick(text, fraction)) lua_pushstring(L, why);
  else lua_pushboolean(L, 0);
  return 1;
}

// During training (sn.train's tick) or between recorded frames: at most every 40 ms (at least
// 10 pictures a second while the work ticks at least that often), show the last picture with the progress bar and read
// the window's events; why the work must stop when the user cancelled or closed the window, else null.
const char* Loop::tick(const std::string& text, double fraction) {
  if (!hud_.has_progress()) busy_since_ = Clock::now();
  hud_.set_progress(text, fraction);
  auto now = Clock::now();
  ticked_at_ = now;
  double since = std::chrono::duration<double>(now - last_tick_).count();
  const char* why = lua::LiveInterrupt::take() ? "interrupted by the user (Ctrl-C)" : nullptr;
  if (exit_after_ > 0 && seconds_since(started_) >= exit_after_) why = "stopped: SHADENET_LIVE_EXIT_AFTER ran out", quit_ = true;
  if (!ctx_.windowed()) {
    if (since >= 1) fprintf(stderr, "[live] %s\n", text.c_str()), last_tick_ = now;  // headless: a line a second
    if (!shown_path_.empty() && since >= 1) present();
    if (why) fprintf(stderr, "[live] cancelled: %s\n", text.c_str()), stopped_ = true;
    return why;
  }
  if (since < 0.04 && !why) return nullptr;  // work that ticks every 50 ms is shown at each tick
  last_tick_ = now;
  ctx_.poll(0);  // input callbacks run; the view they change is drawn after the work
  if (input_.take_cancel()) why = "cancelled by the user (Esc)";
  // Closing the window stops the work; the session ends with it unless console edits would be
  // lost (then the loop asks first, as for Q).
  if (ctx_.should_close()) why = "stopped: the window was closed", quit_ = !unsaved_;
  try {
    if (!quit_) present();
  } catch (const std::exception& e) {
    fprintf(stderr, "[live] cannot show the progress: %s\n", e.what());
  }
  if (why) fprintf(stderr, "[live] %s: %s\n", quit_ ? "window closed" : "cancelled", text.c_str());
  if (why) stopped_ = true;
  return why;
}

std::unique_ptr<Watch> Loop::watch(const std::string& what) {
  if (!RunGuard::active()) running_ = what, running_since_ = Clock::now();
  return std::make_unique<Watch>(L_, [this] { return check_run(); });
}

// Asked by the hook about every 40 ms while plain Lua runs: why it must stop, or null. Shows the
// last picture with a bar naming what runs once it has run for half a second.
const char* Loop::check_run() {
  const char* why = check_stop();
  if (why) stopped_ = true;
  return why;
}

const char* Loop::check_stop() {
  // Work that ticks (training, recording) reads the keys and Ctrl-C itself and says why it stopped
  // (sn.train: cancelled by the user (Esc) in epoch 1 of 3): it is left to do so while it ticks,
  // also through gaps of a loaded machine.
  if (seconds_since(ticked_at_) < 2) return nullptr;
  if (lua::LiveInterrupt::take()) return "interrupted by the user (Ctrl-C)";
  if (exit_after_ > 0 && seconds_since(started_) >= exit_after_) {  // the tests' time limit holds in a loop too
    quit_ = true;
    return "stopped: SHADENET_LIVE_EXIT_AFTER ran out";
  }
  if (!ctx_.windowed()) return nullptr;
  try {
    ctx_.poll(0);
    if (input_.take_cancel()) return "interrupted by the user (Esc)";
    if (ctx_.should_close()) {
      quit_ = !unsaved_;
      fprintf(stderr, "[live] %s: running %s\n", quit_ ? "window closed" : "stopped", running_.c_str());
      return "stopped: the window was closed";
    }
    double running = seconds_since(running_since_);
    if (running >= 0.5 && seconds_since(running_shown_) >= 0.1) {
      running_shown_ = Clock::now();
      char text[512];
      snprintf(text, sizeof text, "running %s: %.1f s  (Esc or Ctrl-C stops it)", running_.c_str(), running);
      if (!hud_.has_progress()) busy_since_ = Clock::now();
      hud_.set_progress(text, 0);
      present();
    }
  } catch (const std::exception& e) {
    fprintf(stderr, "[live] cannot show the progress: %s\n", e.what());
  }
  return nullptr;
}

// The probe box follows the cursor (key I): the values of the last frame under it, read back
// from the frame's parts (sn.live._probe_lines), none when the cursor is off the picture.
void Loop::update_probe() {
  bool had = hud_.has_probe();
  hud_.set_probe({}, 0, 0);
  if (input_.probe_on() && target_ref_ != LUA_NOREF && ctx_.windowed()) {
    lua_rawgeti(L_, LUA_REGISTRYINDEX, target_ref_);
    auto& frame = lua::check<gl::RenderTarget>(L_, -1, "Target");
    lua_pop(L_, 1);
    auto [fw, fh] = ctx_.framebuffer_size();
    auto c = input_.cursor();
    int x = 0, y = 0;
    if (picture_pixel(c[0], c[1], fw, fh, frame.width(), frame.height(), x, y)) {
      lua_pushinteger(L_, x + 1);
      lua_pushinteger(L_, y + 1);
      std::vector<std::string> lines;
      auto watching = watch("the probe");
      if (call("_probe_lines", 2, 1) && lua_istable(L_, -1))
        for (int i = 1; i <= int(lua_objlen(L_, -1)); ++i) {
          lua_rawgeti(L_, -1, i);
          if (const char* l = lua_tostring(L_, -1)) lines.push_back(l);
          lua_pop(L_, 1);
        }
      lua_settop(L_, 0);
      hud_.set_probe(std::move(lines), x, y);
    }
  }
  if (had || hud_.has_probe()) present_due_ = true;
}

// After a run, a console line or an action: the progress bar goes.
void Loop::end_busy() {
  bool stopped = std::exchange(stopped_, false);
  if (!hud_.has_progress()) return;
  hud_.set_progress("", 0);
  // An Esc soon after is taken for one meant to stop the work when the bar was up long enough to
  // be seen, and the work was not stopped (that took its key: a later one is meant).
  if (!stopped && seconds_since(busy_since_) >= 0.3) busy_ended_ = Clock::now();
  present_due_ = true;
}

// Shows the last picture with the overlays over it; SHADENET_LIVE_SHOWN saves what is shown.
void Loop::present() {
  present_due_ = false;
  if (!ctx_.windowed() && shown_path_.empty()) return;
  const gl::RenderTarget* frame = nullptr;
  if (target_ref_ != LUA_NOREF) {
    lua_rawgeti(L_, LUA_REGISTRYINDEX, target_ref_);
    frame = &lua::check<gl::RenderTarget>(L_, -1, "Target");
    lua_pop(L_, 1);  // the registry keeps it alive
  }
  // A window shows the overlays at its own size over the frame fitted inside; headless, the
  // frame's size is the view's (and without a frame, --size's or 640 x 480).
  auto [w, h] = view_size();
  if (!ctx_.windowed()) {
    if (frame) w = h = 0;
    else if (w < 1) w = 640, h = 480;
  } else if (w < 1 || h < 1) {
    return;  // minimised
  }
  const ViewState& v = input_.view();
  hud_.set_view(frame ? mode_name(v.mode) : "", view_error_scale_, frame_ms_, ctx_.windowed());
  const gl::RenderTarget& shown = hud_.compose(frame, w, h);
  ctx_.present(shown.fbo(), shown.width(), shown.height());
  if (shown_path_.empty()) return;
  const std::string path = numbered(shown_path_, ++shown_count_);
  try {
    io::save_image(shown.read(), path);
  } catch (const std::exception& e) {
    fprintf(stderr, "[live] SHADENET_LIVE_SHOWN: %s\n", e.what());
  }
}

// Q or Esc, the window's close button, Ctrl-D at the console: quits at once, unless console edits
// (or bound keys' changes) that are not in the script would be lost; then it asks, in the window
// and on the terminal, for a second request (any of them) within kConfirm. An Esc (it also stops
// work; Q is a plain quit) read within kLateEsc of the end of a training, a recording or a long
// run that ended by itself was most likely meant to stop it: it asks too.
void Loop::ask_quit(QuitBy by) {
  auto now = Clock::now();
  if (by == QuitBy::close) glfwSetWindowShouldClose(static_cast<GLFWwindow*>(ctx_.native_window()), GLFW_FALSE);
  bool late = by == QuitBy::esc && now - busy_ended_ < kLateEsc;
  if ((!unsaved_ && !late) || now < confirm_until_) {
    quit_ = true;
    return;
  }
  const char* again = by == QuitBy::close    ? "close the window again (or press Q)"
                      : by == QuitBy::ctrl_d ? "press Ctrl-D again (or Q)"
                      : by == QuitBy::esc    ? "press Esc (or Q) again"
                                             : "press Q (or Esc) again";
  if (unsaved_)
    fprintf(stderr, "[live] Console edits are not in the script and will be lost: %s to quit\n", again);
  else
    fprintf(stderr, "[live] The work had ended before the key was read (nothing was cancelled): %s to quit\n", again);
  fflush(stderr);
  std::string last = by == QuitBy::close    ? "Close again (or Q): quit"
                     : by == QuitBy::ctrl_d ? "Ctrl-D again (or Q): quit"
                                            : "Q or Esc again: quit";
  if (unsaved_) hud_.set_notice({"Console edits will be lost", "(they are not in the script)", last});
  else hud_.set_notice({"The work ended before the key:", "nothing was cancelled", last});
  confirm_until_ = now + kConfirm;
  present_due_ = true;
}

// The HUD's list of bound keys and their values (sn.live.bind), read after anything that may
// have changed them.
void Loop::update_binds() {
  std::vector<std::string> lines;
  auto watching = watch("the bound keys' values");
  if (call("_bind_lines", 0, 1) && lua_istable(L_, -1))
    for (int i = 1; i <= int(lua_objlen(L_, -1)); ++i) {
      lua_rawgeti(L_, -1, i);
      if (const char* l = lua_tostring(L_, -1)) lines.push_back(l);
      lua_pop(L_, 1);
    }
  lua_settop(L_, 0);
  if (lines != hud_.binds()) hud_.set_binds(std::move(lines)), present_due_ = true;
}

void Loop::actions() {
  Actions a = input_.take_actions();
  for (auto [key, down] : a.keys) {  // sn.live.bind's keys: a bound value steps
    lua_pushlstring(L_, &key, 1);
    lua_pushboolean(L_, down);
    bool stepped = false;
    {
      auto watching = watch("a bound key");
      stepped = call("_key", 2, 2);
    }
    if (!stepped) continue;
    if (const char* line = lua_tostring(L_, 1)) {
      printf("[live] %s\n", line);
      dirty_ = unsaved_ = true;  // like a console edit: gone at the next reload
    } else if (const char* err = lua_tostring(L_, 2)) {
      fprintf(stderr, "[live] %s\n", err);
    }
    lua_settop(L_, 0);
  }
  if (!a.keys.empty()) update_binds();
  if (a.quit) ask_quit(a.escape ? QuitBy::esc : QuitBy::key);
  if (hud_.has_notice() && Clock::now() >= confirm_until_) hud_.set_notice({}), present_due_ = true;
  if (a.help) printf("%s", Input::help());
  auto run_lua = [&](const char* what, const char* code) {
    if (luaL_loadstring(L_, code) != 0) return lua_settop(L_, 0);
    lua_pushcfunction(L_, traceback);
    lua_insert(L_, -2);
    auto watching = watch(what);
    if (lua_pcall(L_, 0, 0, 1) != 0) fprintf(stderr, "[live] %s\n", lua_tostring(L_, -1));
    lua_settop(L_, 0);
  };
  if (a.screenshot) run_lua("the screenshot", "local sn = require 'shadenet'; print('[live] screenshot: ' .. sn.live.screenshot())");
  if (a.record)
    run_lua("the recording", "local sn = require 'shadenet'; local dir, frames = sn.record { orbit = { count = 36 } }; "
            "print(('[live] recorded %d frames of an orbit in %s'):format(#frames, dir))");
  if (a.print_view) run_lua("the view's code", "local sn = require 'shadenet'; print(sn.live.view_code())");
  end_busy();
  if (a.present && !dirty_) present_due_ = true;
  fflush(stdout);
}

int Loop::run() {
  if (const char* s = getenv("SHADENET_LIVE_SNAPSHOT"); s && *s) snapshot_ = s;
  if (const char* s = getenv("SHADENET_LIVE_EXIT_AFTER"); s && *s) exit_after_ = atof(s);
  if (const char* s = getenv("SHADENET_LIVE_SHOWN"); s && *s) shown_path_ = s;
  started_ = Clock::now();

  // The module table: `require "shadenet"` before the script, so its sn.live functions exist.
  lua_settop(L_, 0);
  lua_getglobal(L_, "require");
  lua_pushstring(L_, "shadenet");
  if (lua_pcall(L_, 1, 1, 0) != 0) {
    fprintf(stderr, "shadenet: %s\n", lua_tostring(L_, -1));
    return 1;
  }
  lua_getfield(L_, -1, "live");
  lua_pushlightuserdata(L_, this);
  lua_pushcclosure(L_, tick_thunk, 1);
  lua_setfield(L_, -2, "_tick");
  live_ref_ = luaL_ref(L_, LUA_REGISTRYINDEX);
  lua_settop(L_, 0);

  gl::set_shader_file_observer([this](const std::string& f) { shader_files_.insert(f); });
  gl::set_program_fallback([this](const std::string& e) { fallback_errors_.push_back(e); });
  if (ctx_.windowed()) input_.attach(static_cast<GLFWwindow*>(ctx_.native_window()));
  auto wake = [this] { waker_.wake(); };
  if (o_.watch) {
    try {
      watcher_ = std::make_unique<FileWatcher>(wake);
    } catch (const std::exception& e) {
      fprintf(stderr, "shadenet: %s\n", e.what());
      return 1;
    }
    // A terminal this process does not own (started with `&`) would stop it on the first read.
    if (isatty(0) && tcgetpgrp(0) != getpgrp())
      fprintf(stderr, "[live] console off: started in the background of a terminal (run in the foreground to type "
                      "Lua lines)\n");
    else
      stdin_ = std::make_unique<StdinReader>(wake);
    console_ = std::make_unique<Console>(L_, [this](lua_State*) {
      if (!call("_console_env", 0, 1)) return false;
      if (lua_istable(L_, -1)) return true;
      lua_pop(L_, 1);
      return false;
    });
  }
  if (o_.already_ran) {
    sync_view(true);
    update_watch_set();
  } else {
    run_script();
  }
  if (ctx_.windowed()) fprintf(stderr, "[live] %s", Input::help());
  if (console_) prompt();

  while (!quit_) {
    // A save is run once its files were quiet for kSettle: an editor that truncates, then writes,
    // or two saves in a row, give one run of the finished file.
    if (files_changed()) reload_at_ = Clock::now() + kSettle, reload_pending_ = true;
    if (reload_pending_ && Clock::now() >= reload_at_) reload_pending_ = false, run_script();
    if (!reload_pending_) console();  // a line typed after a save runs after its reload
    actions();
    if (input_.take_dirty()) dirty_ = true;
    if (ctx_.windowed()) {
      if (ctx_.should_close() && !quit_) ask_quit(QuitBy::close);
      if (ctx_.framebuffer_size() != drawn_size_) drawn_size_ = ctx_.framebuffer_size(), dirty_ = true;
    }
    // Headless there is nothing to show unless a snapshot file is asked for.
    if (dirty_ && !quit_ && (ctx_.windowed() || !snapshot_.empty())) {
      dirty_ = false;
      try {
        redraw();
      } catch (const std::exception& e) {  // a frame that fails in C++ is reported like one that fails in Lua
        lua_settop(L_, 0);
        frame_error_ = e.what();
        set_status();
      }
    }
    // After a new frame the probe reads that frame; after a move, the pixel under the cursor.
    if ((input_.take_probe_dirty() || (frame_ != probed_frame_ && input_.probe_on())) && !quit_) {
      probed_frame_ = frame_;
      update_probe();
    }
    if (present_due_ && !quit_) {
      try {
        present();
      } catch (const std::exception& e) {
        fprintf(stderr, "[live] cannot show the overlay: %s\n", e.what());
      }
    }
    if (prompt_after_frame_ && console_) prompt(), prompt_after_frame_ = false;
    dirty_ = false;
    if (quit_) break;
    double timeout = 3600;
    if (exit_after_ > 0) {
      timeout = exit_after_ - seconds_since(started_);
      if (timeout <= 0) break;
    }
    if (reload_pending_)
      timeout = std::min(timeout, std::max(0.0, std::chrono::duration<double>(reload_at_ - Clock::now()).count()));
    if (hud_.has_notice())  // wake to take the question away
      timeout = std::min(timeout, std::max(0.0, std::chrono::duration<double>(confirm_until_ - Clock::now()).count()));
    if (ctx_.windowed()) ctx_.poll(timeout);  // sleeps until an event, a file save or a console line
    else waker_.wait(timeout);
  }
  fflush(stdout);
  return 0;
}

}  // namespace

int run_live(lua_State* L, const LiveOptions& options) {
  Loop loop(L, options);
  return loop.run();
}

}  // namespace sn::live
