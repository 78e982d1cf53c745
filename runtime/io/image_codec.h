// OpenImageIO behind a module loaded on first use. Linked into the program, it and its libraries
// (ldd: 269 for the program then, 21 without) made every start about 0.15 s slower (their
// symbols bound at load time; measured), although most runs of a script or a test never read,
// write or label an image. Every call into OpenImageIO lives in the module (libshadenet_image.so,
// built beside the program, runtime/io/image_module.cpp); the rest of the runtime reaches it
// through this table.
#pragma once
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "io/image.h"

namespace sn::io {

struct ImageHeader {
  int width = 0, height = 0, depth = 1, channels = 0;
};

// An opened image: its header, then its pixels.
class ImageSource {
 public:
  virtual ~ImageSource() = default;
  virtual ImageHeader header() const = 0;
  // width x height x channels floats; false with the library's reason in `error`.
  virtual bool read(float* pixels, std::string* error) = 0;
};

// A text's extent drawn at a size, relative to its origin on the baseline (y up is negative).
struct TextBox {
  bool defined = false;
  int x0 = 0, x1 = 0, y0 = 0, y1 = 0;
};

struct ImageCodec {
  int version;  // kImageCodecVersion: a module from another build is refused
  // null with the library's reason in `error` when the file or bytes are not a readable image;
  // `name`'s extension tells the format of bytes in memory.
  std::unique_ptr<ImageSource> (*open_file)(const std::string& path, std::string* error);
  std::unique_ptr<ImageSource> (*open_memory)(const unsigned char* bytes, std::size_t size, const std::string& name,
                                              std::string* error);
  // The encoded file: the format from `name`'s extension, float pixels or 8 bits (`bytes`,
  // already clamped and rounded). Throws "cannot save 'name': reason".
  std::vector<unsigned char> (*encode)(const Image& img, const std::vector<unsigned char>* bytes, const std::string& name);
  TextBox (*text_size)(const std::string& text, int size, const std::string& font);
  // Draws into `img` (float pixels); false with the reason in `error`.
  bool (*render_text)(Image& img, int x, int baseline, const std::string& text, int size, const std::string& font,
                      const std::vector<float>& color, std::string* error);
};
constexpr int kImageCodecVersion = 1;

// The module's table, loaded on the first call (and kept): from $SHADENET_IMAGE_MODULE when set,
// else beside the running program, else where the build put it. Throws naming each path tried
// and the loader's reason when none loads.
const ImageCodec& image_codec();

}  // namespace sn::io
