#include "gl/program.h"

#include <epoxy/gl.h>

#include <cmath>
#include <regex>
#include <stdexcept>

#include "gl/context.h"
#include "io/text.h"

namespace sn::gl {

namespace {

unsigned compile(GLenum stage, const ShaderSource& src) {
  GLuint sh = glCreateShader(stage);
  const char* text = src.text.c_str();
  glShaderSource(sh, 1, &text, nullptr);
  glCompileShader(sh);
  GLint ok = 0;
  glGetShaderiv(sh, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    GLint len = 0;
    glGetShaderiv(sh, GL_INFO_LOG_LENGTH, &len);
    std::string log(std::max(len, 1), '\0');
    glGetShaderInfoLog(sh, len, nullptr, log.data());
    glDeleteShader(sh);
    std::string msg = rewrite_log(log.c_str(), src);
    if (!msg.empty() && msg.back() == '\n') msg.pop_back();
    throw std::runtime_error("GLSL compile error in " + src.files[0] + (msg.empty() ? "" : ":\n" + msg));
  }
  return sh;
}

// The names a source declares with `uniform TYPE a, b[4];` (uniform blocks have no ';' first).
void declared_uniforms(const std::string& text, std::set<std::string>& out) {
  static const std::regex decl(R"(\buniform\s+(?:(?:lowp|mediump|highp)\s+)?\w+\s+([^;{]+);)");
  static const std::regex name(R"(([A-Za-z_]\w*)\s*(?:\[[^\]]*\])?\s*(?:,|$))");
  for (std::sregex_iterator it(text.begin(), text.end(), decl), end; it != end; ++it) {
    std::string names = (*it)[1];
    for (std::sregex_iterator n(names.begin(), names.end(), name); n != end; ++n) out.insert((*n)[1]);
  }
}

std::string stage_key(const char* tag, const ShaderSource& s) { return std::string(tag) + "\n" + s.key(); }

std::map<std::string, std::shared_ptr<Program>>& cache() {
  static std::map<std::string, std::shared_ptr<Program>> c;
  return c;
}

}  // namespace

Program::Program(const ProgramDesc& desc) {
  std::vector<unsigned> shaders;
  auto cleanup = [&] {
    for (unsigned s : shaders) glDeleteShader(s);
  };
  compute_ = !desc.compute.empty();
  if (compute_ == (!desc.vertex.empty() || !desc.fragment.empty()))
    throw std::invalid_argument("a program takes either 'compute' or 'vertex' + 'fragment'");
  auto stage = [&](GLenum kind, const std::string& path) {
    ShaderSource src = preprocess(path, desc.defines, desc.includes);
    declared_uniforms(src.text, declared_);
    shaders.push_back(compile(kind, src));
  };
  try {
    if (compute_) {
      stage(GL_COMPUTE_SHADER, desc.compute);
      name_ = desc.compute;
    } else {
      if (desc.vertex.empty() || desc.fragment.empty())
        throw std::invalid_argument("a graphics program needs both 'vertex' and 'fragment'");
      stage(GL_VERTEX_SHADER, desc.vertex);
      stage(GL_FRAGMENT_SHADER, desc.fragment);
      name_ = desc.vertex + " + " + desc.fragment;
    }
  } catch (...) {
    cleanup();
    throw;
  }
  id_ = glCreateProgram();
  for (unsigned s : shaders) glAttachShader(id_, s);
  glLinkProgram(id_);
  cleanup();
  GLint ok = 0;
  glGetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint len = 0;
    glGetProgramiv(id_, GL_INFO_LOG_LENGTH, &len);
    std::string log(std::max(len, 1), '\0');
    glGetProgramInfoLog(id_, len, nullptr, log.data());
    glDeleteProgram(id_);
    throw std::runtime_error(name_ + ": link failed: " + std::string(log.c_str()));
  }
  if (compute_) glGetProgramiv(id_, GL_COMPUTE_WORK_GROUP_SIZE, local_size_);

  GLint count = 0;
  glGetProgramInterfaceiv(id_, GL_UNIFORM, GL_ACTIVE_RESOURCES, &count);
  for (GLint i = 0; i < count; ++i) {
    const GLenum props[] = {GL_NAME_LENGTH, GL_TYPE, GL_LOCATION, GL_ARRAY_SIZE};
    GLint vals[4];
    glGetProgramResourceiv(id_, GL_UNIFORM, i, 4, props, 4, nullptr, vals);
    if (vals[2] < 0) continue;  // a block member
    std::string n(vals[0], '\0');
    glGetProgramResourceName(id_, GL_UNIFORM, i, vals[0], nullptr, n.data());
    n.resize(n.find('\0') == std::string::npos ? n.size() : n.find('\0'));
    if (n.size() > 3 && n.compare(n.size() - 3, 3, "[0]") == 0) n.resize(n.size() - 3);
    uniforms_[n] = UniformInfo{vals[2], unsigned(vals[1]), vals[3]};
  }

  glGetProgramInterfaceiv(id_, GL_SHADER_STORAGE_BLOCK, GL_ACTIVE_RESOURCES, &count);
  for (GLint i = 0; i < count; ++i) {
    const GLenum props[] = {GL_NAME_LENGTH, GL_BUFFER_BINDING};
    GLint vals[2];
    glGetProgramResourceiv(id_, GL_SHADER_STORAGE_BLOCK, GLuint(i), 2, props, 2, nullptr, vals);
    std::string n(vals[0], '\0');
    glGetProgramResourceName(id_, GL_SHADER_STORAGE_BLOCK, GLuint(i), vals[0], nullptr, n.data());
    n.resize(n.find('\0') == std::string::npos ? n.size() : n.find('\0'));
    storage_blocks_.push_back({n, vals[1]});
  }
}

std::string Program::shared_storage_binding() const {
  for (std::size_t i = 0; i < storage_blocks_.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (storage_blocks_[i].binding == storage_blocks_[j].binding)
        return "buffer blocks '" + storage_blocks_[j].name + "' and '" + storage_blocks_[i].name + "' share binding " +
               std::to_string(storage_blocks_[i].binding) + " (a block without layout(binding = N) gets 0)";
  return "";
}

Program::~Program() { glDeleteProgram(id_); }

const UniformInfo* Program::uniform(const std::string& name) const {
  auto it = uniforms_.find(name);
  return it == uniforms_.end() ? nullptr : &it->second;
}

std::vector<std::string> Program::uniform_names() const {
  std::vector<std::string> v;
  for (const auto& [k, _] : uniforms_) v.push_back(k);
  return v;
}

bool Program::optimised_away(const std::string& name) const { return !uniform(name) && declared_.count(name); }

bool Program::set_uniform(const std::string& name, const std::vector<double>& v) {
  const UniformInfo* u = uniform(name);
  if (!u && declared_.count(name)) return false;
  if (!u) {
    std::string valid;
    for (const auto& n : uniform_names()) valid += (valid.empty() ? "" : ", ") + n;
    throw std::invalid_argument("program " + name_ + " has no uniform '" + name + "' (valid: " +
                                (valid.empty() ? "none" : valid) + ")");
  }
  auto need = [&](size_t n) {
    if (v.size() != n * size_t(u->size))
      throw std::invalid_argument("uniform '" + name + "' takes " + std::to_string(n * u->size) + " numbers, got " +
                                  std::to_string(v.size()));
  };
  // An int or uint uniform takes whole numbers in its GLSL type's range: the casts below turned
  // 2.7 into 2, -1 into 4294967295 and NaN into 0.
  auto whole = [&](double lo, double hi, const char* type) {
    for (double x : v)
      if (!(x == std::floor(x) && x >= lo && x <= hi))
        throw std::invalid_argument("uniform '" + name + "' (" + type + "): " + io::whole_text(x) +
                                    " is not a whole number in " + io::whole_text(lo) + ".." + io::whole_text(hi));
  };
  switch (u->type) {
    case GL_INT: case GL_INT_VEC2: case GL_INT_VEC3: case GL_INT_VEC4: case GL_BOOL: case GL_SAMPLER_2D: case GL_IMAGE_2D:
      whole(-2147483648.0, 2147483647.0, "int");
      break;
    case GL_UNSIGNED_INT: case GL_UNSIGNED_INT_VEC2: case GL_UNSIGNED_INT_VEC3: case GL_UNSIGNED_INT_VEC4:
      whole(0, 4294967295.0, "uint");
      break;
    default:  // float: a NaN, an infinity or a double past float's range reached the shader as NaN or inf
      for (double x : v)
        if (!(std::abs(x) <= double(std::numeric_limits<float>::max())))
          throw std::invalid_argument("uniform '" + name + "' (float): " + io::number_text(x) +
                                      " is not a finite number in float's range (|x| <= 3.40282e+38)");
  }
  std::vector<float> f(v.begin(), v.end());
  std::vector<int> iv(v.size());
  std::vector<unsigned> uv(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) {  // the casts only where the value fits (else UB)
    iv[i] = v[i] >= -2147483648.0 && v[i] <= 2147483647.0 ? int(v[i]) : 0;
    uv[i] = v[i] >= 0 && v[i] <= 4294967295.0 ? unsigned(v[i]) : 0;
  }
  GLuint p = id_;
  GLint loc = u->location, n = u->size;
  switch (u->type) {
    case GL_FLOAT: need(1), glProgramUniform1fv(p, loc, n, f.data()); break;
    case GL_FLOAT_VEC2: need(2), glProgramUniform2fv(p, loc, n, f.data()); break;
    case GL_FLOAT_VEC3: need(3), glProgramUniform3fv(p, loc, n, f.data()); break;
    case GL_FLOAT_VEC4: need(4), glProgramUniform4fv(p, loc, n, f.data()); break;
    case GL_FLOAT_MAT3: need(9), glProgramUniformMatrix3fv(p, loc, n, GL_FALSE, f.data()); break;
    case GL_FLOAT_MAT4: need(16), glProgramUniformMatrix4fv(p, loc, n, GL_FALSE, f.data()); break;
    case GL_INT: case GL_BOOL: case GL_SAMPLER_2D: case GL_IMAGE_2D:
      need(1), glProgramUniform1iv(p, loc, n, iv.data()); break;
    case GL_INT_VEC2: need(2), glProgramUniform2iv(p, loc, n, iv.data()); break;
    case GL_INT_VEC3: need(3), glProgramUniform3iv(p, loc, n, iv.data()); break;
    case GL_INT_VEC4: need(4), glProgramUniform4iv(p, loc, n, iv.data()); break;
    case GL_UNSIGNED_INT: need(1), glProgramUniform1uiv(p, loc, n, uv.data()); break;
    case GL_UNSIGNED_INT_VEC2: need(2), glProgramUniform2uiv(p, loc, n, uv.data()); break;
    case GL_UNSIGNED_INT_VEC3: need(3), glProgramUniform3uiv(p, loc, n, uv.data()); break;
    case GL_UNSIGNED_INT_VEC4: need(4), glProgramUniform4uiv(p, loc, n, uv.data()); break;
    default: throw std::invalid_argument("uniform '" + name + "' has a type shadenet cannot set from numbers");
  }
  return true;
}

namespace {

std::shared_ptr<Program> build_program(const ProgramDesc& desc) {
  // The key is the preprocessed text, so an edited file or include is a new program.
  // Checked before the cache: a cached compute program answered for {compute, vertex} too.
  const bool graphics = !desc.vertex.empty() && !desc.fragment.empty();
  if (desc.compute.empty() ? !graphics : !desc.vertex.empty() || !desc.fragment.empty())
    throw std::invalid_argument("a program takes either 'compute' or 'vertex' + 'fragment'");
  std::string key;
  if (!desc.compute.empty()) {
    key = stage_key("compute", preprocess(desc.compute, desc.defines, desc.includes));
  } else {
    key = stage_key("vertex", preprocess(desc.vertex, desc.defines, desc.includes)) +
          stage_key("fragment", preprocess(desc.fragment, desc.defines, desc.includes));
  }
  auto& c = cache();
  auto it = c.find(key);
  if (it != c.end()) return it->second;
  auto p = std::make_shared<Program>(desc);
  c.emplace(key, p);
  return p;
}

std::function<void(const std::string&)>& fallback_sink() {
  static std::function<void(const std::string&)> f;
  return f;
}

// The last program that built for each request (paths + defines), for set_program_fallback.
std::map<std::string, std::shared_ptr<Program>>& last_good() {
  static std::map<std::string, std::shared_ptr<Program>> m;
  return m;
}

int& fallback_suspended() {
  static int n = 0;
  return n;
}

}  // namespace

void set_program_fallback(std::function<void(const std::string&)> sink) { fallback_sink() = std::move(sink); }

NoProgramFallback::NoProgramFallback() { ++fallback_suspended(); }
NoProgramFallback::~NoProgramFallback() { --fallback_suspended(); }

std::shared_ptr<Program> get_program(const ProgramDesc& desc) {
  std::string request = desc.compute + "|" + desc.vertex + "|" + desc.fragment;
  for (const auto& [k, v] : desc.defines) request += "|" + k + "=" + v;
  for (const auto& [k, v] : desc.includes) request += "|#include " + k;
  try {
    auto p = build_program(desc);
    last_good()[request] = p;
    return p;
  } catch (const std::exception& e) {
    auto it = last_good().find(request);
    if (!fallback_sink() || fallback_suspended() > 0 || it == last_good().end()) throw;
    fallback_sink()(e.what());
    return it->second;
  }
}

void clear_program_cache() {
  cache().clear();
  last_good().clear();
}
std::size_t program_cache_size() { return cache().size(); }

void dispatch_without_barrier(Program& p, unsigned gx, unsigned gy, unsigned gz) {
  if (!p.is_compute()) throw std::invalid_argument("dispatch needs a compute program, got " + p.name());
  GLint max[3];
  for (int i = 0; i < 3; ++i) glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, i, &max[i]);
  if (gx == 0 || gy == 0 || gz == 0 || gx > unsigned(max[0]) || gy > unsigned(max[1]) || gz > unsigned(max[2]))
    throw std::invalid_argument("workgroup count " + std::to_string(gx) + "x" + std::to_string(gy) + "x" +
                                std::to_string(gz) + " is outside 1..(" + std::to_string(max[0]) + "x" +
                                std::to_string(max[1]) + "x" + std::to_string(max[2]) + ")");
  check_gl_errors_before("dispatching " + p.name());
  glUseProgram(p.id());
  glDispatchCompute(gx, gy, gz);
  // A dispatch the driver refuses leaves its outputs as they were: an error, not a silent result.
  if (GLenum e = take_gl_errors(); e != GL_NO_ERROR)
    throw std::runtime_error("dispatching " + p.name() + " (" + std::to_string(gx) + "x" + std::to_string(gy) + "x" +
                             std::to_string(gz) + " workgroups) failed: " + gl_error_text(e) +
                             " (SHADENET_GL_DEBUG=1 prints the driver's reason)");
}

void dispatch(Program& p, unsigned gx, unsigned gy, unsigned gz) {
  dispatch_without_barrier(p, gx, gy, gz);
  glMemoryBarrier(GL_ALL_BARRIER_BITS);
}

}  // namespace sn::gl
