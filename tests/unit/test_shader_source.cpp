// The GLSL loader: #include expansion, #define injection and the mapping of driver logs back
// to the file and line a person wrote.
#include <gtest/gtest.h>

#include "gl/shader_source.h"

using namespace sn::gl;

TEST(ShaderSource, DefinesAndVersionComeFirst) {
  ShaderSource s = preprocess_text("inline.comp", "void main() {}\n", {{"WIDTH", "8"}, {"ACT", "tanh"}});
  EXPECT_EQ(s.text.rfind("#version 450 core\n#define ACT tanh\n#define WIDTH 8\n#line 1 0\n", 0), 0u);
  EXPECT_EQ(s.files.size(), 1u);
}

TEST(ShaderSource, IncludeIsExpandedOnceWithLineMarkers) {
  ShaderSource s = preprocess("tests/data/shaders/uses_broken.comp", {});
  ASSERT_EQ(s.files.size(), 2u);
  EXPECT_EQ(s.files[0], "tests/data/shaders/uses_broken.comp");
  EXPECT_EQ(s.files[1], "tests/data/shaders/broken_helper.glsl");
  // after the include, line numbering resumes in file 0 at the line after the #include (line 4)
  EXPECT_NE(s.text.find("#line 100001 1\n"), std::string::npos);
  EXPECT_NE(s.text.find("#line 4 0\n"), std::string::npos);
}

TEST(ShaderSource, MesaLogMapsToIncludedFile) {
  ShaderSource s = preprocess("tests/data/shaders/uses_broken.comp", {});
  // Mesa may name source string 0 for an error in file 1; the line number carries the file.
  std::string out = rewrite_log("0:100005(12): error: `undeclared_thing' undeclared\n", s);
  EXPECT_EQ(out,
            "tests/data/shaders/broken_helper.glsl:5: error: `undeclared_thing' undeclared\n"
            "        return undeclared_thing * 2.0;\n");
}

TEST(ShaderSource, NvidiaLogMapsToIncludedFile) {
  ShaderSource s = preprocess("tests/data/shaders/uses_broken.comp", {});
  std::string out = rewrite_log("1(100005) : error C1008: undefined variable \"undeclared_thing\"\n", s);
  EXPECT_EQ(out.substr(0, out.find('\n')),
            "tests/data/shaders/broken_helper.glsl:5: error C1008: undefined variable \"undeclared_thing\"");
}

TEST(ShaderSource, MissingFileNamesBothPlaces) {
  try {
    preprocess("no/such/file.comp", {});
    FAIL() << "expected an error";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("shader file 'no/such/file.comp' not found"), std::string::npos) << e.what();
  }
}

TEST(ShaderSource, IncludeCycleIsAnError) {
  try {
    preprocess("tests/data/shaders/self_include.glsl", {});
    FAIL() << "expected an error";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("self_include.glsl:2: #include cycle"), std::string::npos) << e.what();
  }
}

// In-memory includes (gl::Includes): found before the disk, pasted once, and a log line in one
// names the include, with its own line numbers.
TEST(ShaderSource, InMemoryIncludeShadowsTheDiskAndMapsItsLines) {
  Includes mem;
  mem["broken_helper.glsl"] = "float helper(float x) {\n  return bad_name;\n}\n";
  ShaderSource s = preprocess("tests/data/shaders/uses_broken.comp", {}, mem);
  ASSERT_EQ(s.files.size(), 2u);
  EXPECT_EQ(s.files[1], "broken_helper.glsl");
  EXPECT_NE(s.text.find("return bad_name;"), std::string::npos);
  EXPECT_EQ(s.text.find("undeclared_thing"), std::string::npos);  // the file on disk was not read
  std::string out = rewrite_log("0:100002(10): error: `bad_name' undeclared\n", s);
  EXPECT_EQ(out, "broken_helper.glsl:2: error: `bad_name' undeclared\n      return bad_name;\n");
}
