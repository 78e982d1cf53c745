#include "nn/render.h"

#include <cmath>
#include <stdexcept>

#include <epoxy/gl.h>

#include "gl/context.h"
#include "gl/render_target.h"
#include "nn/cpu_net.h"
#include "nn/render_inputs.h"

namespace sn::nn {

const char* render_backend_name(RenderBackend b) {
  switch (b) {
    case RenderBackend::gl: return "gl";
    case RenderBackend::cpu: return "cpu";
    default: return "auto";
  }
}

RenderBackend choose_render_backend(const Mlp& net, const RenderOptions& o, std::string* reason) {
  Activation without;
  const bool cpu_ok = has_cpu_code(net.spec, &without);
  const bool storage = o.weights == WeightBuffer::storage;
  auto say = [&](std::string why, RenderBackend b) {
    if (reason) *reason = std::move(why);
    return b;
  };
  if (o.backend == RenderBackend::cpu) {
    check_cpu_code(net.spec);
    if (storage) throw std::invalid_argument("weights = \"storage\" is a choice of the gl backend, not of \"cpu\"");
    return say("requested", RenderBackend::cpu);
  }
  if (o.backend == RenderBackend::gl) return say("requested", RenderBackend::gl);
  if (!cpu_ok)
    return say(activation_without_cpu_code(without), RenderBackend::gl);
  if (storage) return say("weights = \"storage\" asks for the fragment shader", RenderBackend::gl);
  for (const InputEncoding& e : net.spec.encodings)
    if (encoding_def(e.kind).caller_thread)
      return say(std::string("encoding '") + encoding_name(e.kind) + "' is a Lua definition (its cpu twin runs on one thread)",
                 RenderBackend::gl);
  const gl::ContextInfo& info = gl::current().info();
  if (info.software)
    return say("software renderer (" + info.renderer + "): the native cpu kernels are faster", RenderBackend::cpu);
  return say("hardware GPU (" + info.renderer + ")", RenderBackend::gl);
}

Rendered render_network(const std::shared_ptr<const Mlp>& net, const scene::GBuffer& g, const RenderOptions& o) {
  if (!net) throw std::invalid_argument("render: no network");
  const RenderInputs inputs = render_inputs(*net, g, o.values);
  Rendered r;
  r.backend = choose_render_backend(*net, o, &r.reason);
  const int frames = std::max(1, o.frames);
  if (r.backend == RenderBackend::cpu) {
    for (int f = 0; f < frames; ++f) r.nonfinite = cpu_render(*net, g, inputs, r.image, CpuLayout::image, &r.cpu_times);
    return r;
  }
  gl::RenderTarget out(g.width, g.height, 1);
  draw_mlp(net, g, out, frames, o.weights, o.values);
  r.image = out.read(0);
  // What the cpu path counts as it writes; here one pass over the image.
  const std::vector<float>& p = r.image.pixels;
  for (std::size_t i = 0; i < p.size(); i += 4)
    if (p[i + 3] > 0.0f && !(std::isfinite(p[i]) && std::isfinite(p[i + 1]) && std::isfinite(p[i + 2]))) ++r.nonfinite;
  return r;
}

Rendered render_network(const std::shared_ptr<const Mlp>& net, const scene::GBuffer& g, gl::RenderTarget& out,
                        const RenderOptions& o) {
  if (!net) throw std::invalid_argument("render: no network");
  const RenderInputs inputs = render_inputs(*net, g, o.values);
  if (out.width() != g.width || out.height() != g.height)
    throw std::invalid_argument("render: the target is " + std::to_string(out.width()) + "x" +
                                std::to_string(out.height()) + ", the G-buffer " + std::to_string(g.width) + "x" +
                                std::to_string(g.height));
  Rendered r;
  r.backend = choose_render_backend(*net, o, &r.reason);
  const int frames = std::max(1, o.frames);
  if (r.backend == RenderBackend::gl) {
    draw_mlp(net, g, out, frames, o.weights, o.values);
    return r;
  }
  // The box's pixels in GL's row order straight into the texture; of the rest only what an
  // earlier frame drew is cleared.
  static io::Image host;  // kept: a frame allocates nothing
  const scene::PixelBox box = g.box();
  for (int f = 0; f < frames; ++f) {
    r.nonfinite = cpu_render(*net, g, inputs, host, CpuLayout::gl_box, &r.cpu_times);
    const std::array<int, 4> b = {box.x0, box.y0, box.x1, box.y1};
    out.clear_drawn(b);  // what the last frame drew outside this box
    if (box.width() > 0 && box.height() > 0)
      glTextureSubImage2D(out.color_texture(0), 0, box.x0, box.y0, box.width(), box.height(), GL_RGBA, GL_FLOAT,
                          host.pixels.data());
    out.set_drawn(b);
  }
  return r;
}

}  // namespace sn::nn
