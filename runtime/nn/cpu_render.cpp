#include "nn/cpu_render.h"

#include <epoxy/gl.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "nn/cpu_net.h"
#include "nn/encoding.h"
#include "io/parallel.h"
#include "shading/color.h"

namespace sn::nn {

namespace {

constexpr int kLanes = CpuNet::kLanes;
constexpr int kBandRows = 8;      // rows per unit of work handed to a thread
constexpr int kChunkBlocks = 16;  // blocks of 8 pixels per forward_lanes call

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

// Host copies of the attachments, kept between renders: a fresh 11 MB buffer per frame would
// cost page faults and zeroing on every one.
GBufferTexels& scratch() {
  static GBufferTexels s;
  return s;
}

void zero(float* p, std::size_t floats) { std::memset(p, 0, floats * sizeof(float)); }

}  // namespace

bool has_cpu_code(const MlpSpec& spec, Activation* without) {
  for (Activation a : {spec.activation, spec.output_activation})
    if (activation_def(a).simd < 0) {
      if (without) *without = a;
      return false;
    }
  return true;
}

namespace {
void check_cpu_code(const MlpSpec& spec) {
  Activation bad;
  if (!has_cpu_code(spec, &bad))
    throw std::invalid_argument(spec.describe() + ": activation '" + activation_name(bad) +
                                "' is a definition without cpu code: render it with backend = \"gl\"");
}
}  // namespace

const std::vector<float>& GBufferTexels::of(const std::string& attribute) const {
  for (std::size_t a = 0; a < attributes.size(); ++a)
    if (attributes[a] == attribute) return texels[a];
  throw std::invalid_argument("G-buffer attribute '" + attribute + "' was not read back for this render");
}

void read_gbuffer(const scene::GBuffer& g, const std::vector<std::string>& attributes, GBufferTexels& out) {
  const scene::PixelBox box = g.box();
  const int bw = std::max(0, box.width()), bh = std::max(0, box.height());
  const std::size_t texels = std::size_t(bw) * std::size_t(bh);
  out.attributes = attributes;
  out.texels.resize(attributes.size());
  if (texels) glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  for (std::size_t a = 0; a < attributes.size(); ++a) {
    out.texels[a].resize(texels * 4);
    if (texels)
      glGetTextureSubImage(g.target->color_texture(g.attachment(attributes[a])), 0, box.x0, box.y0, 0, bw, bh, 1, GL_RGBA,
                           GL_FLOAT, GLsizei(texels * 4 * sizeof(float)), out.texels[a].data());
  }
}

std::size_t cpu_render(const Mlp& net, const scene::GBuffer& g, const RenderInputs& inputs, io::Image& out,
                       CpuLayout layout, CpuRenderTimes* times) {
  check_cpu_code(net.spec);
  const double t0 = now();
  // Only the attachments the network reads, only inside the box.
  read_gbuffer(g, inputs.attributes, scratch());
  const double t1 = now();
  const std::size_t bad = cpu_render(net, g, scratch(), inputs, out, layout);
  if (times) *times = {t1 - t0, now() - t1};
  return bad;
}

std::size_t cpu_render(const Mlp& net, const scene::GBuffer& g, const GBufferTexels& texels, const RenderInputs& inputs,
                       io::Image& out, CpuLayout layout) {
  check_cpu_code(net.spec);
  const int w = g.width, h = g.height;
  const scene::PixelBox box = g.box();
  const int bw = std::max(0, box.width()), bh = std::max(0, box.height());
  const std::size_t na = inputs.attributes.size();

  // Where texel (x, y) of the box lands, and what is zeroed outside it.
  const bool whole = layout == CpuLayout::image;
  const int ow = whole ? w : bw, oh = whole ? h : bh;
  const bool fresh = out.width != ow || out.height != oh || out.channels != 4;
  if (fresh) out = io::Image(ow, oh, 4);  // zeros
  float* const base = out.pixels.data();
  if (whole && !fresh) {  // the previous frame may have drawn outside this box
    for (int y = 0; y < h; ++y) {
      float* row = base + std::size_t(h - 1 - y) * std::size_t(w) * 4;
      if (y < box.y0 || y >= box.y1 || bw == 0) {
        zero(row, std::size_t(w) * 4);
      } else {
        zero(row, std::size_t(box.x0) * 4);
        zero(row + std::size_t(box.x1) * 4, std::size_t(w - box.x1) * 4);
      }
    }
  }
  if (bw == 0 || bh == 0) return 0;

  const int in = net.spec.inputs;      // raw inputs per pixel
  const int first = net.spec.width(0);  // what the first layer reads: encoded when the net encodes
  const std::vector<InputEncoding>& encodings = net.spec.encodings;
  const shading::ColorSpace color = net.spec.color;
  const int bands = (bh + kBandRows - 1) / kBandRows;
  // A user's encoding (a Lua function) runs on this thread alone.
  const int threads = single_threaded(encodings) ? 1 : std::max(1, std::min(io::default_threads(), bands));
  std::atomic<int> next{0};
  std::atomic<std::size_t> nonfinite{0};
  // Coverage is in .w of each attachment; the first one's is used.
  std::vector<const float*> src(na);
  for (std::size_t a = 0; a < na; ++a) {
    const std::vector<float>& t = texels.of(inputs.attributes[a]);
    if (t.size() != std::size_t(bw) * std::size_t(bh) * 4)
      throw std::invalid_argument("cpu_render: the attachments read back are not of this G-buffer's box");
    src[a] = t.data();
  }
  const float* coverage = src[0] + 3;
  // Output pixel (floats / 4) of box texel (x, y): the frame's row h - 1 - y (images run top
  // first) or the box's own.
  const std::size_t row_step = whole ? std::size_t(w) : std::size_t(bw);
  const std::size_t dst0 = whole ? std::size_t(h - 1 - box.y0) * std::size_t(w) + std::size_t(box.x0) : 0;
  auto dst_of = [&](int x, int y) {
    return whole ? dst0 - std::size_t(y) * row_step + std::size_t(x) : std::size_t(y) * row_step + std::size_t(x);
  };
  io::parallel_for(threads, threads, [&](int) {
    CpuNet cpu(net.spec, net.params.data());
    std::vector<float> x(std::size_t(kChunkBlocks) * kLanes * std::size_t(first));
    std::vector<float> raw(static_cast<std::size_t>(in)), encoded(static_cast<std::size_t>(first));  // one pixel's, when encoding
    std::vector<float> y(std::size_t(kChunkBlocks) * kLanes * 3);
    std::vector<uint32_t> pix(std::size_t(kChunkBlocks) * kLanes);  // box texel per lane
    std::vector<std::size_t> dst(pix.size());                        // output pixel per lane
    std::size_t bad_here = 0;
    // The pending pixels' inputs into lanes, the forward pass, their colours out.
    auto flush = [&](std::size_t n) {
      const std::size_t blocks = (n + kLanes - 1) / kLanes;
      for (std::size_t k = n; k < blocks * kLanes; ++k) pix[k] = pix[n - 1];  // dead lanes repeat a live one
      for (std::size_t b = 0; b < blocks; ++b) {
        float* xb = x.data() + b * std::size_t(first) * kLanes;
        const uint32_t* pb = pix.data() + b * kLanes;
        if (!encodings.empty()) {  // per pixel: its raw inputs, encoded as the trainers encode rows
          for (int l = 0; l < kLanes; ++l) {
            for (int i = 0; i < in; ++i) {
              const InputSlot& s = inputs.slots[std::size_t(i)];
              raw[std::size_t(i)] = s.attribute < 0 ? s.value : src[std::size_t(s.attribute)][std::size_t(pb[l]) * 4 + std::size_t(s.component)];
            }
            encode_rows(encodings, in, raw.data(), 1, encoded.data());
            for (int j = 0; j < first; ++j) xb[std::size_t(j) * kLanes + std::size_t(l)] = encoded[std::size_t(j)];
          }
          continue;
        }
        for (int i = 0; i < in; ++i) {
          const InputSlot& s = inputs.slots[std::size_t(i)];
          float* xi = xb + std::size_t(i) * kLanes;
          if (s.attribute < 0) {
            for (int l = 0; l < kLanes; ++l) xi[l] = s.value;
          } else {
            const float* a = src[std::size_t(s.attribute)] + s.component;
            for (int l = 0; l < kLanes; ++l) xi[l] = a[std::size_t(pb[l]) * 4];
          }
        }
      }
      cpu.forward_lanes(x.data(), blocks, y.data());
      for (std::size_t k = 0; k < n; ++k) {
        const float* yb = y.data() + (k / kLanes) * 3 * kLanes + k % kLanes;
        float c0 = yb[0], c1 = yb[kLanes], c2 = yb[2 * kLanes];
        if (color != shading::ColorSpace::rgb) {
          const glm::dvec3 rgb = shading::decode_color(color, glm::dvec3(c0, c1, c2));
          c0 = float(rgb.x), c1 = float(rgb.y), c2 = float(rgb.z);
        }
        // One test per pixel; the three only when the sum is not finite (an overflow or a bad one).
        bad_here += !std::isfinite(c0 + c1 + c2) && !(std::isfinite(c0) && std::isfinite(c1) && std::isfinite(c2));
        float* o = base + dst[k] * 4;
        o[0] = c0, o[1] = c1, o[2] = c2, o[3] = coverage[std::size_t(pix[k]) * 4];
      }
    };
    for (int b; (b = next.fetch_add(1)) < bands;) {
      const int y0 = b * kBandRows, y1 = std::min(bh, y0 + kBandRows);
      std::size_t n = 0;
      for (int yy = y0; yy < y1; ++yy) {
        if (!fresh) zero(base + dst_of(0, yy) * 4, std::size_t(bw) * 4);
        const std::size_t row = std::size_t(yy) * std::size_t(bw);
        const float* cov = coverage + row * 4;
        for (int xx = 0; xx < bw; ++xx) {
          // What the fragment shader tests: NaN coverage is uncovered too.
          if (!(cov[std::size_t(xx) * 4] > 0.0f)) continue;
          pix[n] = uint32_t(row + std::size_t(xx));
          dst[n] = dst_of(xx, yy);
          if (++n == pix.size()) flush(n), n = 0;
        }
      }
      if (n) flush(n);
    }
    nonfinite += bad_here;
  });
  return nonfinite.load();
}

}  // namespace sn::nn
