#include "nn/oracle.h"

#include <cmath>

#include "nn/shuffle.h"

namespace sn::nn::oracle {

double activate(Activation a, double param, double z) { return activation_def(a).f(z, param); }

double activate_grad(Activation a, double param, double z) { return activation_def(a).df(z, param); }

namespace {
Activation layer_activation(const MlpSpec& s, int l) {
  return l == s.layers() - 1 ? s.output_activation : s.activation;
}
}  // namespace

std::vector<double> forward(const MlpSpec& spec, const std::vector<double>& p, const double* x, Trace* trace) {
  // a[0]: the raw inputs encoded (nn/encoding.h), in double.
  std::vector<double> a(std::size_t(spec.width(0))), z;
  if (spec.encodings.empty()) a.assign(x, x + spec.inputs);
  else encode_row(spec.encodings, spec.inputs, x, a.data());
  if (trace) {
    trace->a.assign(1, a);
    trace->z.assign(1, {});
  }
  for (int l = 0; l < spec.layers(); ++l) {
    int in = spec.width(l), out = spec.width(l + 1);
    const double* w = p.data() + spec.weight_offset(l);
    const double* b = p.data() + spec.bias_offset(l);
    z.assign(out, 0.0);
    std::vector<double> next(out);
    for (int o = 0; o < out; ++o) {
      double s = b[o];
      for (int i = 0; i < in; ++i) s += w[o * in + i] * a[i];
      z[o] = s;
      next[o] = activate(layer_activation(spec, l), spec.param(layer_activation(spec, l)), s);
    }
    a = std::move(next);
    if (trace) {
      trace->z.push_back(z);
      trace->a.push_back(a);
    }
  }
  return a;
}

double loss_grad(const MlpSpec& spec, const std::vector<double>& p, const std::vector<const float*>& xs,
                 const std::vector<const float*>& ys, std::vector<double>* grad, const Loss& lf) {
  const std::size_t count = xs.size();
  const int L = spec.layers(), outs = spec.outputs;
  if (grad) grad->assign(spec.param_count(), 0.0);
  double loss = 0;
  const double scale = 1.0 / (double(count) * outs);  // of the mean
  Trace t;
  std::vector<double> x(spec.inputs);
  for (std::size_t n = 0; n < count; ++n) {
    for (int i = 0; i < spec.inputs; ++i) x[i] = xs[n][i];
    auto y = forward(spec, p, x.data(), &t);
    std::vector<double> delta(outs);
    for (int o = 0; o < outs; ++o) {
      double d = y[o] - ys[n][o];
      loss += lf.value(d, ys[n][o]);
      delta[o] = scale * lf.grad(d, ys[n][o]) * activate_grad(spec.output_activation, spec.param(spec.output_activation), t.z[L][o]);
    }
    if (!grad) continue;
    for (int l = L - 1; l >= 0; --l) {
      int in = spec.width(l), out = spec.width(l + 1);
      double* gw = grad->data() + spec.weight_offset(l);
      double* gb = grad->data() + spec.bias_offset(l);
      const double* w = p.data() + spec.weight_offset(l);
      for (int o = 0; o < out; ++o) {
        gb[o] += delta[o];
        for (int i = 0; i < in; ++i) gw[o * in + i] += delta[o] * t.a[l][i];
      }
      if (l == 0) break;
      std::vector<double> prev(in, 0.0);
      for (int i = 0; i < in; ++i) {
        double s = 0;
        for (int o = 0; o < out; ++o) s += w[o * in + i] * delta[o];
        prev[i] = s * activate_grad(spec.activation, spec.param(spec.activation), t.z[l][i]);
      }
      delta = std::move(prev);
    }
  }
  return loss / (double(count) * outs);
}

void Adam::step(std::vector<double>& p, const std::vector<double>& g, const TrainConfig& c) {
  if (m.size() != p.size()) {
    m.assign(p.size(), 0.0);
    v.assign(p.size(), 0.0);
    t = 0;
  }
  ++t;
  const double c1 = 1.0 - std::pow(c.beta1, double(t)), c2 = 1.0 - std::pow(c.beta2, double(t));
  for (std::size_t j = 0; j < p.size(); ++j) {
    m[j] = c.beta1 * m[j] + (1 - c.beta1) * g[j];
    v[j] = c.beta2 * v[j] + (1 - c.beta2) * g[j] * g[j];
    p[j] -= c.lr * (m[j] / c1) / (std::sqrt(v[j] / c2) + c.eps);
  }
}

double mse(const MlpSpec& spec, const std::vector<double>& p, const float* x, const float* y, std::size_t count) {
  return mean_loss(spec, p, x, y, count, Loss{});
}

double mean_loss(const MlpSpec& spec, const std::vector<double>& p, const float* x, const float* y, std::size_t count,
                 const Loss& lf) {
  double sum = 0;
  std::vector<double> xi(spec.inputs);
  for (std::size_t n = 0; n < count; ++n) {
    for (int i = 0; i < spec.inputs; ++i) xi[i] = x[n * spec.inputs + i];
    auto out = forward(spec, p, xi.data());
    for (int o = 0; o < spec.outputs; ++o) {
      double d = out[o] - y[n * spec.outputs + o];
      sum += lf.value(d, y[n * spec.outputs + o]);
    }
  }
  return count ? sum / (double(count) * spec.outputs) : 0.0;
}

NetResult train(const MlpSpec& spec, const std::vector<float>& params, const data::Dataset& data, const TrainConfig& cfg) {
  NetResult r;
  std::vector<double> p(params.begin(), params.end()), g;
  Adam adam;
  const uint32_t n = uint32_t(data.train_count());
  const long long steps = n / cfg.batch;
  std::vector<const float*> xs(cfg.batch), ys(cfg.batch);
  r.initial_val_mse = mse(spec, p, data.val_x.data(), data.val_y.data(), data.val_count());
  const double sample_limit = cfg.divergence.sample_limit(r.initial_val_mse, spec.outputs);
  for (int e = 0; e < cfg.epochs; ++e) {
    EpochShuffle perm(cfg.seed, uint32_t(e), n);
    double sum = 0;
    for (long long s = 0; s < steps; ++s) {
      for (int k = 0; k < cfg.batch; ++k) {
        uint32_t row = perm(uint32_t(s * cfg.batch + k));
        xs[k] = data.train_x.data() + std::size_t(row) * data.inputs;
        ys[k] = data.train_y.data() + std::size_t(row) * data.outputs;
      }
      double loss = loss_grad(spec, p, xs, ys, &g, cfg.loss);
      // The rule's bound on each sample's squared error (nn/trainer.h), after the loss's check.
      if (std::isfinite(loss) && std::isfinite(sample_limit)) {
        bool too_big = false;
        std::vector<double> xi(spec.inputs);
        for (int k = 0; k < cfg.batch && !too_big; ++k) {
          for (int i = 0; i < spec.inputs; ++i) xi[i] = xs[k][i];
          const auto out = forward(spec, p, xi.data());
          double se = 0;
          for (int o = 0; o < spec.outputs; ++o) se += (out[o] - ys[k][o]) * (out[o] - ys[k][o]);
          too_big = se > sample_limit;
        }
        if (too_big) {
          r.diverged = Divergence{e + 1, s + 1, DivergenceKind::exploded};
          break;
        }
      }
      auto before = p;
      adam.step(p, g, cfg);
      bool finite = std::isfinite(loss);
      for (double v : p) finite = finite && std::isfinite(float(v));
      if (!finite) {
        p = before;
        r.diverged = Divergence{e + 1, s + 1, DivergenceKind::nonfinite};
        break;
      }
      sum += loss;
      ++r.steps;
    }
    if (r.diverged) break;
    std::vector<float> pf(p.begin(), p.end());
    const double val = mse(spec, p, data.val_x.data(), data.val_y.data(), data.val_count());
    const double val_loss = cfg.loss.kind == LossKind::l2
                                ? val
                                : mean_loss(spec, p, data.val_x.data(), data.val_y.data(), data.val_count(), cfg.loss);
    if (!r.end_epoch(cfg, steps, sum / double(steps), val, val_loss, pf.data(), pf.size())) break;
  }
  r.final_params.assign(p.begin(), p.end());
  return r;
}

}  // namespace sn::nn::oracle
