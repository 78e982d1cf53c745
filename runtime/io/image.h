// Float images in memory, loaded and saved through OpenImageIO (PNG, EXR, and whatever else it
// reads). Rows run top to bottom, channels are interleaved.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace sn::io {

// What a loaded image may be: io::limits().image_pixels and image_channels (2^28 pixels, 64
// channels until raised, io/limits.h). Larger is an error naming the file, before any pixel is
// read; volumes (depth > 1) are refused.

struct Image {
  // w * h * c, checked against the free memory first (io/memory.h).
  static size_t checked_size(int w, int h, int c);

  int width = 0, height = 0, channels = 0;
  std::vector<float> pixels;  // width * height * channels

  Image() = default;
  Image(int w, int h, int c, float fill = 0.f) : width(w), height(h), channels(c), pixels(checked_size(w, h, c), fill) {}
  float& at(int x, int y, int c) { return pixels[(size_t(y) * width + x) * channels + c]; }
  float at(int x, int y, int c) const { return pixels[(size_t(y) * width + x) * channels + c]; }
};

// Throws naming the file and OpenImageIO's reason when it is missing, not a regular file, not an
// image, a volume, or above the limits.
Image load_image(const std::string& path);
// Decodes an image held in memory (e.g. a texture embedded in a glTF file).
Image decode_image(const std::vector<unsigned char>& bytes, const std::string& what);
// Encodes in memory, then writes through write_file_atomic (temporary file, every write, fsync,
// rename), so a failure -- a full disk included -- never leaves a half-written image. 8-bit formats (PNG, JPEG) are clamped to [0,1] and sRGB-free (values
// stored as given); EXR keeps full float. Throws on an unknown extension.
void save_image(const Image& img, const std::string& path);
// The file save_image writes, in memory: the format from `name`'s extension (8-bit ones clamped).
std::vector<unsigned char> encode_image(const Image& img, const std::string& name);

// Throws "WHAT: pixel (x, y) channel c is not a finite number" for the first NaN or infinity in
// channels [0, channels), scanning by channel.
void check_finite(const Image& img, int channels, const std::string& what);
// |a - b| per channel (sizes must match).
Image difference(const Image& a, const Image& b);
// Mean squared error over channels [0, channels) (all when -1) of the pixels where `mask` (if
// given, channel `mask_channel`) is > 0.5. NaN where a compared pixel is not finite.
double mse(const Image& a, const Image& b, int channels = -1, const Image* mask = nullptr, int mask_channel = 3);

}  // namespace sn::io
