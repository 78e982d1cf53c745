// A network as the lighting model of every covered G-buffer pixel (runtime/nn/mlp_render.cpp):
// the input vector assembled from the G-buffer attributes the network reads, in net:inputs()
// order; the forward pass with the parameters from a buffer (so a weight edit needs no
// recompile), architecture as #defines; the output taken from the network's colour space back to
// RGB; alpha = coverage. Uncovered pixels skip the network and stay transparent black.
//
// Host-made #defines besides the architecture's: MLP_ATTRS (attachments read), MLP_GATHER_INPUTS
// (code filling the array u0[] of input vec4s from them, through mlp_encode when the network
// encodes its inputs: mlp/encoding.glsl), MLP_MAX_WIDTH4, MLP_CONDITIONS (uniform
// inputs of a conditioned network, when it has any), MLP_LOOP_CHECK (1 on a software renderer:
// report a loop llvmpipe's limiter cut, mlp/loop_limit.glsl).
#define COLOR_SPACE MLP_COLOR
#include "color.glsl"
#include "mlp/activation.glsl"
#include "mlp/encoding.glsl"

// Padded vec4 layout (runtime/nn/mlp_shader.h). A uniform buffer where it fits: every fragment
// reads the same parameters, what uniform buffers are for (llvmpipe: one scalar load instead of
// a loop over the SIMD lanes; in the whole shader the difference was within this machine's
// noise), a storage buffer beyond.
#if MLP_WEIGHTS_UBO
layout(std140, binding = 0) uniform Params { vec4 params[MLP_PQ]; };
#else
layout(std430, binding = 0) readonly buffer Params { vec4 params[]; };
#endif
uniform sampler2D u_attr[MLP_ATTRS];  // the G-buffer attachments, in the network's input order
#ifdef MLP_CONDITIONS
uniform float u_condition[MLP_CONDITIONS];  // a conditioned network's parameter inputs
#endif
uniform int u_zero;  // never set: 0; the run table keeps a wide layer's input loop rolled with it
#if MLP_LOOP_CHECK
#include "mlp/loop_limit.glsl"
layout(std430, binding = 1) writeonly buffer LoopCut { uint loops_cut; };  // 1: some pixel's loops were cut
#endif

layout(location = 0) out vec4 o_color;

#define MLP_P4(k) params[k]

// Units of the layer being read and of the layer being written, alternating.
vec4 h[2][MLP_MAX_WIDTH4];
#define MLP_UNIT(b, u0, k) h[(b) & 1][k]
// Loops a fragment shader keeps cost llvmpipe a mask stack per iteration: literal bounds let the
// compiler unroll each layer (measured 1.3-6x faster than rolled loops, 4x4 to 16x16); runs of
// equal layers stay one loop, so compile time stays about a second.
#define MLP_ROLLED(n) (n)
#include "mlp/forward.glsl"

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  float coverage = texelFetch(u_attr[0], p, 0).w;
  // An early return, not discard: on llvmpipe discard keeps a per-fragment mask live through the
  // whole network (measured 3-8x slower); the target is cleared to this colour anyway.
  if (!(coverage > 0.0)) {
    o_color = vec4(0.0);
    return;
  }
  MLP_GATHER_INPUTS
  for (int q = 0; q < MLP_IN4; ++q) h[0][q] = u0[q];
  MLP_FORWARD()
  vec3 y = h[MLP_LAYERS & 1][0].xyz;
  o_color = vec4(color_to_rgb(y), coverage);
#if MLP_LOOP_CHECK
  if (mlp_loops_were_cut()) loops_cut = 1u;
#endif
}
