// A storage buffer read as a texture (GL_TEXTURE_BUFFER). On llvmpipe a texelFetch is a plain
// gather, and a storage-buffer read a loop over the SIMD lanes with a branch per lane: slower to
// run, and far slower for LLVM to compile when a shader does many.
#pragma once
#include <cstddef>

#include "gl/buffer.h"

namespace sn::gl {

// How many elements to allocate for `n` that a BufferTexture will read: n, or n + 1 when n is a
// power of two. llvmpipe compiles a variant of a shader for each combination of its textures'
// sizes being powers of two or not (seconds each for a large kernel); sizes that never are keep
// one variant whatever the data.
std::size_t texture_buffer_size(std::size_t n);

class BufferTexture {
 public:
  // Texels are the buffer's elements (float32 -> R32F, uint32 -> R32UI, vec4 -> RGBA32F, ...).
  // Throws when the buffer has more elements than max_texels(). The buffer must outlive this.
  explicit BufferTexture(const Buffer& buffer);
  ~BufferTexture();
  BufferTexture(const BufferTexture&) = delete;
  BufferTexture& operator=(const BufferTexture&) = delete;

  void bind(unsigned unit) const;  // reads the buffer's current storage (map() replaces it)
  static std::size_t max_texels();  // GL_MAX_TEXTURE_BUFFER_SIZE

 private:
  const Buffer& buffer_;
  unsigned id_ = 0;
  mutable unsigned storage_ = 0;  // the buffer's id() when attached
};

}  // namespace sn::gl
