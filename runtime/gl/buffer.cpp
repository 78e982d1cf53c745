#include "gl/buffer.h"

#include <epoxy/gl.h>

#include <cstring>
#include <stdexcept>

#include "gl/context.h"
#include "gl/pool.h"
#include "io/memory.h"

namespace sn::gl {

namespace {
const ElemInfo kInfo[] = {
    {"float32", 1, true, true}, {"uint32", 1, false, false}, {"int32", 1, false, true},
    {"vec2", 2, true, true},    {"vec4", 4, true, true},     {"uvec4", 4, false, false},
    {"ivec4", 4, false, true},
};
// Storage the host never maps lives where the GPU wants it. Mappable storage (persistent,
// coherent) is only made when a buffer is mapped: NVIDIA's driver may keep it in host memory,
// and an H100 run read mid-sized uploads into it as zeros (docs/performance.md, "On a GPU").
constexpr GLbitfield kMapAccess = GL_MAP_READ_BIT | GL_MAP_WRITE_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;

// A buffer object of `bytes` with `flags`; throws when the driver is out of memory.
GLuint create_storage(std::size_t bytes, GLbitfield flags) {
  if (current().info().software) io::check_memory(bytes, "a buffer of " + std::to_string(bytes) + " bytes");
  check_gl_errors_before("creating a buffer");
  GLuint id = 0;
  glCreateBuffers(1, &id);
  glNamedBufferStorage(id, GLsizeiptr(bytes), nullptr, flags);
  if (take_gl_errors() == GL_OUT_OF_MEMORY) {
    glDeleteBuffers(1, &id);
    throw std::runtime_error(std::string("out of ") + device_memory_name() + " for a buffer of " + std::to_string(bytes) +
                             " bytes");
  }
  return id;
}
}  // namespace

const ElemInfo& elem_info(ElemType t) { return kInfo[static_cast<int>(t)]; }

std::string elem_type_names() {
  std::string s;
  for (const ElemInfo& e : kInfo) s += (s.empty() ? "" : ", ") + std::string(e.name);
  return s;
}

ElemType parse_elem_type(const std::string& name) {
  if (name == "float") return ElemType::float32;
  for (int i = 0; i < int(std::size(kInfo)); ++i)
    if (name == kInfo[i].name) return static_cast<ElemType>(i);
  throw std::invalid_argument("unknown buffer type '" + name + "' (valid: " + elem_type_names() + ")");
}

Buffer::Buffer(ElemType type, std::size_t count) : type_(type), count_(count) {
  if (count == 0) throw std::invalid_argument("buffer size must be at least 1 element");
  id_ = create_storage(bytes(), GL_DYNAMIC_STORAGE_BIT);
  const uint32_t zero = 0;
  glClearNamedBufferData(id_, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
}

Buffer::~Buffer() {
  if (mapped_) glUnmapNamedBuffer(id_);
  glDeleteBuffers(1, &id_);
}

static void check_range(const Buffer& b, std::size_t first, std::size_t n) {
  if (first + n > b.components())
    throw std::out_of_range("buffer range " + std::to_string(first) + "+" + std::to_string(n) +
                            " is outside its " + std::to_string(b.components()) + " components");
}

// Through GL even when mapped (persistent mappings allow it): the driver orders the copy after
// the commands before it, where a write through the mapping could land before a pending one.
void Buffer::upload(const void* data, std::size_t first, std::size_t n) {
  check_range(*this, first, n);
  glNamedBufferSubData(id_, GLintptr(first * 4), GLsizeiptr(n * 4), data);
}

void Buffer::download(void* data, std::size_t first, std::size_t n) const {
  check_range(*this, first, n);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  if (mapped_) {
    finish();
    std::memcpy(data, static_cast<const char*>(mapped_) + first * 4, n * 4);
    return;
  }
  glGetNamedBufferSubData(id_, GLintptr(first * 4), GLsizeiptr(n * 4), data);
}

void Buffer::copy_from(const Buffer& src, std::size_t src_first, std::size_t first, std::size_t n) {
  check_range(src, src_first, n);
  check_range(*this, first, n);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);  // shader writes to `src` land before the copy reads them
  glCopyNamedBufferSubData(src.id_, id_, GLintptr(src_first * 4), GLintptr(first * 4), GLsizeiptr(n * 4));
}

void Buffer::fill_float(float v) { glClearNamedBufferData(id_, GL_R32F, GL_RED, GL_FLOAT, &v); }
void Buffer::fill_uint(uint32_t v) { glClearNamedBufferData(id_, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &v); }

std::vector<float> Buffer::download_floats() const {
  std::vector<float> out(components());
  download(out.data(), 0, out.size());
  return out;
}

void* Buffer::map() {
  if (!mapped_) {  // moved once into storage the host can map, its contents copied on the GPU
    GLuint mappable = create_storage(bytes(), GL_DYNAMIC_STORAGE_BIT | kMapAccess);
    glCopyNamedBufferSubData(id_, mappable, 0, 0, GLsizeiptr(bytes()));
    glDeleteBuffers(1, &id_);
    id_ = mappable;
    mapped_ = glMapNamedBufferRange(id_, 0, GLsizeiptr(bytes()), kMapAccess);
    if (!mapped_) throw std::runtime_error("could not map the buffer into host memory");
  }
  finish();
  return mapped_;
}

void finish() {
  glMemoryBarrier(GL_ALL_BARRIER_BITS);
  glFinish();
}

namespace {
Pool<Buffer>& pool() {
  static Pool<Buffer> p(8);
  return p;
}
}  // namespace

std::shared_ptr<Buffer> pooled_buffer(ElemType type, std::size_t count) {
  return pool().take([&](const Buffer& b) { return b.type() == type && b.count() >= count; },
                     [](const Buffer& a, const Buffer& b) { return a.count() < b.count(); },  // the smallest
                     [&] { return std::make_shared<Buffer>(type, count); });
}

void clear_buffer_pool() { pool().clear(); }

}  // namespace sn::gl
