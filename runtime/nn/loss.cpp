#include "nn/loss.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "io/text.h"

namespace sn::nn {

std::string Loss::describe() const {
  switch (kind) {
    case LossKind::l1: return "l1";
    case LossKind::relative_l2: return "relative_l2";
    case LossKind::huber: {
      char buf[48];
      std::snprintf(buf, sizeof buf, "huber(delta=%g)", delta);
      return buf;
    }
    default: return "l2";
  }
}

double Loss::value(double e, double t) const {
  switch (kind) {
    case LossKind::l1: return std::fabs(e);
    case LossKind::relative_l2: return e * e / (t * t + kRelativeL2Eps);
    case LossKind::huber: return std::fabs(e) <= delta ? 0.5 * e * e : delta * (std::fabs(e) - 0.5 * delta);
    default: return e * e;
  }
}

double Loss::grad(double e, double t) const {
  switch (kind) {
    case LossKind::l1: return e > 0 ? 1.0 : e < 0 ? -1.0 : 0.0;
    case LossKind::relative_l2: return 2.0 * e / (t * t + kRelativeL2Eps);
    case LossKind::huber: return e > delta ? delta : e < -delta ? -delta : e;
    default: return 2.0 * e;
  }
}

Loss parse_loss(const std::string& name, double delta) {
  Loss l;
  if (name == "l2") l.kind = LossKind::l2;
  else if (name == "l1") l.kind = LossKind::l1;
  else if (name == "relative_l2") l.kind = LossKind::relative_l2;
  else if (name == "huber") l.kind = LossKind::huber;
  else throw std::invalid_argument("unknown loss '" + name + "' (valid: l2, l1, relative_l2, huber)");
  // A normal float at least: the kernels flush denormals to zero, where the loss would be 0.
  if (!(delta >= 1e-30 && delta <= 1e6))
    throw std::invalid_argument("huber delta must be in [1e-30, 1e6], got " + io::number_text(delta));
  l.delta = delta;
  return l;
}

}  // namespace sn::nn
