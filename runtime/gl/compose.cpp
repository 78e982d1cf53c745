#include "gl/compose.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "gl/program.h"

namespace sn::gl {

namespace {

std::string size_str(int w, int h) { return std::to_string(w) + "x" + std::to_string(h); }

void check_inputs(int nw, int nh, int tw, int th, double scale) {
  if (nw != tw || nh != th)
    throw std::invalid_argument("the network image is " + size_str(nw, nh) + " but the truth image is " +
                                size_str(tw, th) + "; they must be the same size");
  if (!(scale > 0) || !std::isfinite(scale))
    throw std::invalid_argument("error scale must be a finite number > 0, got " + std::to_string(scale));
}

double clamp01(double x) { return std::clamp(x, 0.0, 1.0); }

}  // namespace

std::array<double, 4> error_heat(const std::array<double, 4>& n, const std::array<double, 4>& t, double scale,
                                 io::Colormap map) {
  if (!(n[3] > 0.5 || t[3] > 0.5)) return {0, 0, 0, 0};
  for (int c = 0; c < 3; ++c)
    if (!std::isfinite(n[c])) return {1, 0, 1, 1};
  double e = (std::abs(n[0] - t[0]) + std::abs(n[1] - t[1]) + std::abs(n[2] - t[2])) / 3.0;
  io::Color c = io::colormap(map, clamp01(e / scale));
  return {c[0], c[1], c[2], 1};
}

std::array<int, 2> composed_size(Layout layout, int w, int h) {
  return layout == Layout::side ? std::array<int, 2>{3 * w, h} : std::array<int, 2>{w, h};
}

void compose(Layout layout, const gl::RenderTarget& network, const gl::RenderTarget& truth, double scale,
             io::Colormap map, gl::RenderTarget& out) {
  check_inputs(network.width(), network.height(), truth.width(), truth.height(), scale);
  auto [ow, oh] = composed_size(layout, network.width(), network.height());
  if (out.width() != ow || out.height() != oh)
    throw std::invalid_argument("the composed image needs a " + size_str(ow, oh) + " target, got " +
                                size_str(out.width(), out.height()));
  auto program = gl::get_program({"live/compose.comp", "", "", {{"LAYOUT_SIDE", layout == Layout::side ? "1" : "0"}}});
  if (layout == Layout::side)  // the error layout does not read it (and the compiler drops it)
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
  gl::dispatch(*program, unsigned(ow + 7) / 8, unsigned(oh + 7) / 8);
  glBindTextureUnit(0, 0);
  glBindTextureUnit(1, 0);
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
}

io::Image compose_reference(Layout layout, const io::Image& network, const io::Image& truth, double scale,
                            io::Colormap map) {
  if (network.channels != 4 || truth.channels != 4)
    throw std::invalid_argument("compose_reference needs RGBA images");
  check_inputs(network.width, network.height, truth.width, truth.height, scale);
  auto [ow, oh] = composed_size(layout, network.width, network.height);
  io::Image out(ow, oh, 4);
  for (int y = 0; y < oh; ++y)
    for (int x = 0; x < ow; ++x) {
      int panel = layout == Layout::side ? x / network.width : 2;
      int qx = layout == Layout::side ? x - panel * network.width : x;
      std::array<double, 4> n, t;
      for (int c = 0; c < 4; ++c) n[c] = network.at(qx, y, c), t[c] = truth.at(qx, y, c);
      std::array<double, 4> v = panel == 0 ? t : panel == 1 ? n : error_heat(n, t, scale, map);
      for (int c = 0; c < 4; ++c) out.at(x, y, c) = float(v[c]);
    }
  return out;
}

}  // namespace sn::gl
