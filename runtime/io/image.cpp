#include "io/image.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <unistd.h>

#include "io/atomic_write.h"
#include "io/image_codec.h"
#include "io/limits.h"
#include "io/memory.h"

namespace sn::io {

namespace fs = std::filesystem;

namespace {
Image read_from(std::unique_ptr<ImageSource> in, const std::string& error, const std::string& what) {
  if (!in) throw std::runtime_error(what + ": not a readable image (" + error + ")");
  const ImageHeader spec = in->header();
  if (spec.width <= 0 || spec.height <= 0 || spec.channels <= 0)
    throw std::runtime_error(what + ": image has no pixels");
  // A volume would be written depth times past a 2-D buffer.
  if (spec.depth > 1)
    throw std::runtime_error(what + ": a volume image (" + std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                             "x" + std::to_string(spec.depth) + "); shadenet reads 2-D images");
  const Limits lim = limits();
  const uint64_t pixels = uint64_t(spec.width) * uint64_t(spec.height);
  if (pixels > lim.image_pixels)
    throw std::runtime_error(what + ": " + std::to_string(spec.width) + "x" + std::to_string(spec.height) + " is " +
                             std::to_string(pixels) + " pixels, above the limit of " + std::to_string(lim.image_pixels) +
                             raise_hint("image_pixels"));
  if (uint64_t(spec.channels) > lim.image_channels)
    throw std::runtime_error(what + ": " + std::to_string(spec.channels) + " channels, above the limit of " +
                             std::to_string(lim.image_channels) + raise_hint("image_channels"));
  Image img(spec.width, spec.height, spec.channels);
  std::string reason;
  if (!in->read(img.pixels.data(), &reason)) throw std::runtime_error(what + ": corrupt image data (" + reason + ")");
  return img;
}

// A DDS header that declares depth (DDSD_DEPTH) > 1 is a volume whatever its caps say: without
// the volume cap OpenImageIO reports one slice and then reads all of them (a 253-byte file kept
// it busy for minutes; found by tests/fuzz). Read from the raw header before OpenImageIO opens it.
void refuse_dds_volume(const std::string& path, const std::string& what) {
  unsigned char h[28] = {};
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return;  // OpenImageIO names the problem
  const std::size_t got = std::fread(h, 1, sizeof h, f);
  std::fclose(f);
  auto u32 = [&](int at) { return uint32_t(h[at]) | uint32_t(h[at + 1]) << 8 | uint32_t(h[at + 2]) << 16 | uint32_t(h[at + 3]) << 24; };
  if (got < sizeof h || std::memcmp(h, "DDS ", 4) != 0) return;
  const uint32_t flags = u32(8), height = u32(12), width = u32(16), depth = u32(24);
  if ((flags & 0x800000u) && depth > 1)
    throw std::runtime_error(what + ": a volume image (" + std::to_string(width) + "x" + std::to_string(height) + "x" +
                             std::to_string(depth) + "); shadenet reads 2-D images");
}
}  // namespace

Image load_image(const std::string& path) {
  if (!fs::exists(path)) throw std::runtime_error("image file '" + path + "' does not exist");
  if (!fs::is_regular_file(path)) throw std::runtime_error("image file '" + path + "' is not a regular file");
  const std::string what = "image file '" + path + "'";
  refuse_dds_volume(path, what);
  std::string error;
  auto in = image_codec().open_file(path, &error);
  return read_from(std::move(in), error, what);
}

Image decode_image(const std::vector<unsigned char>& bytes, const std::string& what) {
  // The library picks the reader from a name; sniff PNG/JPEG magic numbers to name it.
  std::string name = "embedded.png";
  if (bytes.size() > 2 && bytes[0] == 0xFF && bytes[1] == 0xD8) name = "embedded.jpg";
  std::string error;
  auto in = image_codec().open_memory(bytes.data(), bytes.size(), name, &error);
  return read_from(std::move(in), error, what);
}

std::vector<unsigned char> encode_image(const Image& img, const std::string& name) {
  std::string ext = fs::path(name).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
  const bool is_float = ext == ".exr" || ext == ".hdr" || ext == ".tif" || ext == ".tiff";
  if (!(is_float || ext == ".png" || ext == ".jpg" || ext == ".jpeg" || ext == ".bmp"))
    throw std::runtime_error("cannot save '" + name + "': unknown image extension '" + ext +
                             "' (valid: .png, .exr, .jpg, .bmp, .tif, .hdr)");
  // Radiance HDR holds RGB only and JPEG no alpha: alpha is dropped, a grey image's value goes to
  // all three (.hdr) or stays grey (.jpg, .bmp).
  const int keep = ext == ".hdr" ? 3 : img.channels == 2 && !is_float && ext != ".png" ? 1 : img.channels;
  if (keep != img.channels) {
    Image out(img.width, img.height, keep);
    const std::size_t channels = std::size_t(img.channels);
    for (std::size_t p = 0; p < std::size_t(img.width) * std::size_t(img.height); ++p)
      for (std::size_t c = 0; c < std::size_t(keep); ++c)
        out.pixels[p * std::size_t(keep) + c] = img.pixels[p * channels + (channels < 3 ? 0 : c)];
    return encode_image(out, name);
  }
  if (ext == ".hdr") {
    // RGBE holds neither negative nor non-finite values (its encoder turned -0.35 into 0.65 and a
    // pixel with one NaN or Inf black): stored as 0, +Inf as the largest float, said aloud.
    constexpr float kRgbeMax = 1e38f;  // FLT_MAX's exponent overflows RGBE's byte: black
    Image out = img;
    std::size_t bad = 0;
    for (float& v : out.pixels) {
      if (std::isfinite(v) && v >= 0.f) continue;
      ++bad;
      v = v == INFINITY ? kRgbeMax : 0.f;
    }
    if (bad)
      std::fprintf(stderr,
                   "warning: %s: %zu negative, NaN or infinite values stored as 0 (+Inf as 1e38, near the largest it holds): "
                   ".hdr cannot hold them; .exr can\n",
                   name.c_str(), bad);
    return image_codec().encode(out, nullptr, name);
  }
  if (is_float) return image_codec().encode(img, nullptr, name);
  std::vector<unsigned char> bytes(img.pixels.size());
  std::size_t nans = 0;
  for (size_t i = 0; i < bytes.size(); ++i) {
    float v = img.pixels[i];
    nans += std::isnan(v);
    v = std::isnan(v) ? 0.f : std::clamp(v, 0.f, 1.f);  // +inf is as bright as it gets
    bytes[i] = (unsigned char)(v * 255.f + 0.5f);
  }
  if (nans)  // 8 bits hold no NaN: stored as 0, said aloud
    std::fprintf(stderr, "warning: %s: %zu NaN values stored as 0 (an 8-bit %s cannot hold NaN; .exr can)\n",
                 name.c_str(), nans, ext.c_str() + 1);
  return image_codec().encode(img, &bytes, name);
}

void save_image(const Image& img, const std::string& path) {
  if (img.pixels.empty()) throw std::runtime_error("cannot save an empty image to '" + path + "'");
  // Encoded in memory, then written whole by write_file_atomic, which checks every write, the
  // flush, fsync and close (OpenImageIO's writers report success on a full disk).
  const std::vector<unsigned char> encoded = encode_image(img, path);
  write_file_atomic(path, std::string(encoded.begin(), encoded.end()), "image");
}

static void same_size(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height || a.channels != b.channels)
    throw std::invalid_argument("images differ in size: " + std::to_string(a.width) + "x" + std::to_string(a.height) +
                                "x" + std::to_string(a.channels) + " vs " + std::to_string(b.width) + "x" +
                                std::to_string(b.height) + "x" + std::to_string(b.channels));
}

void check_finite(const Image& img, int channels, const std::string& what) {
  // A pass over every float in integer bit tests (which vectorize) first; only when it finds one
  // does the scan by channel name it (or find it in a channel not compared).
  uint32_t bad = 0;
  for (const float f : img.pixels) {
    uint32_t u;
    std::memcpy(&u, &f, sizeof u);
    bad |= uint32_t((u & 0x7f800000u) == 0x7f800000u);
  }
  if (!bad) return;
  for (int c = 0; c < channels; ++c)
    for (int i = 0; i < img.width * img.height; ++i)
      if (!std::isfinite(img.pixels[std::size_t(i) * img.channels + c]))
        throw std::invalid_argument(what + ": pixel (" + std::to_string(i % img.width + 1) + ", " +
                                    std::to_string(i / img.width + 1) + ") channel " + std::to_string(c + 1) +
                                    " is not a finite number");
}

Image difference(const Image& a, const Image& b) {
  same_size(a, b);
  Image d(a.width, a.height, a.channels);
  for (size_t i = 0; i < d.pixels.size(); ++i) d.pixels[i] = std::abs(a.pixels[i] - b.pixels[i]);
  return d;
}

double mse(const Image& a, const Image& b, int channels, const Image* mask, int mask_channel) {
  same_size(a, b);
  if (channels == 0) throw std::invalid_argument("mse: 'channels' must be 1.." + std::to_string(a.channels) + " (or all)");
  if (channels < 0 || channels > a.channels) channels = a.channels;
  if (mask && (mask->width != a.width || mask->height != a.height))
    throw std::invalid_argument("mse: the mask is " + std::to_string(mask->width) + "x" + std::to_string(mask->height) +
                                ", the images " + std::to_string(a.width) + "x" + std::to_string(a.height));
  if (mask && (mask_channel < 0 || mask_channel >= mask->channels))
    throw std::invalid_argument("mse: mask channel " + std::to_string(mask_channel + 1) + " outside the mask's channels 1.." +
                                std::to_string(mask->channels));
  // A pixel's squares are summed first, then added to the total: one addition per pixel on the
  // total's dependency chain instead of one per channel.
  double sum = 0;
  size_t n = 0;
  const size_t pixels = size_t(a.width) * size_t(a.height), step = size_t(a.channels);
  for (size_t p = 0; p < pixels; ++p) {
    if (mask && mask->pixels[p * size_t(mask->channels) + size_t(mask_channel)] <= 0.5f) continue;
    const float *pa = a.pixels.data() + p * step, *pb = b.pixels.data() + p * step;
    double here = 0;
    for (int c = 0; c < channels; ++c) {
      const double d = double(pa[c]) - pb[c];
      here += d * d;
    }
    sum += here;
    ++n;
  }
  // No pixel compared is no score: 0 would read as a perfect match (ssim refuses it too).
  if (!n)
    throw std::invalid_argument("mse: the mask covers no pixel (its channel " + std::to_string(mask_channel + 1) +
                                " is above 0.5 nowhere)");
  return sum / (double(n) * channels);
}

size_t Image::checked_size(int w, int h, int c) {
  const size_t n = size_t(w) * size_t(h) * size_t(c);
  check_memory(n * sizeof(float), "a " + std::to_string(w) + "x" + std::to_string(h) + " image of " + std::to_string(c) +
                                      " channel(s)");
  return n;
}

}  // namespace sn::io
