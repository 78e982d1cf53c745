#include "scene/gather.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <string>

#include "gl/program.h"

namespace sn::scene {

Samples gather(const GBuffer& g) {
  // Only the box can hold covered pixels: the buffers and the dispatch are that big, not the
  // frame. The buffers come from the pool (a dataset gathers view after view); the shader
  // writes slots [0, count), and only those are read.
  const PixelBox box = g.box();
  const std::size_t capacity = std::max<std::size_t>(1, std::size_t(std::max(0, box.width())) * std::max(0, box.height()));
  const int n = int(g.attributes.size());
  gl::ProgramDesc desc;
  desc.compute = "gather.comp";
  desc.defines = {{"ATTRIBUTES", std::to_string(n)}};
  auto prog = gl::get_program(desc);

  Samples s;
  s.pixels = gl::pooled_buffer(gl::ElemType::uint32, capacity);
  for (int a = 0; a < n; ++a) s.attributes.push_back(gl::pooled_buffer(gl::ElemType::vec4, capacity));
  gl::Buffer counter(gl::ElemType::uint32, 1);  // zero-filled

  std::vector<double> units;
  for (int a = 0; a < n; ++a) {
    glBindTextureUnit(GLuint(a), g.target->color_texture(a));
    units.push_back(a);
  }
  prog->set_uniform("u_attributes", units);
  prog->set_uniform("u_box", {double(box.x0), double(box.y0), double(box.x1), double(box.y1)});
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, counter.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, s.pixels->id());
  for (int a = 0; a < n; ++a) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, GLuint(2 + a), s.attributes[a]->id());
  if (box.width() > 0 && box.height() > 0)
    gl::dispatch(*prog, unsigned((box.width() + 7) / 8), unsigned((box.height() + 7) / 8));
  uint32_t count = 0;
  counter.download(&count, 0, 1);
  s.count = count;
  return s;
}

std::vector<float> download_vec4(const gl::Buffer& b, std::size_t count) {
  std::vector<float> f(count * 4);
  if (count) b.download(f.data(), 0, f.size());
  return f;
}

std::vector<uint32_t> download_pixels(const Samples& s) {
  std::vector<uint32_t> p(s.count);
  if (s.count) s.pixels->download(p.data(), 0, s.count);
  return p;
}

}  // namespace sn::scene
