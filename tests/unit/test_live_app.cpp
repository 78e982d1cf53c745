// The live loop's parts without a window: orbit controls, the console and the file watcher.
#include <gtest/gtest.h>

#include <GLFW/glfw3.h>
#include <lua.hpp>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <thread>

#include "live/file_watcher.h"
#include "live/input.h"
#include "live/repl.h"
#include "io/temp_dir.h"

using namespace sn::live;
namespace fs = std::filesystem;

TEST(LiveInput, OrbitRoundTrip) {
  std::array<double, 3> c{0.5, -1, 2}, p{1.1, 0.3, 4.5};
  Orbit o = Orbit::from(c, p);
  auto q = o.position();
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(q[i], p[i], 1e-12);
  // Azimuth from +Z towards +X, as sn.orbit: a point on +X is at 90 degrees, on +Y at elevation 90.
  EXPECT_NEAR(Orbit::from({0, 0, 0}, {2, 0, 0}).azimuth, 90, 1e-12);
  EXPECT_NEAR(Orbit::from({0, 0, 0}, {0, 3, 0}).elevation, 90, 1e-12);
}

TEST(LiveInput, DragZoomKeys) {
  Input in;
  Orbit cam = Orbit::from({0, 0, 0}, {0, 0, 3}), light = Orbit::from({0, 0, 0}, {0, 0, 1});
  in.set_initial(cam, 45, light, Mode::network, {true, true, true});
  EXPECT_TRUE(in.take_dirty());
  EXPECT_FALSE(in.take_dirty());
  in.drag(100, 0, false);  // 0.4 degrees per pixel; dragging right moves the eye left
  EXPECT_NEAR(in.view().camera.azimuth, -40, 1e-12);
  EXPECT_TRUE(in.view().camera_moved);
  EXPECT_FALSE(in.view().light_moved);
  in.drag(0, 1000, false);  // elevation stops short of the pole
  EXPECT_NEAR(in.view().camera.elevation, 89, 1e-12);
  in.zoom(2);
  EXPECT_NEAR(in.view().camera.distance, 3 * 0.81, 1e-12);
  in.key(GLFW_KEY_RIGHT, 0);  // light 5 degrees
  EXPECT_NEAR(in.view().light.azimuth, 5, 1e-12);
  EXPECT_TRUE(in.view().light_moved);
  in.key(GLFW_KEY_3, 0);
  EXPECT_EQ(in.view().mode, Mode::error);
  in.key(GLFW_KEY_TAB, 0);
  EXPECT_EQ(in.view().mode, Mode::side);
  in.key(GLFW_KEY_TAB, 0);
  EXPECT_EQ(in.view().mode, Mode::network);
  in.key(GLFW_KEY_RIGHT_BRACKET, 0);
  EXPECT_EQ(in.view().error_scale_factor, 2);
  in.key(GLFW_KEY_S, 0);
  in.key(GLFW_KEY_R, 0);
  Actions a = in.take_actions();
  EXPECT_TRUE(a.screenshot && a.record && !a.quit);
  EXPECT_FALSE(in.take_actions().screenshot);
  // A reload that does not change the script's camera keeps the user's; Home goes back to it.
  in.set_initial(cam, 45, light, Mode::network, {});
  EXPECT_TRUE(in.view().camera_moved);
  // A script that moves its light resets the light, not the mode or the camera the user picked.
  in.key(GLFW_KEY_3, 0);
  in.set_initial(cam, 45, Orbit::from({0, 0, 0}, {1, 0, 0}), Mode::network, {false, true, false});
  EXPECT_EQ(in.view().mode, Mode::error);
  EXPECT_TRUE(in.view().camera_moved);
  EXPECT_FALSE(in.view().light_moved);
  EXPECT_NEAR(in.view().light.azimuth, 90, 1e-12);
  in.key(GLFW_KEY_HOME, 0);
  EXPECT_FALSE(in.view().camera_moved);
  EXPECT_NEAR(in.view().camera.distance, 3, 1e-12);
  EXPECT_NEAR(in.view().camera.azimuth, 0, 1e-12);
}

TEST(LiveConsole, RunsLinesLikeTheLuaInterpreter) {
  lua_State* L = luaL_newstate();
  luaL_openlibs(L);
  luaL_dostring(L, "out = {} print = function(...) local t = {} for i = 1, select('#', ...) do "
                   "t[#t + 1] = tostring((select(i, ...))) end out[#out + 1] = table.concat(t, '\\t') end");
  Console c(L);
  bool ok = false;
  EXPECT_TRUE(c.execute("x = 20", &ok));
  EXPECT_TRUE(ok);
  EXPECT_TRUE(c.execute("x + 1, 'two'", &ok));  // an expression prints its values
  EXPECT_FALSE(c.execute("function f(a)", &ok));  // incomplete: waits for more
  EXPECT_TRUE(c.continuing());
  EXPECT_FALSE(c.execute("  return a * x", &ok));
  EXPECT_TRUE(c.execute("end", &ok));
  EXPECT_TRUE(ok);
  EXPECT_TRUE(c.execute("f(2)", &ok));
  testing::internal::CaptureStderr();
  EXPECT_TRUE(c.execute("error('boom')", &ok));
  EXPECT_FALSE(ok);
  EXPECT_TRUE(c.execute("x = = 1", &ok));  // a syntax error is reported, not waited on
  std::string err = testing::internal::GetCapturedStderr();
  EXPECT_FALSE(ok);
  EXPECT_NE(err.find("stdin:1: boom"), std::string::npos) << err;
  EXPECT_NE(err.find("unexpected symbol near '='"), std::string::npos) << err;
  luaL_dostring(L, "return table.concat(out, '|')");
  EXPECT_STREQ(lua_tostring(L, -1), "21\ttwo|40");
  // As the lua interpreter: a statement's `return` values print, "=expr" is "return expr", and an
  // expression's error names its line (the call's closing bracket stood on the next: stdin:2; it
  // still does after a trailing comment, which would comment it out).
  luaL_dostring(L, "out = {}");
  EXPECT_TRUE(c.execute("return 1, nil, 'x'", &ok));
  EXPECT_TRUE(c.printed_values());
  EXPECT_TRUE(c.execute("=x * 2", &ok));
  EXPECT_TRUE(c.execute("x -- the value", &ok));
  testing::internal::CaptureStderr();
  EXPECT_TRUE(c.execute("nosuch.y", &ok));
  err = testing::internal::GetCapturedStderr();
  EXPECT_EQ(err.find("stdin:2"), std::string::npos) << err;
  EXPECT_NE(err.find("stdin:1: attempt to index global 'nosuch'"), std::string::npos) << err;
  luaL_dostring(L, "return table.concat(out, '|')");
  EXPECT_STREQ(lua_tostring(L, -1), "1\tnil\tx|40|20");
  lua_close(L);
}

TEST(LiveConsole, EnvironmentFromPrepare) {
  lua_State* L = luaL_newstate();
  luaL_openlibs(L);
  Console c(L, [](lua_State* S) {
    luaL_dostring(S, "return setmetatable({ net = 42 }, { __index = _G })");
    return true;
  });
  EXPECT_TRUE(c.execute("seen = net", nullptr));
  luaL_dostring(L, "return seen");  // `seen` went into the console environment, not _G
  EXPECT_TRUE(lua_isnil(L, -1));
  lua_close(L);
}

TEST(LiveWatcher, SeesWritesAndRenamesOfWatchedFilesOnly) {
  const sn::io::TempDir tmp("test_watch");
  const fs::path dir = tmp.path();
  std::ofstream(dir / "a.lua") << "x = 1\n";
  std::ofstream(dir / "other.lua") << "y = 1\n";
  std::atomic<int> wakes{0};
  FileWatcher w([&] { ++wakes; });
  w.watch({(dir / "a.lua").string(), (dir / "b.glsl").string()});  // b.glsl does not exist yet
  // No wait: the watches are in place when watch() returns (a save right after was missed).
  auto wait_for = [&](size_t n) {
    std::vector<std::string> got;
    for (int i = 0; i < 200 && got.size() < n; ++i) {
      for (auto& f : w.take_changed()) got.push_back(fs::path(f).filename().string());
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return got;
  };
  std::ofstream(dir / "other.lua") << "y = 2\n";  // not watched
  std::ofstream(dir / "a.lua") << "x = 2\n";      // written in place
  EXPECT_EQ(wait_for(1), std::vector<std::string>{"a.lua"});
  std::ofstream(dir / "b.tmp") << "// new\n";  // saved by rename, as many editors do
  fs::rename(dir / "b.tmp", dir / "b.glsl");
  EXPECT_EQ(wait_for(1), std::vector<std::string>{"b.glsl"});
  EXPECT_GE(wakes.load(), 2);
  EXPECT_TRUE(w.take_changed().empty());
}
