#include "scene/texture.h"

#include <mutex>

namespace sn::scene {

struct Texture::State {
  std::once_flag decoded;  // not set when decoding throws: the next read tries again, and throws again
  std::vector<unsigned char> encoded;
  std::string what;
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

const io::Image& Texture::operator*() const {
  State& s = *state_;
  std::call_once(s.decoded, [&s] { s.image = io::decode_image(s.encoded, s.what); });
  return s.image;
}

const std::vector<unsigned char>* Texture::encoded() const {
  return state_ && !state_->encoded.empty() ? &state_->encoded : nullptr;
}

}  // namespace sn::scene
