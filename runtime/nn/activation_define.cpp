#include "nn/activation_define.h"

#include <epoxy/gl.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "gl/buffer.h"
#include "gl/program.h"
#include "io/text.h"
#include "nn/activation_expr.h"
#include "nn/cpu_net.h"

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

// `desc` compiled, for part `what` of `d`; a compile error names the defining script line.
std::shared_ptr<gl::Program> compile(const ActivationDef& d, const char* what, const gl::ProgramDesc& desc) {
  try {
    gl::NoProgramFallback strict;  // in live mode too: never the last good program of the same name
    return gl::get_program(desc);
  } catch (const std::exception& e) {
    // The log names the include; a person wrote the text at the defining script line.
    std::string log = e.what();
    const std::string include = "mlp/act_hidden.glsl", origin = d.origin + " (" + what + ")";
    for (std::size_t at = log.find(include); at != std::string::npos; at = log.find(include, at + origin.size()))
      log.replace(at, include.size(), origin);
    throw std::invalid_argument("activation '" + d.name + "': its " + what + " (GLSL) does not compile:\n" + log);
  }
}

// The GLSL function `part` of `d` at the sample points, 4 values per point: lane k of point i
// is the function at point i + k (mod the count). The function is compiled in a fragment shader
// too (a render's), and not run there.
std::vector<float> run_glsl(const ActivationDef& d, ActivationPart part) {
  const std::vector<double> zd = sample_points();
  std::vector<float> z(zd.begin(), zd.end());
  gl::ProgramDesc desc;
  const char* what = part == ActivationPart::f ? "glsl" : "grad";
  desc.includes["mlp/act_hidden.glsl"] = activation_glsl_function(d, part);
  desc.includes["mlp/act_output.glsl"] = "";
  desc.defines["CHECK_CALL(z)"] = "sn_act_" + d.name + (part == ActivationPart::f ? "" : "_grad") + "(z, 0.0)";
  gl::ProgramDesc fragment = desc;
  fragment.vertex = "fullscreen.vert";
  fragment.fragment = "activation_check.frag";
  desc.compute = "activation_check.comp";
  const std::shared_ptr<gl::Program> prog = compile(d, what, desc);
  compile(d, what, fragment);
  gl::Buffer in(gl::ElemType::float32, z.size()), out(gl::ElemType::float32, 4 * z.size());
  in.upload(z.data(), 0, z.size());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, out.id());
  prog->set_uniform("u_count", {double(z.size())});
  gl::dispatch(*prog, unsigned((z.size() + 63) / 64));
  std::vector<float> y(4 * z.size());
  out.download(y.data(), 0, y.size());
  return y;
}

void check_glsl(const ActivationDef& d) {
  const std::vector<double> z = sample_points();
  for (ActivationPart part : {ActivationPart::f, ActivationPart::grad}) {
    const std::vector<float> got = run_glsl(d, part);
    const char* what = part == ActivationPart::f ? "glsl" : "grad";
    auto twin = [&](std::size_t i, std::size_t lane) {
      const double at = z[(i / 4 + lane) % z.size()];
      return part == ActivationPart::f ? d.f(at, 0.0) : d.df(at, 0.0);
    };
    auto agrees = [](double v, double want) { return std::fabs(v - want) <= 1e-4 * (1 + std::fabs(want)); };
    for (std::size_t i = 0; i < got.size(); ++i) {
      const std::size_t lane = i % 4;
      const double want = twin(i, lane);
      if (agrees(got[i], want)) continue;
      std::string why = "activation '" + d.name + "': its " + what + " (GLSL) gives " + io::number_text(got[i]) + " at " +
                        io::number_text(z[(i / 4 + lane) % z.size()]) + ", its Lua twin " + io::number_text(want);
      for (std::size_t other = 0; other < 4; ++other)
        if (other != lane && agrees(got[i], twin(i, other))) {
          why += std::string(": lane ") + "xyzw"[lane] + " of the vec4 holds lane " + "xyzw"[other] +
                 "'s value, and each lane is a unit of its own (no swizzles or sums across lanes)";
          break;
        }
      throw std::invalid_argument(why);
    }
  }
}

// The cpu backend's code: glsl and grad translated (nn/activation_expr.h) and held to the twins
// at the GLSL's points and tolerance. One that does not translate, or disagrees, runs on gl only;
// cpu_missing says why.
void translate_for_cpu(ActivationDef& d) {
  std::shared_ptr<const ActivationExpr> f, both;
  const std::pair<const char*, const std::string*> parts[] = {{"glsl", &d.glsl}, {"grad", &d.grad}};
  try {
    for (const auto& [what, text] : parts) {  // each alone first: an error names its part
      try {
        auto e = std::make_shared<const ActivationExpr>(translate_activation(*text));
        if (!f) f = std::move(e);
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(std::string("its ") + what + ", " + e.what());
      }
    }
    both = std::make_shared<const ActivationExpr>(translate_activation(d.glsl, d.grad));
  } catch (const std::invalid_argument& e) {
    d.cpu_missing = e.what();
    return;
  }
  const std::vector<double> zd = sample_points();
  const std::vector<float> z(zd.begin(), zd.end());
  std::vector<float> alone(z.size()), with_f(z.size()), with_df(z.size());
  cpu_translated(*f, 0.0f, z.data(), z.size(), alone.data());
  cpu_translated(*both, 0.0f, z.data(), z.size(), with_f.data(), with_df.data());
  auto agrees = [&](const char* what, const std::vector<float>& got, bool grad) {
    for (std::size_t k = 0; k < z.size(); ++k) {
      const double want = grad ? d.df(zd[k], 0.0) : d.f(zd[k], 0.0);
      if (!(std::fabs(double(got[k]) - want) <= 1e-4 * (1 + std::fabs(want)))) {
        d.cpu_missing = std::string("its ") + what + " translated for the cpu backend gives " + io::number_text(got[k]) +
                        " at " + io::number_text(zd[k]) + ", its Lua twin " + io::number_text(want);
        return false;
      }
    }
    return true;
  };
  if (agrees("glsl", alone, false) && agrees("glsl", with_f, false) && agrees("grad", with_df, true))
    d.cpu_f = std::move(f), d.cpu_both = std::move(both);
}

}  // namespace

Activation define_activation(ActivationDef def) {
  def.simd = -1;
  check_activation_def(def);  // the name's rules before its GLSL is compiled under that name
  check_twins(def);
  check_glsl(def);
  translate_for_cpu(def);
  return register_activation(std::move(def));
}

}  // namespace sn::nn
