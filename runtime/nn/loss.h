// The training losses, per output component with error e = net(x) - y and target y, averaged
// over the minibatch's samples and the network's outputs like the MSE (nn/trainer.h):
//   l2           e^2 (the thesis' MSE, the default)
//   l1           |e|                           (d/de: sign e, 0 at 0)
//   relative_l2  e^2 / (y^2 + 0.01)            (highlights: errors relative to the target; the
//                denominator is the target's, so the gradient is exact; tiny-cuda-nn divides by
//                the prediction with its gradient stopped)
//   huber        e^2 / 2 for |e| <= delta, delta (|e| - delta / 2) beyond (PyTorch HuberLoss)
// Written once in double here (the oracle's), in GLSL (shaders/include/mlp/loss.glsl) and in
// the cpu backend's SIMD code (nn/cpu_net.cpp).
#pragma once
#include <string>

namespace sn::nn {

enum class LossKind { l2, l1, relative_l2, huber };

constexpr double kRelativeL2Eps = 0.01;

struct Loss {
  LossKind kind = LossKind::l2;
  double delta = 1.0;  // huber's

  // "l2", "l1", "relative_l2", "huber(delta=0.1)": what results and tables call it.
  std::string describe() const;
  // The loss of one component and its derivative with respect to the prediction.
  double value(double e, double target) const;
  double grad(double e, double target) const;
  bool operator==(const Loss& o) const { return kind == o.kind && (kind != LossKind::huber || delta == o.delta); }
};

// Throws "unknown loss 'x' (valid: l2, l1, relative_l2, huber)", or for a delta out of (0, 1e6].
Loss parse_loss(const std::string& name, double delta = 1.0);

}  // namespace sn::nn
