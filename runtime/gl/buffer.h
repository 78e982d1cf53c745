// A typed GPU storage buffer (std430 layout): what scripts fill, dispatch over and read back.
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace sn::gl {

enum class ElemType { float32, uint32, int32, vec2, vec4, uvec4, ivec4 };

struct ElemInfo {
  const char* name;
  int components;   // scalars per element
  bool is_float;    // float components; otherwise 32-bit integers
  bool is_signed;   // int32 / ivec4
};
const ElemInfo& elem_info(ElemType t);
// Parses "float32" (alias "float"), "uint32", "int32", "vec2", "vec4", "uvec4", "ivec4";
// throws listing the valid names.
ElemType parse_elem_type(const std::string& name);
std::string elem_type_names();

class Buffer {
 public:
  Buffer(ElemType type, std::size_t count);  // zero-filled
  ~Buffer();
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;

  unsigned id() const { return id_; }
  ElemType type() const { return type_; }
  std::size_t count() const { return count_; }  // elements
  std::size_t components() const { return count_ * elem_info(type_).components; }
  std::size_t bytes() const { return components() * 4; }

  // Raw 32-bit component access; `first` and `n` count components, not elements.
  void upload(const void* data, std::size_t first, std::size_t n);
  void download(void* data, std::size_t first, std::size_t n) const;
  // n components of `src` from src_first to here from `first`, on the device (no host round trip).
  void copy_from(const Buffer& src, std::size_t src_first, std::size_t first, std::size_t n);
  void fill_float(float v);
  void fill_uint(uint32_t v);
  std::vector<float> download_floats() const;

  // A pointer to the whole buffer mapped into host memory (persistent, coherent), valid while
  // the buffer lives. GPU writes become visible after sn::gl::finish(). The first call moves the
  // contents to new, mappable storage: id() changes, so bind the buffer after mapping it.
  void* map();

 private:
  unsigned id_ = 0;
  ElemType type_;
  std::size_t count_;
  void* mapped_ = nullptr;
};

// A buffer of at least `count` elements of `type` that nobody else holds (no other shared_ptr to
// it), reused from earlier calls when one is idle: a gather per view then costs no allocation
// (llvmpipe faults in and zeroes a new buffer's pages). Its contents are what was last written
// there, and its count() may be larger. At most 8 idle buffers are kept.
std::shared_ptr<Buffer> pooled_buffer(ElemType type, std::size_t count);
// Frees the idle buffers (destroy_current calls it: GL objects die before their context).
void clear_buffer_pool();

// Waits until every submitted GL command has completed and its writes are visible.
void finish();

}  // namespace sn::gl
