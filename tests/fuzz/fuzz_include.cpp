// Fuzz target: the GLSL preprocessor (#version/#define prepended, #include expanded with #line
// markers; gl/shader_source.h) and the driver-log rewriting that maps errors back to files.
// Input parts (fuzz_input.h): the shader, a driver info log, then files the shader may include
// as "a.glsl", "b.glsl", ... (served from memory, as generated lighting-model code is); any
// other name resolves on disk as it would for a user's shader.
#include <exception>

#include "fuzz_input.h"
#include "gl/shader_source.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  std::vector<std::string> parts = sn::fuzz::split_parts(data, size);
  sn::gl::Includes includes;
  for (std::size_t k = 2; k < parts.size() && k < 2 + 26; ++k)
    includes[std::string(1, char('a' + k - 2)) + ".glsl"] = parts[k];
  try {
    sn::gl::ShaderSource src = sn::gl::preprocess_text("fuzz.comp", parts[0], {{"LOCAL_SIZE", "64"}}, includes);
    if (src.files.size() != src.lines.size()) __builtin_trap();
    if (parts.size() > 1) sn::gl::rewrite_log(parts[1], src);
  } catch (const std::exception&) {
  }
  return 0;
}
