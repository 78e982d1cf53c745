#include "gl/overlay.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "gl/program.h"

namespace sn::gl {

void blend_over(RenderTarget& target, const io::Image& overlay, int x, int y) {
  if (overlay.channels != 4) throw std::invalid_argument("an overlay must be an RGBA image");
  if (overlay.width < 1 || overlay.height < 1) return;
  std::vector<float> rows(overlay.pixels.size());
  const size_t row = size_t(overlay.width) * 4;
  for (int r = 0; r < overlay.height; ++r)  // GL rows start at the bottom
    std::copy_n(overlay.pixels.begin() + size_t(overlay.height - 1 - r) * row, row, rows.begin() + size_t(r) * row);
  GLuint tex = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &tex);
  glTextureStorage2D(tex, 1, GL_RGBA32F, overlay.width, overlay.height);
  glTextureSubImage2D(tex, 0, 0, 0, overlay.width, overlay.height, GL_RGBA, GL_FLOAT, rows.data());
  auto program = get_program({"live/overlay.comp", "", "", {}, {}});
  program->set_uniform("u_origin", {double(x), double(target.height() - y - overlay.height)});
  glBindTextureUnit(0, tex);
  glBindImageTexture(0, target.color_texture(0), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
  target.mark_drawn();
  dispatch(*program, unsigned(overlay.width + 7) / 8, unsigned(overlay.height + 7) / 8);
  glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  glBindTextureUnit(0, 0);
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
  glDeleteTextures(1, &tex);
}

void copy_color(const RenderTarget& from, RenderTarget& to) {
  if (from.width() != to.width() || from.height() != to.height())
    throw std::invalid_argument("copy_color: " + std::to_string(from.width()) + "x" + std::to_string(from.height()) +
                                " into " + std::to_string(to.width()) + "x" + std::to_string(to.height()));
  glCopyImageSubData(from.color_texture(0), GL_TEXTURE_2D, 0, 0, 0, 0, to.color_texture(0), GL_TEXTURE_2D, 0, 0, 0, 0,
                     from.width(), from.height(), 1);
  to.mark_drawn();
}

void copy_color(const RenderTarget& from, RenderTarget& to, int x, int y, int w, int h) {
  if (x == 0 && y == 0 && w == from.width() && h == from.height() && w == to.width() && h == to.height())
    return copy_color(from, to);
  const int y0 = to.height() - y - h;  // GL rows start at the bottom
  glBlitNamedFramebuffer(from.fbo(), to.fbo(), 0, 0, from.width(), from.height(), x, y0, x + w, y0 + h,
                         GL_COLOR_BUFFER_BIT, GL_LINEAR);
  to.mark_drawn();
}

}  // namespace sn::gl
