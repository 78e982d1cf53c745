#include "gl/compose.h"

#include <epoxy/gl.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "gl/program.h"

namespace sn::gl {

void compose(io::Layout layout, const gl::RenderTarget& network, const gl::RenderTarget& truth, double scale,
             io::Colormap map, gl::RenderTarget& out) {
  io::check_compose_inputs(network.width(), network.height(), truth.width(), truth.height(), scale);
  auto [ow, oh] = io::composed_size(layout, network.width(), network.height());
  if (out.width() != ow || out.height() != oh)
    throw std::invalid_argument("the composed image needs a " + std::to_string(ow) + "x" + std::to_string(oh) +
                                " target, got " + std::to_string(out.width()) + "x" + std::to_string(out.height()));
  gl::ProgramDesc desc;
  desc.compute = "live/compose.comp";
  desc.defines = {{"LAYOUT_SIDE", layout == io::Layout::side ? "1" : "0"}};
  auto program = gl::get_program(desc);
  if (layout == io::Layout::side)  // the error layout does not read it (and the compiler drops it)
    program->set_uniform("u_panel", {double(network.width()), double(network.height())});
  program->set_uniform("u_scale", {scale});
  std::vector<double> points;  // the colormap's control points, as io::colormap interpolates them
  for (int i = 0; i < 10; ++i) {
    io::Color c = io::colormap(map, i / 9.0);
    points.insert(points.end(), c.begin(), c.end());
  }
  program->set_uniform("u_colormap", points);
  glBindTextureUnit(0, network.color_texture(0));
  glBindTextureUnit(1, truth.color_texture(0));
  glBindImageTexture(0, out.color_texture(0), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  out.mark_drawn();
  gl::dispatch(*program, unsigned(ow + 7) / 8, unsigned(oh + 7) / 8);
  glBindTextureUnit(0, 0);
  glBindTextureUnit(1, 0);
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
}

}  // namespace sn::gl
