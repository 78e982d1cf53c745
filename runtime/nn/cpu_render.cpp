#include "nn/cpu_render.h"

#include <epoxy/gl.h>

#include <algorithm>
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

void check_cpu_code(const MlpSpec& spec) {
  Activation bad;
  if (!has_cpu_code(spec, &bad))
    throw std::invalid_argument(spec.describe() + ": " + activation_without_cpu_code(bad) + ": render it with backend = \"gl\"");
}

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

namespace {

// The attachments `inputs` reads, in slot order of inputs.attributes; throws when `texels` is
// not of g's box.
std::vector<const float*> sources(const scene::GBuffer& g, const GBufferTexels& texels, const RenderInputs& inputs) {
  const scene::PixelBox box = g.box();
  const std::size_t texel_floats = std::size_t(std::max(0, box.width())) * std::size_t(std::max(0, box.height())) * 4;
  std::vector<const float*> src(inputs.attributes.size());
  for (std::size_t a = 0; a < src.size(); ++a) {
    const std::vector<float>& t = texels.of(inputs.attributes[a]);
    if (t.size() != texel_floats) throw std::invalid_argument("cpu_render: the attachments read back are not of this G-buffer's box");
    src[a] = t.data();
  }
  return src;
}

// What the first layer reads of `blocks` blocks of kLanes pixels (box texels pix) into x, in
// CpuNet::forward_lanes' layout: per pixel encoded as the trainers encode rows, when the net encodes.
class InputGather {
 public:
  InputGather(const MlpSpec& spec, const RenderInputs& inputs, std::vector<const float*> src)
      : spec_(spec), inputs_(inputs), src_(std::move(src)), raw_(std::size_t(spec.inputs)), encoded_(std::size_t(spec.width(0))) {}

  void operator()(const uint32_t* pix, std::size_t blocks, float* x) {
    const int in = spec_.inputs, first = spec_.width(0);
    for (std::size_t b = 0; b < blocks; ++b) {
      float* xb = x + b * std::size_t(first) * kLanes;
      const uint32_t* pb = pix + b * kLanes;
      if (!spec_.encodings.empty()) {
        for (int l = 0; l < kLanes; ++l) {
          for (int i = 0; i < in; ++i) {
            const InputSlot& s = inputs_.slots[std::size_t(i)];
            raw_[std::size_t(i)] = s.attribute < 0 ? s.value : src_[std::size_t(s.attribute)][std::size_t(pb[l]) * 4 + std::size_t(s.component)];
          }
          encode_rows(spec_.encodings, in, raw_.data(), 1, encoded_.data());
          for (int j = 0; j < first; ++j) xb[std::size_t(j) * kLanes + std::size_t(l)] = encoded_[std::size_t(j)];
        }
        continue;
      }
      for (int i = 0; i < in; ++i) {
        const InputSlot& s = inputs_.slots[std::size_t(i)];
        float* xi = xb + std::size_t(i) * kLanes;
        if (s.attribute < 0) {
          for (int l = 0; l < kLanes; ++l) xi[l] = s.value;
        } else {
          const float* a = src_[std::size_t(s.attribute)] + s.component;
          for (int l = 0; l < kLanes; ++l) xi[l] = a[std::size_t(pb[l]) * 4];
        }
      }
    }
  }

 private:
  const MlpSpec& spec_;
  const RenderInputs& inputs_;
  std::vector<const float*> src_;
  std::vector<float> raw_, encoded_;  // one pixel's, when encoding
};

// The forward pass over the blocks of x that hold n pixels, and their colours into base +
// dst[k] * 4: RGB from the network's colour space, alpha[k]. Returns how many came out NaN or
// infinite. y: room for the blocks' outputs (at most kChunkBlocks).
std::size_t shade(CpuNet& cpu, const float* x, std::size_t n, const uint32_t* dst, const float* alpha, float* y, float* base) {
  const shading::ColorSpace color = cpu.spec().color;
  cpu.forward_lanes(x, (n + kLanes - 1) / kLanes, y);
  std::size_t bad = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const float* yb = y + (k / kLanes) * 3 * kLanes + k % kLanes;
    float c0 = yb[0], c1 = yb[kLanes], c2 = yb[2 * kLanes];
    if (color != shading::ColorSpace::rgb) {
      const glm::dvec3 rgb = shading::decode_color(color, glm::dvec3(c0, c1, c2));
      c0 = float(rgb.x), c1 = float(rgb.y), c2 = float(rgb.z);
    }
    // One test per pixel; the three only when the sum is not finite (an overflow or a bad one).
    bad += !std::isfinite(c0 + c1 + c2) && !(std::isfinite(c0) && std::isfinite(c1) && std::isfinite(c2));
    float* o = base + std::size_t(dst[k]) * 4;
    o[0] = c0, o[1] = c1, o[2] = c2, o[3] = alpha[k];
  }
  return bad;
}

}  // namespace

std::size_t cpu_render(const Mlp& net, const scene::GBuffer& g, const GBufferTexels& texels, const RenderInputs& inputs,
                       io::Image& out, CpuLayout layout) {
  check_cpu_code(net.spec);
  const int w = g.width, h = g.height;
  const scene::PixelBox box = g.box();
  const int bw = std::max(0, box.width()), bh = std::max(0, box.height());

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

  const int bands = (bh + kBandRows - 1) / kBandRows;
  // A user's encoding (a Lua function) runs on this thread alone.
  const int threads = single_threaded(net.spec.encodings) ? 1 : std::max(1, std::min(io::default_threads(), bands));
  std::atomic<int> next{0};
  std::atomic<std::size_t> nonfinite{0};
  const std::vector<const float*> src = sources(g, texels, inputs);
  const float* coverage = src[0] + 3;  // in .w of each attachment; the first one's is used
  // Output pixel (floats / 4) of box texel (x, y): the frame's row h - 1 - y (images run top
  // first) or the box's own.
  const std::size_t row_step = whole ? std::size_t(w) : std::size_t(bw);
  const std::size_t dst0 = whole ? std::size_t(h - 1 - box.y0) * std::size_t(w) + std::size_t(box.x0) : 0;
  auto dst_of = [&](int x, int y) {
    return whole ? dst0 - std::size_t(y) * row_step + std::size_t(x) : std::size_t(y) * row_step + std::size_t(x);
  };
  io::parallel_for(threads, threads, [&](int) {
    CpuNet cpu(net.spec, net.params.data());
    InputGather gather(net.spec, inputs, src);
    std::vector<float> x(std::size_t(kChunkBlocks) * kLanes * std::size_t(net.spec.width(0)));
    std::vector<float> y(std::size_t(kChunkBlocks) * kLanes * 3), alpha(std::size_t(kChunkBlocks) * kLanes);
    std::vector<uint32_t> pix(std::size_t(kChunkBlocks) * kLanes);  // box texel per lane
    std::vector<uint32_t> dst(pix.size());                           // output pixel per lane
    std::size_t bad_here = 0;
    auto flush = [&](std::size_t n) {
      const std::size_t blocks = (n + kLanes - 1) / kLanes;
      for (std::size_t k = n; k < blocks * kLanes; ++k) pix[k] = pix[n - 1];  // dead lanes repeat a live one
      gather(pix.data(), blocks, x.data());
      bad_here += shade(cpu, x.data(), n, dst.data(), alpha.data(), y.data(), base);
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
          dst[n] = uint32_t(dst_of(xx, yy));
          alpha[n] = cov[std::size_t(xx) * 4];
          if (++n == pix.size()) flush(n), n = 0;
        }
      }
      if (n) flush(n);
    }
    nonfinite += bad_here;
  });
  return nonfinite.load();
}

CoveredInputs covered_inputs(const MlpSpec& spec, const scene::GBuffer& g, const GBufferTexels& texels,
                             const RenderInputs& inputs) {
  const scene::PixelBox box = g.box();
  const int bw = std::max(0, box.width()), bh = std::max(0, box.height());
  const std::vector<const float*> src = sources(g, texels, inputs);
  CoveredInputs c;
  c.first = spec.width(0);
  if (bw == 0 || bh == 0) return c;
  const float* coverage = src[0] + 3;
  std::vector<uint32_t> pix;  // box texel per covered pixel, in cpu_render's order
  for (int yy = 0; yy < bh; ++yy) {
    const std::size_t row = std::size_t(yy) * std::size_t(bw);
    const std::size_t to = std::size_t(g.height - 1 - box.y0 - yy) * std::size_t(g.width) + std::size_t(box.x0);
    for (int xx = 0; xx < bw; ++xx) {
      const float cov = coverage[(row + std::size_t(xx)) * 4];
      if (!(cov > 0.0f)) continue;
      pix.push_back(uint32_t(row + std::size_t(xx)));
      c.dst.push_back(uint32_t(to + std::size_t(xx)));
      c.alpha.push_back(cov);
    }
  }
  c.count = pix.size();
  if (c.count == 0) return c;
  const std::size_t blocks = (c.count + kLanes - 1) / kLanes;
  pix.resize(blocks * kLanes, pix.back());  // dead lanes repeat a live one
  c.x.resize(blocks * kLanes * std::size_t(c.first));
  InputGather(spec, inputs, src)(pix.data(), blocks, c.x.data());
  return c;
}

bool same_inputs(const MlpSpec& a, const RenderInputs& ia, const MlpSpec& b, const RenderInputs& ib) {
  if (a.inputs != b.inputs || !(a.encodings == b.encodings) || ia.slots.size() != ib.slots.size()) return false;
  for (std::size_t i = 0; i < ia.slots.size(); ++i) {
    const InputSlot &s = ia.slots[i], &t = ib.slots[i];
    if ((s.attribute < 0) != (t.attribute < 0) || s.component != t.component) return false;
    if (s.attribute < 0 ? s.value != t.value
                        : ia.attributes[std::size_t(s.attribute)] != ib.attributes[std::size_t(t.attribute)])
      return false;
  }
  return true;
}

std::size_t cpu_render(const Mlp& net, const scene::GBuffer& g, const CoveredInputs& covered, io::Image& out) {
  check_cpu_code(net.spec);
  if (covered.first != net.spec.width(0))
    throw std::invalid_argument("cpu_render: the gathered inputs are not what " + net.spec.describe() + " reads");
  if (out.width != g.width || out.height != g.height || out.channels != 4) out = io::Image(g.width, g.height, 4);
  else std::fill(out.pixels.begin(), out.pixels.end(), 0.0f);
  CpuNet cpu(net.spec, net.params.data());
  constexpr std::size_t chunk = std::size_t(kChunkBlocks) * kLanes;
  float y[chunk * 3];
  std::size_t bad = 0;
  for (std::size_t k = 0; k < covered.count; k += chunk)
    bad += shade(cpu, covered.x.data() + k * std::size_t(covered.first), std::min(chunk, covered.count - k),
                 covered.dst.data() + k, covered.alpha.data() + k, y, out.pixels.data());
  return bad;
}

}  // namespace sn::nn
