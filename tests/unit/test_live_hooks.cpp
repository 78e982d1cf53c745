// The shader loader's hooks live mode relies on: the observer sees every file a program read
// (includes too), and with a fallback set a program broken by an edit keeps its last good build.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "gl/context.h"
#include "gl/program.h"
#include "gl/shader_source.h"
#include "io/temp_dir.h"

using namespace sn::gl;
namespace fs = std::filesystem;

namespace {

struct TempShaders {
  sn::io::TempDir tmp{"test_live_hooks"};
  fs::path dir = tmp.path();
  ~TempShaders() {
    set_shader_file_observer(nullptr);
    set_program_fallback(nullptr);
  }
  std::string write(const std::string& name, const std::string& text) {
    std::ofstream(dir / name) << text;
    return (dir / name).string();
  }
};

const char* kInclude = "float twice(float x) { return 2.0 * x; }\n";
std::string kernel(const std::string& body) {
  return "#include \"twice.glsl\"\nlayout(local_size_x = 1) in;\n"
         "layout(std430, binding = 0) buffer B { float v[]; };\nvoid main() {\n" + body + "\n}\n";
}

}  // namespace

TEST(LiveHooks, ObserverSeesTheFileAndItsIncludes) {
  current();
  TempShaders t;
  t.write("twice.glsl", kInclude);
  std::string main_path = t.write("k.comp", kernel("v[0] = twice(v[0]);"));
  std::set<std::string> seen;
  set_shader_file_observer([&](const std::string& f) { seen.insert(fs::path(f).filename().string()); });
  get_program({.compute = main_path});
  EXPECT_EQ(seen, (std::set<std::string>{"k.comp", "twice.glsl"}));
}

TEST(LiveHooks, FallbackKeepsTheLastGoodProgramAndReports) {
  current();
  TempShaders t;
  t.write("twice.glsl", kInclude);
  std::string path = t.write("k.comp", kernel("v[0] = twice(v[0]);"));
  // Without a fallback, a broken shader throws (the default, for scripts and tests).
  auto good = get_program({.compute = path});
  t.write("k.comp", kernel("v[0] = twice(v[0]) +;"));
  EXPECT_THROW(get_program({.compute = path}), std::runtime_error);

  std::vector<std::string> errors;
  set_program_fallback([&](const std::string& e) { errors.push_back(e); });
  auto kept = get_program({.compute = path});
  EXPECT_EQ(kept.get(), good.get()) << "the last good build keeps running";
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_NE(errors[0].find("k.comp:5"), std::string::npos) << errors[0];  // file:line of the bad statement

  // A broken include is reported through the includer's request too.
  t.write("k.comp", kernel("v[0] = twice(v[0]);"));
  t.write("twice.glsl", "float twice(float x) { return 2.0 * ; }\n");
  EXPECT_EQ(get_program({.compute = path}).get(), good.get());
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_NE(errors[1].find("twice.glsl:1"), std::string::npos) << errors[1];

  // The fix builds a new program; a request that never built still throws.
  t.write("twice.glsl", "float twice(float x) { return x + x; }\n");
  auto fixed = get_program({.compute = path});
  EXPECT_NE(fixed.get(), good.get());
  EXPECT_EQ(errors.size(), 2u);
  std::string never = t.write("never.comp", "void main() { oops }\n");
  EXPECT_THROW(get_program({.compute = never}), std::runtime_error);
}

// A definition being checked builds under NoProgramFallback: broken, it throws even in live mode
// (the last good program of the same files stood in for it, and the broken definition was taken).
TEST(LiveHooks, NoFallbackWhileADefinitionIsChecked) {
  current();
  TempShaders t;
  t.write("twice.glsl", kInclude);
  std::string path = t.write("k.comp", kernel("v[0] = twice(v[0]);"));
  auto good = get_program({.compute = path});
  std::vector<std::string> errors;
  set_program_fallback([&](const std::string& e) { errors.push_back(e); });
  t.write("twice.glsl", "float twice(float x) { return 2.0 * ; }\n");
  {
    NoProgramFallback strict;
    EXPECT_THROW(get_program({.compute = path}), std::runtime_error);
  }
  EXPECT_TRUE(errors.empty());
  EXPECT_EQ(get_program({.compute = path}).get(), good.get()) << "outside it, the fallback is back";
  EXPECT_EQ(errors.size(), 1u);
}
