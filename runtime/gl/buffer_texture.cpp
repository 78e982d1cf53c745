#include "gl/buffer_texture.h"

#include <epoxy/gl.h>

#include <stdexcept>
#include <string>

namespace sn::gl {

namespace {

GLenum texel_format(ElemType t) {
  switch (t) {
    case ElemType::float32: return GL_R32F;
    case ElemType::uint32: return GL_R32UI;
    case ElemType::int32: return GL_R32I;
    case ElemType::vec2: return GL_RG32F;
    case ElemType::vec4: return GL_RGBA32F;
    case ElemType::uvec4: return GL_RGBA32UI;
    case ElemType::ivec4: return GL_RGBA32I;
  }
  throw std::logic_error("buffer texture: unknown element type");
}

}  // namespace

std::size_t texture_buffer_size(std::size_t n) { return n > 0 && (n & (n - 1)) == 0 ? n + 1 : n; }

std::size_t BufferTexture::max_texels() {
  GLint n = 0;
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &n);
  return std::size_t(n);
}

BufferTexture::BufferTexture(const Buffer& buffer) : buffer_(buffer) {
  if (buffer.count() > max_texels())
    throw std::length_error("buffer texture: " + std::to_string(buffer.count()) + " elements, the GL driver reads at most " +
                            std::to_string(max_texels()));
  glCreateTextures(GL_TEXTURE_BUFFER, 1, &id_);
}

BufferTexture::~BufferTexture() {
  if (id_) glDeleteTextures(1, &id_);
}

void BufferTexture::bind(unsigned unit) const {
  if (storage_ != buffer_.id()) {
    storage_ = buffer_.id();
    glTextureBuffer(id_, texel_format(buffer_.type()), storage_);
  }
  glBindTextureUnit(unit, id_);
}

}  // namespace sn::gl
