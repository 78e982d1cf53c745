// GLSL files as the driver sees them: #version and #define lines prepended, #include "file"
// expanded with #line markers, and driver logs mapped back to `shaders/FILE.glsl:LINE`.
#pragma once
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace sn::gl {

using Defines = std::map<std::string, std::string>;
// Text an #include "name" takes from memory instead of a file: generated code (a lighting
// model's assembly) and sources given as strings. Looked up before any file.
using Includes = std::map<std::string, std::string>;

struct ShaderSource {
  std::string text;                              // what glShaderSource receives
  std::vector<std::string> files;                // source-string number -> display path
  std::vector<std::vector<std::string>> lines;   // per file, its lines (for error context)
  std::string key() const;                       // cache key: the full text
};

// The folder holding shadenet's shaders: $SHADENET_SHADERS, <exe>/../shaders, or the source tree's.
std::string shader_root();
// Finds `path` as given (relative to the working directory), else under shader_root();
// throws naming both places when neither has it.
std::string resolve_shader_path(const std::string& path);
// Turns an absolute or relative path into the name errors show (relative to the project root
// when the file is inside it, e.g. "shaders/include/mlp.glsl").
std::string display_path(const std::string& path);

ShaderSource preprocess(const std::string& path, const Defines& defines, const Includes& includes = {});

// Live mode watches every shader file programs read: when set, `observer` receives the absolute
// path of each file preprocess() opens (the file itself and its #includes). Empty = off.
void set_shader_file_observer(std::function<void(const std::string& absolute_path)> observer);
// Same, from text held in memory (named `name` in messages).
ShaderSource preprocess_text(const std::string& name, const std::string& text, const Defines& defines,
                             const Includes& includes = {});

// A definition's GLSL fixed as it reads now (a lighting model's, shading/lighting_model.h): later
// edits of its files change nothing already defined. `text` (named `name` in errors) is kept with
// each #include of a file found beside it (in `dir`; a nested one beside its includer) rewritten to
// name that file's captured text in `files`, keyed by its display path. An #include found in
// shaders/include/ or shaders/ is the runtime's own and is read when a program is built, as every
// shader of shadenet's. Throws naming file:line and the folders looked in for a missing #include.
struct CapturedSource {
  std::string name, text;
  Includes files;  // for ProgramDesc::includes, beside {name, text}
};
CapturedSource capture_source(const std::string& name, const std::string& text, const std::string& dir);
// The same for a file: named by its display path, its #includes looked up beside it.
CapturedSource capture_file(const std::string& path);

// True for GLSL 4.50's keywords, type names and reserved words (in, vec3, sampler2D, class):
// a name a script gives to generated GLSL (a struct member) must not be one.
bool glsl_reserved_word(const std::string& name);
// `text` with its // and /* */ comments blanked (their newlines kept): what a check of the
// source's declarations reads.
std::string without_glsl_comments(const std::string& text);

// A GLSL float literal that reads back as the same float as `v` ("0.5", "1.0", "1e-07").
std::string float_literal(double v);

// Rewrites a Mesa or NVIDIA info log ("0:12(3): error: ..." / "0(12) : error ...") into
// "shaders/FILE.glsl:LINE: error: ..." lines, each followed by the offending source line.
std::string rewrite_log(const std::string& log, const ShaderSource& src);

}  // namespace sn::gl
