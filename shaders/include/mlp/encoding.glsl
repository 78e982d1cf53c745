// The network's input encodings, from the registry of runtime/nn/encoding.h: the host passes
// their GLSL and the function
//   void mlp_encode(float x[MLP_RAW_IN], out vec4 e[MLP_IN4])
// (one raw input row -> the first layer's input vec4s) as the in-memory include
// mlp/enc_net.glsl, and sets MLP_ENCODED to 1 (runtime/nn/mlp_shader.cpp). A network without
// encodings has MLP_ENCODED 0, an empty include, and reads its rows as they are.
//
// Helpers the built-in encodings share:
#define SN_ENC_PI 3.14159265358979
// Phi(t), the standard normal CDF: 0.5 erfc(-t / sqrt 2), erfc as Numerical Recipes' erfcc
// (relative error below 1.2e-7 everywhere).
float sn_enc_normal_cdf(float t) {
  float z = abs(t) * 0.70710678118654752;
  float k = 1.0 / (1.0 + 0.5 * z);
  float r = k * exp(-z * z - 1.26551223 +
                    k * (1.00002368 +
                         k * (0.37409196 +
                              k * (0.09678418 +
                                   k * (-0.18628806 +
                                        k * (0.27886807 +
                                             k * (-1.13520398 + k * (1.48851587 + k * (-0.82215223 + k * 0.17087277)))))))));
  return t >= 0.0 ? 1.0 - 0.5 * r : 0.5 * r;
}

#include "mlp/enc_net.glsl"
