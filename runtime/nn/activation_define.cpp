#include "nn/activation_define.h"

#include <epoxy/gl.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "gl/buffer.h"
#include "gl/program.h"
#include "io/text.h"

namespace sn::nn {

namespace {

// Sample points off the integers (kinks such as relu's at 0 fall between them).
std::vector<double> sample_points() {
  std::vector<double> z;
  for (int i = 0; i <= 64; ++i) z.push_back(-4.0 + 0.125 * i + 0.0137);
  return z;
}

void check_twins(const ActivationDef& d) {
  const std::string who = "activation '" + d.name + "'";
  for (double z : sample_points()) {
    const double f = d.f(z, 0.0), df = d.df(z, 0.0);
    if (!std::isfinite(f)) throw std::invalid_argument(who + ": lua(" + io::number_text(z) + ") returned " + io::number_text(f));
    if (!std::isfinite(df)) throw std::invalid_argument(who + ": lua_grad(" + io::number_text(z) + ") returned " + io::number_text(df));
    const double h = 1e-5, fd = (d.f(z + h, 0.0) - d.f(z - h, 0.0)) / (2 * h);
    if (std::fabs(fd - df) > 1e-4 * (1 + std::fabs(fd)))
      throw std::invalid_argument(who + ": lua_grad(" + io::number_text(z) + ") = " + io::number_text(df) + " but central differences of lua give " +
                                  io::number_text(fd));
  }
}

// The GLSL function `part` of `d` at the sample points.
std::vector<float> run_glsl(const ActivationDef& d, ActivationPart part) {
  const std::vector<double> zd = sample_points();
  std::vector<float> z(zd.begin(), zd.end());
  gl::ProgramDesc desc;
  desc.compute = "activation_check.comp";
  const char* what = part == ActivationPart::f ? "glsl" : "grad";
  desc.includes["mlp/act_hidden.glsl"] = activation_glsl_function(d, part);
  desc.includes["mlp/act_output.glsl"] = "";
  desc.defines["CHECK_CALL(z)"] = "sn_act_" + d.name + (part == ActivationPart::f ? "" : "_grad") + "(z, 0.0)";
  std::shared_ptr<gl::Program> prog;
  try {
    prog = gl::get_program(desc);
  } catch (const std::exception& e) {
    // The log names the include; a person wrote the text at the defining script line.
    std::string log = e.what();
    const std::string include = "mlp/act_hidden.glsl", origin = d.origin + " (" + what + ")";
    for (std::size_t at = log.find(include); at != std::string::npos; at = log.find(include, at + origin.size()))
      log.replace(at, include.size(), origin);
    throw std::invalid_argument("activation '" + d.name + "': its " + what + " GLSL does not compile:\n" + log);
  }
  gl::Buffer in(gl::ElemType::float32, z.size()), out(gl::ElemType::float32, z.size());
  in.upload(z.data(), 0, z.size());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, out.id());
  prog->set_uniform("u_count", {double(z.size())});
  gl::dispatch(*prog, unsigned((z.size() + 63) / 64));
  std::vector<float> y(z.size());
  out.download(y.data(), 0, y.size());
  return y;
}

void check_glsl(const ActivationDef& d) {
  const std::vector<double> z = sample_points();
  for (ActivationPart part : {ActivationPart::f, ActivationPart::grad}) {
    const std::vector<float> got = run_glsl(d, part);
    const char* what = part == ActivationPart::f ? "glsl" : "grad";
    for (std::size_t i = 0; i < z.size(); ++i) {
      const double want = part == ActivationPart::f ? d.f(z[i], 0.0) : d.df(z[i], 0.0);
      if (!(std::fabs(double(got[i]) - want) <= 1e-4 * (1 + std::fabs(want))))
        throw std::invalid_argument("activation '" + d.name + "': its " + what + " GLSL gives " + io::number_text(got[i]) + " at " +
                                    io::number_text(z[i]) + ", its Lua twin " + io::number_text(want));
    }
  }
}

}  // namespace

Activation define_activation(ActivationDef def) {
  def.simd = -1;
  check_twins(def);
  check_glsl(def);
  return register_activation(std::move(def));
}

}  // namespace sn::nn
