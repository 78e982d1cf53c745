#include "scene/texture.h"

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

}  // namespace sn::scene
