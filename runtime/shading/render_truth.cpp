#include "shading/render_truth.h"

#include <epoxy/gl.h>

#include <stdexcept>

#include "gl/program.h"
#include "gl/render_target.h"
#include "shading/lighting_gpu.h"

namespace sn::shading {

std::vector<std::string> model_attributes(const LightingParams& p) {
  std::vector<std::string> a = {"normal", "view"};
  for (const auto& x : p.spec().attributes) a.push_back(x);
  return a;
}

io::Image render_truth(const scene::GBuffer& g, const LightingParams& p, const scene::Light& light) {
  for (const auto& a : model_attributes(p)) {
    bool held = false;
    for (const auto& h : g.attributes) held = held || h == a;
    if (!held)
      throw std::invalid_argument("lighting model " + p.spec().name + " reads the G-buffer attribute '" +
                                  a + "', which this G-buffer does not hold");
  }
  gl::ProgramDesc desc;
  desc.vertex = "fullscreen.vert";
  desc.fragment = "shade_truth.frag";
  use_lighting(desc, p);
  auto prog = gl::get_program(desc);
  set_lighting_uniforms(*prog, p, light);
  auto names = model_attributes(p);
  for (std::size_t i = 0; i < names.size(); ++i) {
    glBindTextureUnit(GLuint(i), g.target->color_texture(g.attachment(names[i])));
    prog->set_uniform("u_" + names[i], {double(i)});
  }
  gl::RenderTarget out(g.width, g.height, 1);
  out.bind();
  out.clear({0, 0, 0, 0});
  glDisable(GL_DEPTH_TEST);
  static GLuint vao = 0;  // core profile draws need a VAO, even one without buffers
  if (!vao || !glIsVertexArray(vao)) glCreateVertexArrays(1, &vao);
  glUseProgram(prog->id());
  glBindVertexArray(vao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glEnable(GL_DEPTH_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  io::Image img = out.read(0);
  // The model's contract is a finite radiance everywhere (a dataset of it refuses one that is
  // not): a truth render would otherwise hide a broken model in black pixels.
  std::size_t bad = 0, first = 0;
  for (std::size_t i = 0; i < std::size_t(img.width) * std::size_t(img.height); ++i)
    if (img.pixels[i * 4 + 3] < 0.f && bad++ == 0) first = i;
  if (bad)
    throw std::invalid_argument("lighting model " + p.spec().name + " gives a NaN or infinite radiance at " +
                                std::to_string(bad) + " covered pixel" + (bad == 1 ? "" : "s") + " (the first at (" +
                                std::to_string(first % std::size_t(img.width) + 1) + ", " +
                                std::to_string(first / std::size_t(img.width) + 1) +
                                ")); its shade must be finite for every input (sn.lighting.stress finds where)");
  return img;
}

}  // namespace sn::shading
