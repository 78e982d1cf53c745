#include "io/compose.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace sn::io {

namespace {
std::string size_str(int w, int h) { return std::to_string(w) + "x" + std::to_string(h); }
}  // namespace

void check_compose_inputs(int nw, int nh, int tw, int th, double scale) {
  if (nw != tw || nh != th)
    throw std::invalid_argument("the network image is " + size_str(nw, nh) + " but the truth image is " +
                                size_str(tw, th) + "; they must be the same size");
  if (!(scale > 0) || !std::isfinite(scale))
    throw std::invalid_argument("error scale must be a finite number > 0, got " + std::to_string(scale));
}

std::array<double, 4> error_heat(const std::array<double, 4>& n, const std::array<double, 4>& t, double scale,
                                 Colormap map) {
  if (!(n[3] > 0.5 || t[3] > 0.5)) return {0, 0, 0, 0};
  for (int c = 0; c < 3; ++c)
    if (!std::isfinite(n[c])) return {1, 0, 1, 1};
  double e = (std::abs(n[0] - t[0]) + std::abs(n[1] - t[1]) + std::abs(n[2] - t[2])) / 3.0;
  Color c = colormap(map, std::clamp(e / scale, 0.0, 1.0));
  return {c[0], c[1], c[2], 1};
}

std::array<int, 2> composed_size(Layout layout, int w, int h) {
  return layout == Layout::side ? std::array<int, 2>{2 * w, 2 * h} : std::array<int, 2>{w, h};
}

Image compose(Layout layout, const Image& network, const Image& truth, double scale, Colormap map) {
  if (network.channels != 4 || truth.channels != 4) throw std::invalid_argument("compose needs RGBA images");
  check_compose_inputs(network.width, network.height, truth.width, truth.height, scale);
  auto [ow, oh] = composed_size(layout, network.width, network.height);
  Image out(ow, oh, 4);
  for (int y = 0; y < oh; ++y)
    for (int x = 0; x < ow; ++x) {
      bool side = layout == Layout::side;
      int col = side ? x / network.width : 0, row = side ? y / network.height : 0;
      int panel = side ? row * 2 + col : 2;
      int qx = x - col * network.width, qy = y - row * network.height;
      std::array<double, 4> n, t;
      for (int c = 0; c < 4; ++c) n[c] = network.at(qx, qy, c), t[c] = truth.at(qx, qy, c);
      std::array<double, 4> v = panel == 0 ? t : panel == 1 ? n : panel == 2 ? error_heat(n, t, scale, map)
                                                                         : std::array<double, 4>{0, 0, 0, 0};
      for (int c = 0; c < 4; ++c) out.at(x, y, c) = float(v[c]);
    }
  return out;
}

}  // namespace sn::io
