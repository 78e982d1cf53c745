#include "gl/shader_source.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>

#include "io/limits.h"
#include "io/read_file.h"

namespace fs = std::filesystem;

namespace sn::gl {

namespace {

std::function<void(const std::string&)>& file_observer() {
  static std::function<void(const std::string&)> f;
  return f;
}

// Shader sources are small: io::limits().shader_bytes (16 MiB until raised) is far beyond any
// real one and keeps /dev/zero out.
std::string read_file(const fs::path& p) {
  if (file_observer()) file_observer()(fs::absolute(p).string());  // before reading: a missing file is watched too
  return io::read_file(p.string(), "shader file", io::limits().shader_bytes, "shader_bytes");
}

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::string line;
  std::istringstream in(text);
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(line);
  }
  return lines;
}

fs::path project_root() { return fs::path(shader_root()).parent_path(); }

// Mesa reports some errors with source-string 0 whatever #line said, so the file index is also
// encoded in the line number itself: line kStride * index + n is line n of file `index`.
constexpr int kStride = 100000;
std::string line_marker(int index, int line) {
  return "#line " + std::to_string(kStride * index + line) + " " + std::to_string(index) + "\n";
}

const std::regex& include_regex() {
  static const std::regex re(R"(^\s*#\s*include\s+[\"<]([^\">]+)[\">]\s*(//.*)?$)");
  return re;
}

// Where `#include "name"` in a file of folder `dir` finds its file: beside it, then in
// shaders/include/, then in shaders/. Throws naming `where` (file:line) and the folders.
fs::path find_include(const fs::path& dir, const std::string& name, const std::string& where) {
  const fs::path root = shader_root();
  std::vector<std::string> looked;
  for (const fs::path& folder : {dir, root / "include", root}) {
    if (fs::exists(folder / name)) return folder / name;
    std::string shown = display_path(folder.empty() ? "." : folder.string()) + "/";
    if (std::find(looked.begin(), looked.end(), shown) == looked.end()) looked.push_back(shown);
  }
  std::string places;
  for (std::size_t i = 0; i < looked.size(); ++i)
    places += (i == 0 ? "" : i + 1 == looked.size() ? " and " : ", ") + looked[i];
  throw std::runtime_error(where + ": cannot find #include \"" + name + "\" (looked in " + places + ")");
}

struct Expander {
  ShaderSource& out;
  const Includes& memory;
  std::set<std::string> included;  // each file is pasted once (like #pragma once)
  std::vector<std::string> stack;

  void expand(const std::string& name, const std::string& text, const fs::path& dir) {
    int index = int(out.files.size());
    out.files.push_back(name);
    out.lines.push_back(split_lines(text));
    stack.push_back(name);
    static const std::regex version_re(R"(^\s*#\s*version\b.*)");
    out.text += line_marker(index, 1);
    const std::vector<std::string> lines = out.lines.back();  // a copy: nested includes grow out.lines
    for (size_t i = 0; i < lines.size(); ++i) {
      std::smatch m;
      if (std::regex_match(lines[i], m, include_regex())) {
        if (auto it = memory.find(m[1].str()); it != memory.end()) {
          for (const auto& s : stack)
            if (s == it->first)
              throw std::runtime_error(name + ":" + std::to_string(i + 1) + ": #include cycle through '" + s + "'");
          if (included.insert(it->first).second) expand(it->first, it->second, dir);
          out.text += line_marker(index, int(i) + 2);
          continue;
        }
        fs::path target = find_include(dir, m[1].str(), name + ":" + std::to_string(i + 1));
        std::string canon = fs::weakly_canonical(target).string();
        for (const auto& s : stack)
          if (s == display_path(canon))
            throw std::runtime_error(name + ":" + std::to_string(i + 1) + ": #include cycle through '" + s + "'");
        if (included.insert(canon).second) expand(display_path(canon), read_file(canon), fs::path(canon).parent_path());
        out.text += line_marker(index, int(i) + 2);
      } else if (std::regex_match(lines[i], version_re)) {
        out.text += "\n";  // the loader writes #version itself
      } else {
        out.text += lines[i] + "\n";
      }
    }
    stack.pop_back();
  }
};

std::string prolog(const Defines& defines) {
  std::string s = "#version 450 core\n";
  for (const auto& [k, v] : defines) s += "#define " + k + " " + v + "\n";
  return s;
}

}  // namespace

std::string ShaderSource::key() const { return text; }

void set_shader_file_observer(std::function<void(const std::string&)> observer) {
  file_observer() = std::move(observer);
}

std::string shader_root() {
  if (const char* env = getenv("SHADENET_SHADERS"); env && *env) return fs::absolute(env).string();
  char exe[4096];
  ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
  if (n > 0) {
    exe[n] = 0;
    fs::path p = fs::path(exe).parent_path().parent_path() / "shaders";
    if (fs::is_directory(p)) return p.string();
  }
  return (fs::path(SHADENET_SOURCE_DIR) / "shaders").string();
}

std::string resolve_shader_path(const std::string& path) {
  if (fs::exists(path)) return fs::absolute(path).string();
  fs::path under = fs::path(shader_root()) / path;
  if (fs::exists(under)) return under.string();
  throw std::runtime_error("shader file '" + path + "' not found (looked in the working directory and in " +
                           display_path(shader_root()) + "/)");
}

std::string display_path(const std::string& path) {
  std::error_code ec;
  fs::path abs = fs::weakly_canonical(fs::absolute(path), ec);
  fs::path root = fs::weakly_canonical(project_root(), ec);
  auto rel = abs.lexically_relative(root);
  if (!rel.empty() && *rel.begin() != "..") return rel.string();
  return path;
}

ShaderSource preprocess(const std::string& path, const Defines& defines, const Includes& includes) {
  std::string abs = resolve_shader_path(path);
  ShaderSource src;
  src.text = prolog(defines);
  Expander ex{src, includes, {fs::weakly_canonical(abs).string()}, {}};
  ex.expand(display_path(abs), read_file(abs), fs::path(abs).parent_path());
  return src;
}

ShaderSource preprocess_text(const std::string& name, const std::string& text, const Defines& defines,
                             const Includes& includes) {
  ShaderSource src;
  src.text = prolog(defines);
  Expander ex{src, includes, {}, {}};
  ex.expand(name, text, fs::path(shader_root()));
  return src;
}

namespace {

// Captures one text for capture_source: its includes found beside it become in-memory includes
// named by their file's display path (one line for one line: line numbers stay the file's).
struct Capturer {
  CapturedSource& out;
  std::vector<std::string> stack;

  std::string capture(const std::string& name, const std::string& text, const fs::path& dir) {
    stack.push_back(name);
    std::string result;
    const std::vector<std::string> lines = split_lines(text);
    for (std::size_t i = 0; i < lines.size(); ++i) {
      std::smatch m;
      if (!std::regex_match(lines[i], m, include_regex())) {
        result += lines[i] + "\n";
        continue;
      }
      const std::string where = name + ":" + std::to_string(i + 1);
      const fs::path target = find_include(dir, m[1].str(), where);
      if (!fs::exists(dir / m[1].str())) {  // the runtime's own (shaders/include/, shaders/)
        result += lines[i] + "\n";
        continue;
      }
      const std::string canon = fs::weakly_canonical(target).string(), key = display_path(canon);
      if (key.find_first_of("\"<>") != std::string::npos)
        throw std::runtime_error(where + ": the #included file's path must not hold quotes or angle brackets: " + key);
      if (std::find(stack.begin(), stack.end(), key) != stack.end())
        throw std::runtime_error(where + ": #include cycle through '" + key + "'");
      if (!out.files.count(key)) {
        std::string body = read_file(canon);
        out.files[key] = capture(key, body, fs::path(canon).parent_path());
      }
      result += "#include \"" + key + "\"\n";
    }
    stack.pop_back();
    return result;
  }
};

}  // namespace

CapturedSource capture_source(const std::string& name, const std::string& text, const std::string& dir) {
  if (name.find_first_of("\"<>") != std::string::npos)
    throw std::runtime_error("a GLSL source's name must not hold quotes or angle brackets: " + name);
  CapturedSource src;
  src.name = name;
  Capturer c{src, {}};
  src.text = c.capture(name, text, dir.empty() ? fs::path(".") : fs::path(dir));
  return src;
}

CapturedSource capture_file(const std::string& path) {
  const std::string canon = fs::weakly_canonical(fs::absolute(path)).string();
  return capture_source(display_path(canon), read_file(canon), fs::path(canon).parent_path().string());
}

std::string rewrite_log(const std::string& log, const ShaderSource& src) {
  static const std::regex mesa_re(R"(^(\d+):(\d+)\((\d+)\):\s*(.*)$)");  // 0:12(3): error: ...
  static const std::regex nv_re(R"(^(\d+)\((\d+)\)\s*:\s*(.*)$)");       // 0(12) : error C0000: ...
  std::string out;
  for (const std::string& line : split_lines(log)) {
    std::smatch m;
    int file = -1, lineno = 0;
    std::string msg;
    if (std::regex_match(line, m, mesa_re)) {
      file = std::stoi(m[1]), lineno = std::stoi(m[2]), msg = m[4];
    } else if (std::regex_match(line, m, nv_re)) {
      file = std::stoi(m[1]), lineno = std::stoi(m[2]), msg = m[3];
    }
    if (lineno >= kStride) file = lineno / kStride, lineno %= kStride;
    if (file >= 0 && file < int(src.files.size())) {
      out += src.files[file] + ":" + std::to_string(lineno) + ": " + msg + "\n";
      const auto& lines = src.lines[file];
      if (lineno >= 1 && lineno <= int(lines.size())) out += "    " + lines[lineno - 1] + "\n";
    } else if (!line.empty()) {
      out += line + "\n";
    }
  }
  return out;
}

bool glsl_reserved_word(const std::string& name) {
  // The GLSL 4.50 specification, section 3.6: keywords, then the words reserved for the future.
  static const std::set<std::string> words = {
      "const", "uniform", "buffer", "shared", "attribute", "varying", "coherent", "volatile", "restrict",
      "readonly", "writeonly", "atomic_uint", "layout", "centroid", "flat", "smooth", "noperspective", "patch",
      "sample", "invariant", "precise", "break", "continue", "do", "for", "while", "switch", "case", "default",
      "if", "else", "subroutine", "in", "out", "inout", "int", "void", "bool", "true", "false", "float",
      "double", "discard", "return", "uint", "lowp", "mediump", "highp", "precision", "struct",
      "common", "partition", "active", "asm", "class", "union", "enum", "typedef", "template", "this",
      "resource", "goto", "inline", "noinline", "public", "static", "extern", "external", "interface", "long",
      "short", "half", "fixed", "unsigned", "superp", "input", "output", "hvec2", "hvec3", "hvec4", "fvec2",
      "fvec3", "fvec4", "sampler3DRect", "filter", "sizeof", "cast", "namespace", "using"};
  // The vector, matrix, sampler and image types, by their forms.
  static const std::regex types(R"(([biud]?vec[234])|(d?mat[234](x[234])?)|([iu]?(sampler|image|texture)[0-9A-Z]\w*))");
  return words.count(name) || std::regex_match(name, types);
}

std::string without_glsl_comments(const std::string& text) {
  std::string out = text;
  for (std::size_t i = 0; i + 1 < out.size(); ++i) {
    if (out[i] != '/' || (out[i + 1] != '/' && out[i + 1] != '*')) continue;
    const bool line = out[i + 1] == '/';
    std::size_t end = line ? out.find('\n', i) : out.find("*/", i + 2);
    end = end == std::string::npos ? out.size() : line ? end : end + 2;
    for (std::size_t k = i; k < end; ++k)
      if (out[k] != '\n') out[k] = ' ';
    i = end - 1;
  }
  return out;
}

std::string float_literal(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.9g", float(v));
  std::string s = buf;
  if (s.find_first_of(".eE") == std::string::npos) s += ".0";
  return s;
}

}  // namespace sn::gl
