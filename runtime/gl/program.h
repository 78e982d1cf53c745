// Compute and graphics programs built from files under shaders/, specialised by #defines and
// cached by their full preprocessed source, so the same request never compiles twice.
#pragma once
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "gl/shader_source.h"

namespace sn::gl {

struct ProgramDesc {
  std::string compute, vertex, fragment;  // paths; compute xor (vertex + fragment)
  Defines defines;
  Includes includes;  // #include names served from memory (see shader_source.h)
};

struct StorageBlock {
  std::string name;
  int binding;  // layout(binding = N), 0 when the shader gives none
};

struct UniformInfo {
  int location;
  unsigned type;  // GL_FLOAT, GL_FLOAT_VEC3, GL_INT, GL_FLOAT_MAT4, GL_SAMPLER_2D, ...
  int size;       // array length
};

class Program {
 public:
  // Compiles and links; throws "shaders/FILE.glsl:LINE: message" (with the source line) on error.
  explicit Program(const ProgramDesc& desc);
  ~Program();
  Program(const Program&) = delete;
  Program& operator=(const Program&) = delete;

  unsigned id() const { return id_; }
  bool is_compute() const { return compute_; }
  const std::string& name() const { return name_; }
  int local_size(int axis) const { return local_size_[axis]; }

  const UniformInfo* uniform(const std::string& name) const;
  std::vector<std::string> uniform_names() const;
  const std::vector<StorageBlock>& storage_blocks() const { return storage_blocks_; }
  // "" when every storage block has its own binding; else which two share one (binding buffers
  // to such a program would feed one block's buffer to both).
  std::string shared_storage_binding() const;
  // Sets a uniform from numbers (converted to its declared type); throws for an unknown name
  // (listing the valid ones) or a wrong number of values. A uniform the source declares but the
  // compiler removed (its use commented out) is no error: returns false and sets nothing.
  bool set_uniform(const std::string& name, const std::vector<double>& values);
  // Declared in the source but not active in the linked program.
  bool optimised_away(const std::string& name) const;

 private:
  unsigned id_ = 0;
  bool compute_ = false;
  std::string name_;
  int local_size_[3] = {1, 1, 1};
  std::map<std::string, UniformInfo> uniforms_;
  std::set<std::string> declared_;  // every `uniform` the stages' sources declare, active or not
  std::vector<StorageBlock> storage_blocks_;
};

// The cache: equal sources and defines give the same Program object.
std::shared_ptr<Program> get_program(const ProgramDesc& desc);
void clear_program_cache();
std::size_t program_cache_size();

// Live mode: when a program that built before fails after an edit of its files, get_program
// hands back the last good one and reports the error to `sink` instead of throwing, so the
// window keeps running while the shader is broken. Empty = throw (the default).
void set_program_fallback(std::function<void(const std::string& error)> sink);
// While one lives, get_program throws as it does without a fallback: a definition being checked
// (a lighting model's, an activation's, an encoding's) must compile as given, never have the last
// good program of the same files stand in for it.
class NoProgramFallback {
 public:
  NoProgramFallback();
  ~NoProgramFallback();
  NoProgramFallback(const NoProgramFallback&) = delete;
  NoProgramFallback& operator=(const NoProgramFallback&) = delete;
};

// Runs `groups` workgroups of the bound compute program and orders its writes before later reads.
void dispatch(Program& p, unsigned gx, unsigned gy = 1, unsigned gz = 1);
// The same without the barrier: dispatches over separate buffers, issued one after another,
// may then run side by side; the caller orders their writes (glMemoryBarrier) before reading.
void dispatch_without_barrier(Program& p, unsigned gx, unsigned gy = 1, unsigned gz = 1);

}  // namespace sn::gl
