// A network as the lighting model of every covered G-buffer pixel (runtime/nn/mlp_render.cpp):
// the input vector assembled from the G-buffer attributes the network reads, in net:inputs()
// order; the forward pass with the parameters from a buffer (so a weight edit needs no
// recompile), architecture as #defines; the output taken from the network's colour space back to
// RGB; alpha = coverage. Uncovered pixels are discarded before any network work.
#define COLOR_SPACE MLP_COLOR
#include "color.glsl"
#include "mlp/activation.glsl"

// Padded vec4 layout (runtime/nn/mlp_shader.h). A uniform buffer where it fits: llvmpipe reads a
// uniform buffer at a uniform offset with one scalar load, a storage buffer with a loop over
// the SIMD lanes.
#if MLP_WEIGHTS_UBO
layout(std140, binding = 0) uniform Params { vec4 params[MLP_PQ]; };
#else
layout(std430, binding = 0) readonly buffer Params { vec4 params[]; };
#endif
uniform sampler2D u_attr[MLP_ATTRS];  // the G-buffer attachments, in the network's input order
uniform int u_zero;                   // never set: 0, a loop bound the compiler cannot see through

layout(location = 0) out vec4 o_color;

// Units of the layer being read and of the layer being written, alternating.
vec4 h[2][MLP_MAX_WIDTH4];
#define MLP_P4(k) params[k]
#define MLP_UNIT(b, u0, k) h[(b) & 1][k]
#define MLP_ROLLED(n) ((n) + u_zero)
#include "mlp/forward.glsl"

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  float coverage = texelFetch(u_attr[0], p, 0).w;
  if (!(coverage > 0.0)) discard;
  MLP_GATHER_INPUTS  // h[0][0..MLP_IN4) from the attributes (defined by the host)
  MLP_FORWARD()
  vec3 y = h[MLP_LAYERS & 1][0].xyz;
  o_color = vec4(color_to_rgb(y), coverage);
}
