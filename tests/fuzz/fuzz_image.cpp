// Fuzz target: sn.image.load. OpenImageIO picks its reader from the file name, so the first
// byte of an input picks the extension and the rest is the file.
#include <exception>
#include <iterator>

#include "fuzz_input.h"
#include "io/image.h"
#include "io/image_codec.h"

// The image module (OpenImageIO's side, io/image_codec.h) loaded before the first input, so that
// libFuzzer counts its coverage from the start.
extern "C" int LLVMFuzzerInitialize(int*, char***) {
  sn::io::image_codec();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  static const char* const extensions[] = {"png", "exr", "hdr", "tga", "bmp", "jpg", "dds", "tif", "ppm", "psd"};
  if (size < 1) return 0;
  std::string name = std::string("input.") + extensions[data[0] % std::size(extensions)];
  std::string path = sn::fuzz::scratch_file(name, data + 1, size - 1);
  try {
    sn::io::Image img = sn::io::load_image(path);
    if (img.pixels.size() != std::size_t(img.width) * img.height * img.channels) __builtin_trap();
  } catch (const std::exception&) {
  }
  return 0;
}
