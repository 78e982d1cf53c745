// What live mode shows of an error: the file:line to fix, its source line, the context.
#include <gtest/gtest.h>


#include <filesystem>
#include <fstream>

#include "live/error_report.h"
#include "io/temp_dir.h"

using namespace sn::live;
namespace fs = std::filesystem;

TEST(LiveErrorReport, LuaErrorGetsItsSourceLine) {
  const sn::io::TempDir tmp("test_error_report");
  const fs::path dir = tmp.path();
  std::string file = (dir / "s.lua").string();
  std::ofstream(file) << "local a = 1\n  local x = = 1\n";
  ErrorReport r = report_error(file + ":2: unexpected symbol near '='\nstack traceback:\n\t[C]: in ?");
  EXPECT_EQ(r.headline, file + ":2: unexpected symbol near '='");
  EXPECT_EQ(r.where, file + ":2");
  EXPECT_EQ(r.source, "  2 | local x = = 1");
  EXPECT_TRUE(r.context.empty());
  EXPECT_EQ(r.traceback, "stack traceback:\n\t[C]: in ?");
}

TEST(LiveErrorReport, ShaderLineBeforeTheScriptsAndTheLogsSourceLine) {
  ErrorReport r = report_error(
      "s.lua:4: GLSL compile error in bad.frag:\nbad.frag:3: error: syntax error, unexpected ';'\n"
      "      o_color = vec4(1.0) +;\nstack traceback:\n\t[C]: in function 'program'");
  EXPECT_EQ(r.headline, "bad.frag:3: error: syntax error, unexpected ';'");
  EXPECT_EQ(r.source, "  3 | o_color = vec4(1.0) +;");
  ASSERT_EQ(r.context.size(), 1u);
  EXPECT_EQ(r.context[0], "s.lua:4: GLSL compile error in bad.frag:");
  auto lines = report_lines(r);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0], r.headline);
}

// GLSL given as a string is located "script.lua:2 (glsl of NAME):LINE": the headline was cut
// to "NAME):2: ..." at the first location without spaces.
TEST(LiveErrorReport, GlslStringLocationIsOneLocation) {
  ErrorReport r = report_error(
      "w17.lua:3: sn.lighting.define: lighting model 'wrapl': its GLSL does not compile:\n"
      "w17.lua:2 (glsl of wrapl):2: error: syntax error, unexpected ';'");
  EXPECT_EQ(r.where, "w17.lua:2 (glsl of wrapl):2");
  EXPECT_EQ(r.headline, "w17.lua:2 (glsl of wrapl):2: error: syntax error, unexpected ';'");
}

TEST(LiveErrorReport, ModuleErrorNamesTheModulesLine) {
  ErrorReport r = report_error("s.lua:14: error loading module 'm' from file 'm.lua':\n\tm.lua:1: unexpected symbol near '='");
  EXPECT_EQ(r.where, "m.lua:1");
  EXPECT_EQ(r.headline, "m.lua:1: unexpected symbol near '='");
  EXPECT_EQ(r.source, "");  // m.lua does not exist here
  // No file:line at all: the first line.
  EXPECT_EQ(report_error("the script is empty\nmore").headline, "the script is empty");
}
