#include "scene/texture.h"

#include <cmath>
#include <mutex>
#include <stdexcept>

namespace sn::scene {

struct Texture::State {
  std::once_flag decoded;  // not set when decoding throws: the next read tries again, and throws again
  std::vector<unsigned char> encoded;
  std::string what;
  std::string error;  // set: unreadable, every read throws it
  io::Image image;
};

Texture::Texture(io::Image image) : state_(std::make_shared<State>()) {
  std::call_once(state_->decoded, [] {});
  state_->image = std::move(image);
}

Texture::Texture(std::vector<unsigned char> encoded, std::string what) : state_(std::make_shared<State>()) {
  state_->encoded = std::move(encoded);
  state_->what = std::move(what);
}

Texture Texture::unreadable(std::string error) {
  Texture t;
  t.state_ = std::make_shared<State>();
  t.state_->error = std::move(error);
  return t;
}

const io::Image& Texture::operator*() const {
  State& s = *state_;
  if (!s.error.empty()) throw std::runtime_error(s.error);
  std::call_once(s.decoded, [&s] { s.image = io::decode_image(s.encoded, s.what); });
  return s.image;
}

const std::vector<unsigned char>* Texture::encoded() const {
  return state_ && !state_->encoded.empty() ? &state_->encoded : nullptr;
}

int gl_value(Wrap w) { return w == Wrap::clamp_to_edge ? 33071 : w == Wrap::mirrored_repeat ? 33648 : 10497; }
int gl_value(MagFilter f) { return f == MagFilter::nearest ? 9728 : 9729; }
int gl_value(MinFilter f) { return f <= MinFilter::linear ? 9728 + int(f) : 9984 + int(f) - 2; }

int wrap_texel(Wrap w, int i, int size) {
  auto mod = [](int a, int n) { return ((a % n) + n) % n; };
  switch (w) {
    case Wrap::clamp_to_edge: return i < 0 ? 0 : i >= size ? size - 1 : i;
    case Wrap::mirrored_repeat: {
      int a = mod(i, 2 * size) - size;
      return (size - 1) - (a >= 0 ? a : -(1 + a));
    }
    case Wrap::repeat: break;
  }
  return mod(i, size);
}

double sample_lod0(const io::Image& img, const Sampler& sampler, double u, double v, int channel) {
  auto texel = [&](double x, double y) {
    return double(img.at(wrap_texel(sampler.s, int(x), img.width), wrap_texel(sampler.t, int(y), img.height), channel));
  };
  if (sampler.mag == MagFilter::nearest) return texel(std::floor(u * img.width), std::floor(v * img.height));
  const double fx = u * img.width - 0.5, fy = v * img.height - 0.5;
  const double x0 = std::floor(fx), y0 = std::floor(fy), ax = fx - x0, ay = fy - y0;
  return (1 - ay) * ((1 - ax) * texel(x0, y0) + ax * texel(x0 + 1, y0)) +
         ay * ((1 - ax) * texel(x0, y0 + 1) + ax * texel(x0 + 1, y0 + 1));
}

}  // namespace sn::scene
