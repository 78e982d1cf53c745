// A mesh's base-colour texture: none, an image, or a file's encoded bytes decoded on first read.
// Loading a textured glTF file does not decode its texture: decoding loads OpenImageIO's module
// (io/image_codec.h; Table 4.1's scene step took 0.24-0.64 s with it, 0.006-0.009 s without), and
// most uses of a mesh (a G-buffer of normals and views, a network's render) never sample it.
// Copies share one decoded image, decoded at most once.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "io/image.h"

namespace sn::scene {

// How a texture coordinate outside [0, 1] finds a texel, per axis: glTF's sampler wrapS / wrapT.
enum class Wrap { repeat, clamp_to_edge, mirrored_repeat };
// How a texel's colour is found where the texture is magnified (and at level 0): glTF's magFilter.
enum class MagFilter { nearest, linear };
// ... and where it is minified: glTF's minFilter, OpenGL's names.
enum class MinFilter {
  nearest,
  linear,
  nearest_mipmap_nearest,
  linear_mipmap_nearest,
  nearest_mipmap_linear,
  linear_mipmap_linear
};
struct Sampler {
  Wrap s = Wrap::repeat, t = Wrap::repeat;  // glTF's default
  // A file that leaves the filters undefined gets trilinear filtering.
  MagFilter mag = MagFilter::linear;
  MinFilter min = MinFilter::linear_mipmap_linear;
  bool operator==(const Sampler& o) const { return s == o.s && t == o.t && mag == o.mag && min == o.min; }
};

// OpenGL's number for each, which glTF's samplers use too (10497 repeat, 9728 nearest, ...).
int gl_value(Wrap w);
int gl_value(MagFilter f);
int gl_value(MinFilter f);

// Texel `i` of an axis `size` texels long, wrapped as OpenGL does (4.5 core, section 8.14.2).
int wrap_texel(Wrap w, int i, int size);
// The CPU twin of textureLod(u_base_color, uv, 0) on `img` (gpu_mesh.h): texel centres at
// (i + 0.5) / size, each axis wrapped as `sampler` says; the texel uv lies in (magFilter nearest)
// or bilinear between the four around it (linear).
double sample_lod0(const io::Image& img, const Sampler& sampler, double u, double v, int channel);

class Texture {
 public:
  Texture() = default;  // none
  Texture(io::Image image);
  // Decoded on first read; a decoding error is thrown then, naming `what` (e.g. "mesh file
  // 'cloth.glb': base-colour texture (image 0)").
  Texture(std::vector<unsigned char> encoded, std::string what);
  // A texture the file names but that could not be read (a missing or unreadable image file):
  // reading it throws `error`, so a mesh whose texture is never sampled still loads.
  static Texture unreadable(std::string error);

  bool has_value() const { return bool(state_); }
  explicit operator bool() const { return has_value(); }
  // The pixels (decoding them on first read). Only for a texture that has a value.
  const io::Image& operator*() const;
  const io::Image* operator->() const { return &**this; }
  // The encoded bytes it was made from, or null for none or one made from an image.
  const std::vector<unsigned char>* encoded() const;

  Sampler sampler;  // how draws sample it (the file's; a copy may change its own)

 private:
  struct State;
  std::shared_ptr<State> state_;
};

}  // namespace sn::scene
