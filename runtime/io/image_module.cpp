// The image module (io/image_codec.h): every call into OpenImageIO, built as its own shared
// library and loaded on first use.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <stdexcept>

#include "io/image_codec.h"

namespace sn::io {

namespace {

class OiioSource : public ImageSource {
 public:
  // `memory` (may be null) must outlive the reader: it is the reader's file.
  OiioSource(std::unique_ptr<OIIO::Filesystem::IOMemReader> memory, std::unique_ptr<OIIO::ImageInput> in)
      : memory_(std::move(memory)), in_(std::move(in)) {}

  ImageHeader header() const override {
    const OIIO::ImageSpec& s = in_->spec();
    return {s.width, s.height, s.depth, s.nchannels};
  }

  bool read(float* pixels, std::string* error) override {
    const OIIO::ImageSpec& spec = in_->spec();
    bool ok = true;
    if (spec.tile_width == 0) {
      // read_image converts through a buffer of at least 256 scanlines whatever the image's
      // height (a 26-byte PPM declaring 33,333,323 x 2 pixels asked for 25.6 GB; found by
      // tests/fuzz): scanline files are read a row at a time, so memory is the image and one row.
      const std::size_t row = std::size_t(spec.width) * std::size_t(spec.nchannels);
      for (int y = 0; ok && y < spec.height; ++y)
        ok = in_->read_scanline(spec.y + y, spec.z, OIIO::TypeDesc::FLOAT, pixels + std::size_t(y) * row);
    } else {
      ok = in_->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels);
    }
    // A reader may finish and only record what went wrong (libjpeg fills a truncated file's
    // missing rows with grey and says "Premature end of JPEG file"): that is a failed read too.
    if (ok && in_->has_error()) ok = false;
    if (!ok) *error = in_->geterror();
    in_->close();
    return ok;
  }

 private:
  std::unique_ptr<OIIO::Filesystem::IOMemReader> memory_;
  std::unique_ptr<OIIO::ImageInput> in_;
};

// shadenet's pixels are unassociated (colour not multiplied by alpha): OpenImageIO would
// multiply a PNG's colour by its alpha on reading and divide by it on writing, so that a colour
// under alpha 0.5 came back halved where it was over 0.5, and one under alpha 0 as black.
OIIO::ImageSpec unassociated() {
  OIIO::ImageSpec spec;
  spec.attribute("oiio:UnassociatedAlpha", 1);
  return spec;
}

std::unique_ptr<ImageSource> open_file(const std::string& path, std::string* error) {
  const OIIO::ImageSpec config = unassociated();
  auto in = OIIO::ImageInput::open(path, &config);
  if (!in) return *error = OIIO::geterror(), nullptr;
  return std::make_unique<OiioSource>(nullptr, std::move(in));
}

std::unique_ptr<ImageSource> open_memory(const unsigned char* bytes, std::size_t size, const std::string& name,
                                         std::string* error) {
  auto mem = std::make_unique<OIIO::Filesystem::IOMemReader>(const_cast<unsigned char*>(bytes), size);
  // A reader opened with a configuration takes its proxy from it ("oiio:ioproxy", a PTR attribute
  // that holds the pointer: given &mem instead, OpenImageIO read the vtable and crashed).
  OIIO::ImageSpec config = unassociated();
  OIIO::Filesystem::IOProxy* proxy = mem.get();
  config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
  auto in = OIIO::ImageInput::open(name, &config, proxy);
  if (!in) return *error = OIIO::geterror(), nullptr;
  return std::make_unique<OiioSource>(std::move(mem), std::move(in));
}

std::vector<unsigned char> encode(const Image& img, const std::vector<unsigned char>* bytes, const std::string& name) {
  auto out = OIIO::ImageOutput::create(name);
  if (!out) throw std::runtime_error("cannot save '" + name + "': " + OIIO::geterror());
  if (!out->supports("ioproxy"))
    throw std::runtime_error("cannot save '" + name + "': this build's " + out->format_name() +
                             " writer cannot write to memory (valid: .png, .exr, .jpg, .bmp, .tif, .hdr where supported)");
  std::vector<unsigned char> encoded;
  OIIO::Filesystem::IOVecOutput memory(encoded);
  out->set_ioproxy(&memory);
  const OIIO::TypeDesc type = bytes ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT;
  OIIO::ImageSpec spec(img.width, img.height, img.channels, type);
  spec.attribute("oiio:UnassociatedAlpha", 1);
  if (!out->open(name, spec)) throw std::runtime_error("cannot save '" + name + "': " + out->geterror());
  const bool wrote = bytes ? out->write_image(type, bytes->data()) : out->write_image(type, img.pixels.data());
  std::string err = wrote ? "" : out->geterror();
  const bool ok = out->close() && wrote;
  if (!ok) throw std::runtime_error("cannot save '" + name + "': " + (err.empty() ? out->geterror() : err));
  return encoded;
}

TextBox text_size(const std::string& text, int size, const std::string& font) {
  const OIIO::ROI r = OIIO::ImageBufAlgo::text_size(text, size, font);
  return {r.defined(), r.xbegin, r.xend, r.ybegin, r.yend};
}

bool render_text(Image& img, int x, int baseline, const std::string& text, int size, const std::string& font,
                 const std::vector<float>& color, std::string* error) {
  OIIO::ImageSpec spec(img.width, img.height, img.channels, OIIO::TypeDesc::FLOAT);
  OIIO::ImageBuf buf(spec, img.pixels.data());  // wraps the pixels: drawn in place
  if (OIIO::ImageBufAlgo::render_text(buf, x, baseline, text, size, font, color)) return true;
  *error = buf.geterror();
  return false;
}

const ImageCodec kCodec = {kImageCodecVersion, open_file, open_memory, encode, text_size, render_text};

}  // namespace

}  // namespace sn::io

extern "C" __attribute__((visibility("default"))) const sn::io::ImageCodec* shadenet_image_codec() { return &sn::io::kCodec; }
