#include "nn/mlp_render.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <iterator>
#include <map>
#include <stdexcept>
#include <string>

#include "gl/buffer.h"
#include "gl/context.h"
#include "gl/program.h"
#include "nn/gl_forward.h"
#include "nn/mlp_shader.h"
#include "nn/render_inputs.h"

namespace sn::nn {

namespace {

// A network's parameters on the GPU, tied to the object (weakly: a freed network's entry is
// dropped, and a new network at the same address is not mistaken for it).
struct Uploaded {
  std::weak_ptr<const Mlp> owner;
  uint64_t version = 0;
  std::shared_ptr<gl::Buffer> params;
};
std::map<const Mlp*, Uploaded>& uploads() {
  static std::map<const Mlp*, Uploaded> m;
  return m;
}
std::size_t g_uploads = 0;

const char* kSwizzle = "xyzw";

// GLSL that fills the array u0[] of input vec4s: attribute a's components from attachment a, a
// condition's value from u_condition[k], in input order, zeros after the last input; encoded
// by mlp_encode when the network encodes inputs.
std::string gather_inputs(const Mlp& net) {
  std::vector<std::string> comps;
  std::string code;
  int a = 0, k = 0;
  for (const auto& name : net.input_names) {
    if (net.condition(name)) {
      comps.push_back("u_condition[" + std::to_string(k++) + "]");
      continue;
    }
    code += "vec4 g" + std::to_string(a) + " = texelFetch(u_attr[" + std::to_string(a) + "], p, 0); ";
    const int w = scene::attribute_width(name);
    for (int c = 0; c < w; ++c) comps.push_back("g" + std::to_string(a) + "." + kSwizzle[c]);
    ++a;
  }
  if (!net.spec.encodings.empty()) {  // the raw row, then its encoding (mlp/encoding.glsl)
    std::string raw;
    for (const auto& c : comps) raw += (raw.empty() ? "" : ", ") + c;
    return code + "float x_[" + std::to_string(comps.size()) + "] = float[](" + raw + "); vec4 u0[" +
           std::to_string(chunks4(net.spec.width(0))) + "]; mlp_encode(x_, u0); ";
  }
  while (comps.size() % 4) comps.push_back("0.0");
  std::string all;
  for (std::size_t q = 0; q < comps.size() / 4; ++q) {
    code += "vec4 u0_" + std::to_string(q) + " = vec4(" + comps[4 * q] + ", " + comps[4 * q + 1] + ", " +
            comps[4 * q + 2] + ", " + comps[4 * q + 3] + "); ";
    all += (q ? ", u0_" : "u0_") + std::to_string(q);
  }
  return code + "vec4 u0[" + std::to_string(comps.size() / 4) + "] = vec4[](" + all + "); ";
}

bool fits_uniform_buffer(const MlpSpec& spec) {
  GLint max = 0;
  glGetIntegerv(GL_MAX_UNIFORM_BLOCK_SIZE, &max);
  return padded_chunks(spec) * 16 <= std::size_t(max);
}

gl::Buffer& params_of(const std::shared_ptr<const Mlp>& net) {
  auto& m = uploads();
  for (auto it = m.begin(); it != m.end();) it = it->second.owner.expired() ? m.erase(it) : std::next(it);
  Uploaded& u = m[net.get()];
  if (u.owner.expired() || u.owner.lock() != net) u = Uploaded{net, 0, nullptr};
  const std::size_t pq = padded_chunks(net->spec);
  if (!u.params || u.params->count() != pq) u.params = std::make_shared<gl::Buffer>(gl::ElemType::vec4, pq), u.version = 0;
  if (u.version != net->version) {
    auto padded = pack_padded(net->spec, net->params.data());
    u.params->upload(padded.data(), 0, padded.size());
    u.version = net->version;
    ++g_uploads;
  }
  return *u.params;
}

}  // namespace

void draw_mlp(const std::shared_ptr<const Mlp>& net, const scene::GBuffer& g, gl::RenderTarget& out, int frames,
              WeightBuffer weights, const std::map<std::string, double>& values) {
  if (!net) throw std::invalid_argument("draw_mlp: no network");
  const RenderInputs inputs = render_inputs(*net, g, values);
  if (out.width() != g.width || out.height() != g.height)
    throw std::invalid_argument("draw_mlp: target size differs from the G-buffer's");
  const bool ubo = weights == WeightBuffer::automatic && fits_uniform_buffer(net->spec);
  gl::ProgramDesc desc;
  desc.vertex = "fullscreen.vert";
  desc.fragment = "mlp_shade.frag";
  desc.defines = mlp_defines(net->spec);
  desc.includes = mlp_includes(net->spec);
  const std::vector<std::string>& attributes = inputs.attributes;
  desc.defines["MLP_ATTRS"] = std::to_string(attributes.size());
  desc.defines["MLP_GATHER_INPUTS"] = gather_inputs(*net);
  if (!net->conditions.empty()) desc.defines["MLP_CONDITIONS"] = std::to_string(net->conditions.size());
  desc.defines["MLP_WEIGHTS_UBO"] = ubo ? "1" : "0";
  desc.defines["MLP_MAX_WIDTH4"] = std::to_string(chunks4(net->spec.max_width()));
  // llvmpipe ends every loop of an invocation after 65,535 iterations, silently: there the shader
  // reports a loop it cut. Built-in activations stay far below (64x32: about 5,600, as
  // mlp_eval.comp counts them); an activation defined with a loop of its own may not.
  const bool check_loops = gl::current().info().software;
  desc.defines["MLP_LOOP_CHECK"] = check_loops ? "1" : "0";
  auto prog = gl::get_program(desc);
  std::vector<double> units;
  for (std::size_t a = 0; a < attributes.size(); ++a) {
    glBindTextureUnit(GLuint(a), g.target->color_texture(g.attachment(attributes[a])));
    units.push_back(double(a));
  }
  // The compiler trims the array past its last element read (an input whose encoding reads none
  // of it: spherical harmonics of degree 1 are the constant alone), or drops it whole.
  if (const gl::UniformInfo* u = prog->uniform("u_attr")) {
    units.resize(std::min(units.size(), std::size_t(u->size)));
    prog->set_uniform("u_attr", units);
  }
  if (!net->conditions.empty() && prog->uniform("u_condition"))
    prog->set_uniform("u_condition", std::vector<double>(inputs.conditions.begin(), inputs.conditions.end()));
  gl::Buffer& params = params_of(net);
  glBindBufferBase(ubo ? GL_UNIFORM_BUFFER : GL_SHADER_STORAGE_BUFFER, 0, params.id());
  std::shared_ptr<gl::Buffer> cut;
  if (check_loops) {
    cut = gl::pooled_buffer(gl::ElemType::uint32, 1);
    cut->fill_uint(0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, cut->id());
  }
  out.bind();
  glDisable(GL_DEPTH_TEST);
  static GLuint vao = 0;  // core profile draws need a VAO, even one without buffers
  if (!vao || !glIsVertexArray(vao)) glCreateVertexArrays(1, &vao);
  glUseProgram(prog->id());
  glBindVertexArray(vao);
  for (int f = 0; f < std::max(1, frames); ++f) {
    out.clear({0, 0, 0, 0});
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  glBindVertexArray(0);
  glEnable(GL_DEPTH_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  uint32_t loops_cut = 0;
  if (cut) cut->download(&loops_cut, 0, 1);
  if (loops_cut)
    throw loop_budget_error(net->spec, "forward pass");
}

std::size_t mlp_weight_uploads() { return g_uploads; }

}  // namespace sn::nn
