#include "nn/gl_forward.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>

#include "gl/context.h"
#include "gl/program.h"
#include "nn/cpu_net.h"
#include "nn/mlp_shader.h"

namespace sn::nn {

namespace {

// GL guarantees at least 65,535 workgroups along x.
constexpr std::size_t kMaxGroupsPerDispatch = 65535;

gl::Buffer& dummy_buffer() {
  static std::unique_ptr<gl::Buffer> b;
  if (!b) b = std::make_unique<gl::Buffer>(gl::ElemType::float32, 4);
  return *b;
}

void need(const gl::Buffer& b, std::size_t floats, const char* what) {
  if (b.components() < floats)
    throw std::invalid_argument(std::string(what) + " buffer holds " + std::to_string(b.components()) +
                                " numbers, needs " + std::to_string(floats));
}

void check_params(const MlpSpec& spec, const GlParams& p) {
  if (!p.buffer) throw std::invalid_argument("gl forward: no parameter buffer");
  if (p.nets < 1) throw std::invalid_argument("gl forward: at least one network");
  const std::size_t pq = padded_chunks(spec);
  if (p.buffer->type() != gl::ElemType::vec4) throw std::invalid_argument("gl forward: parameters must be a vec4 buffer");
  if (p.nets > 1 && p.stride < pq) throw std::invalid_argument("gl forward: parameter stride too small");
  if (p.buffer->count() < p.offset + std::size_t(p.nets - 1) * p.stride + pq)
    throw std::invalid_argument("gl forward: parameter buffer holds " + std::to_string(p.buffer->count()) +
                                " vec4s, needs " + std::to_string(p.offset + std::size_t(p.nets - 1) * p.stride + pq));
}

// Runs mlp_eval.comp over all rows in dispatches of at most kMaxGroupsPerDispatch workgroups.
void run_eval(const MlpSpec& spec, bool loss, const GlParams& p, const gl::Buffer& x, const gl::Buffer* y,
              gl::Buffer* out, gl::Buffer* partial, std::size_t rows, const Loss& loss_fn = {}) {
  gl::ProgramDesc desc;
  desc.compute = "mlp_eval.comp";
  const int local = eval_local_size(spec, std::size_t(gl::current().info().max_shared_memory));
  desc.defines = eval_defines(spec, loss, local, loss_fn);
  desc.includes = mlp_includes(spec);
  auto program = gl::get_program(desc);
  const std::size_t groups = (rows + std::size_t(local) - 1) / std::size_t(local);
  gl::Buffer cut(gl::ElemType::uint32, std::size_t(p.nets));
  gl::Buffer& dummy = dummy_buffer();
  const gl::Buffer* bind[6] = {&x, y ? y : &dummy, p.buffer, out ? out : &dummy, partial ? partial : &dummy, &cut};
  for (unsigned i = 0; i < 6; ++i) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, i, bind[i]->id());
  program->set_uniform("u_rows", {double(rows)});
  program->set_uniform("u_param_offset", {double(p.offset)});
  program->set_uniform("u_param_stride", {double(p.stride)});
  if (loss) program->set_uniform("u_partials", {double(groups)});
  for (std::size_t g0 = 0; g0 < groups; g0 += kMaxGroupsPerDispatch) {
    program->set_uniform("u_first_group", {double(g0)});
    gl::dispatch(*program, unsigned(std::min(kMaxGroupsPerDispatch, groups - g0)), unsigned(p.nets));
  }
  std::vector<uint32_t> flags(std::size_t(p.nets));
  cut.download(flags.data(), 0, flags.size());
  for (uint32_t f : flags)
    if (f)
      throw loop_budget_error(spec, "forward pass");
}

}  // namespace

std::runtime_error loop_budget_error(const MlpSpec& spec, const std::string& pass) {
  Activation without{};
  const std::string advice =
      has_cpu_code(spec, &without)
          ? "use the cpu backend (backend = \"cpu\") or a smaller network"
          : "use a smaller network or an activation without a long loop (" + activation_without_cpu_code(without) +
                ", so the cpu backend cannot run it either)";
  return std::runtime_error(spec.describe() + ": one " + pass + " needs more loop iterations than this GL driver runs " +
                            "per shader invocation (" + gl::current().info().renderer + " stops at 65,535); " + advice);
}

void gl_forward(const MlpSpec& spec, const GlParams& p, const gl::Buffer& x, std::size_t rows, gl::Buffer& out) {
  check_params(spec, p);
  if (rows == 0) return;
  need(x, rows * std::size_t(spec.inputs), "input");
  need(out, std::size_t(p.nets) * rows * std::size_t(spec.outputs), "output");
  run_eval(spec, false, p, x, nullptr, &out, nullptr, rows);
}

std::vector<double> gl_squared_errors(const MlpSpec& spec, const GlParams& p, const gl::Buffer& x, const gl::Buffer& y,
                                      std::size_t rows, const Loss& loss) {
  check_params(spec, p);
  std::vector<double> sums(std::size_t(p.nets), 0.0);
  if (rows == 0) return sums;
  need(x, rows * std::size_t(spec.inputs), "input");
  need(y, rows * std::size_t(spec.outputs), "target");
  const int local = eval_local_size(spec, std::size_t(gl::current().info().max_shared_memory));
  const std::size_t groups = (rows + std::size_t(local) - 1) / std::size_t(local);
  gl::Buffer partial(gl::ElemType::uint32, 2 * groups * std::size_t(p.nets));  // doubles
  run_eval(spec, true, p, x, &y, nullptr, &partial, rows, loss);
  std::vector<double> part(groups * std::size_t(p.nets));
  partial.download(part.data(), 0, 2 * part.size());
  for (int n = 0; n < p.nets; ++n)
    for (std::size_t g = 0; g < groups; ++g) sums[std::size_t(n)] += part[std::size_t(n) * groups + g];
  return sums;
}

std::shared_ptr<gl::Buffer> gl_forward(const Mlp& net, const gl::Buffer& x, std::size_t rows) {
  if (net.params.size() != net.spec.param_count())
    throw std::invalid_argument(net.spec.describe() + ": " + std::to_string(net.params.size()) +
                                " parameters, but its spec needs " + std::to_string(net.spec.param_count()));
  std::vector<float> padded = pack_padded(net.spec, net.params.data());
  gl::Buffer params(gl::ElemType::vec4, padded.size() / 4);
  params.upload(padded.data(), 0, padded.size());
  auto out = std::make_shared<gl::Buffer>(gl::ElemType::float32, std::max<std::size_t>(1, rows * net.spec.outputs));
  gl_forward(net.spec, GlParams{&params, 0, 0, 1}, x, rows, *out);
  return out;
}

std::vector<float> gl_encode(const MlpSpec& spec, const std::vector<float>& x) {
  if (spec.encodings.empty()) throw std::invalid_argument("gl encode: " + spec.describe() + " encodes no input");
  const std::size_t in = std::size_t(spec.inputs), w = std::size_t(spec.width(0)), w4 = std::size_t(chunks4(int(w)));
  if (x.size() % in)
    throw std::invalid_argument("gl encode: " + std::to_string(x.size()) + " numbers are not whole rows of " +
                                std::to_string(in) + " inputs");
  const std::size_t rows = x.size() / in;
  if (rows == 0) return {};
  if (rows > 64 * kMaxGroupsPerDispatch)
    throw std::invalid_argument("gl encode: at most " + std::to_string(64 * kMaxGroupsPerDispatch) + " rows at once");
  gl::ProgramDesc desc;
  desc.compute = "encoding_check.comp";
  desc.defines = mlp_defines(spec);
  desc.includes = mlp_includes(spec);
  auto program = gl::get_program(desc);
  gl::Buffer xb(gl::ElemType::float32, x.size()), out(gl::ElemType::vec4, rows * w4);
  xb.upload(x.data(), 0, x.size());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, xb.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, out.id());
  program->set_uniform("u_rows", {double(rows)});
  gl::dispatch(*program, unsigned((rows + 63) / 64));
  std::vector<float> padded(rows * w4 * 4), e(rows * w);
  out.download(padded.data(), 0, padded.size());
  for (std::size_t r = 0; r < rows; ++r)
    for (std::size_t i = 0; i < w; ++i) e[r * w + i] = padded[r * w4 * 4 + i];
  return e;
}

std::vector<float> gl_forward(const Mlp& net, const std::vector<float>& x) {
  const std::size_t in = std::size_t(net.spec.inputs);
  if (x.size() % in)
    throw std::invalid_argument("gl forward: " + std::to_string(x.size()) + " numbers are not whole rows of " +
                                std::to_string(in) + " inputs");
  const std::size_t rows = x.size() / in;
  if (rows == 0) return {};
  gl::Buffer xb(gl::ElemType::float32, x.size());
  xb.upload(x.data(), 0, x.size());
  auto out = gl_forward(net, xb, rows);
  std::vector<float> y(rows * std::size_t(net.spec.outputs));
  out->download(y.data(), 0, y.size());
  return y;
}

}  // namespace sn::nn
