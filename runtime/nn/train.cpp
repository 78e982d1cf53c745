#include "nn/train.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <limits>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "gl/context.h"
#include "io/text.h"
#include "nn/cpu_net.h"
#include "nn/encoding.h"
#include "nn/diagnostics.h"
#include "io/parallel.h"

namespace sn::nn {

namespace {

std::string names(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& n : v) s += (s.empty() ? "" : ", ") + n;
  return s;
}

void check_rows(const std::vector<float>& v, std::size_t width, const char* what) {
  for (std::size_t j = 0; j < v.size(); ++j)
    if (!std::isfinite(v[j]))
      throw std::invalid_argument(std::string("dataset: ") + what + " row " + std::to_string(j / width + 1) +
                                  " column " + std::to_string(j % width + 1) + " is " +
                                  (std::isnan(v[j]) ? "NaN" : "infinite"));
}

}  // namespace

bool DivergenceRule::exploded(double val_mse, double best_before) const {
  if (!std::isfinite(val_mse)) return true;
  if (!(constant_mse >= 0)) return false;  // no constant predictor: backends called without the job
  return val_mse > constant_mse && val_mse > factor * best_before;
}

float DivergenceRule::sample_limit(double initial_val_mse, int outputs) const {
  const double inf = std::numeric_limits<double>::infinity();
  if (!(constant_mse >= 0) || factor == inf) return std::numeric_limits<float>::infinity();
  double reference = constant_mse;
  if (initial_val_mse > reference) reference = initial_val_mse;  // NaN: ignored
  // A zero reference (constant targets and a perfect start) bounds nothing.
  if (!(reference > 0)) return std::numeric_limits<float>::infinity();
  return float(std::min(kSampleFactor * double(outputs) * reference, double(std::numeric_limits<float>::max())));
}

double constant_predictor_mse(const data::Dataset& d) {
  const std::size_t n = d.train_count(), m = d.val_count(), k = std::size_t(d.outputs);
  if (!n || !m || !k) return -1;
  std::vector<double> mean(k, 0.0);
  for (std::size_t r = 0; r < n; ++r)
    for (std::size_t o = 0; o < k; ++o) mean[o] += d.train_y[r * k + o];
  for (double& v : mean) v /= double(n);
  double sum = 0;
  for (std::size_t r = 0; r < m; ++r)
    for (std::size_t o = 0; o < k; ++o) {
      const double e = d.val_y[r * k + o] - mean[o];
      sum += e * e;
    }
  return sum / (double(m) * double(k));
}

void check_dataset(const data::Dataset& d) {
  if (d.inputs < 1 || d.outputs < 1)
    throw std::invalid_argument("dataset: needs at least 1 input and 1 output column, has " +
                                std::to_string(d.inputs) + " and " + std::to_string(d.outputs));
  const std::size_t n = d.train_count(), m = d.val_count();
  if (d.train_x.size() != n * d.inputs || d.train_y.size() != n * d.outputs || d.val_x.size() != m * d.inputs ||
      d.val_y.size() != m * d.outputs)
    throw std::invalid_argument("dataset: inputs and targets have different row counts");
  check_rows(d.train_x, std::size_t(d.inputs), "training input");
  check_rows(d.train_y, std::size_t(d.outputs), "training target");
  check_rows(d.val_x, std::size_t(d.inputs), "validation input");
  check_rows(d.val_y, std::size_t(d.outputs), "validation target");
}

void validate(const TrainJob& job) {
  using std::to_string;
  auto fail = [](const std::string& m) { throw std::invalid_argument(m); };
  if (job.nets.empty()) fail("no networks to train (nets is empty)");
  if (!job.data) fail("no dataset to train on");
  const data::Dataset& d = *job.data;
  const TrainConfig& c = job.config;
  if (c.epochs < 1) fail("epochs must be at least 1, got " + to_string(c.epochs));
  if (c.batch < 1) fail("batch must be at least 1, got " + to_string(c.batch));
  // The kernels run Adam in float: a setting that rounds to 0 or 1 there (lr 1e-50, beta
  // 0.99999999) was taken and trained nothing, or blew the net up, without a word.
  constexpr double kFloatMin = double(std::numeric_limits<float>::min()), kFloatMax = double(std::numeric_limits<float>::max());
  if (!(c.lr >= kFloatMin && c.lr <= kFloatMax))
    fail("adam lr must be a normal float (the kernels run in float), 1.1754944e-38 to 3.4028235e38, got " +
         io::number_text(c.lr));
  for (auto [name, beta] : {std::pair<const char*, double>{"beta1", c.beta1}, {"beta2", c.beta2}})
    if (!(beta >= 0 && float(beta) < 1.0f))
      fail(std::string("adam ") + name + " must be in [0, 1) as a float (the kernels run in float; the largest is " +
           "0.99999994), got " + io::number_text(beta, 1.0));
  // A normal float: the kernels flush denormals to zero (and run in float), so a smaller eps was
  // 0 there, and a parameter with no gradient went 0/0 at the first step.
  if (!(c.eps >= double(std::numeric_limits<float>::min()) && c.eps <= double(std::numeric_limits<float>::max())))
    fail("adam eps must be a normal float, at least 1.1754944e-38, got " + io::number_text(c.eps, 1.1754944e-38));
  if (!(c.divergence.factor >= 1))
    fail("divergence_factor must be >= 1 (math.huge turns the rule off), got " + io::number_text(c.divergence.factor));
  if (c.tick && !(c.tick_seconds > 0 && c.tick_seconds <= 3600))
    fail("tick_seconds must be in (0, 3600], got " + io::number_text(c.tick_seconds));
  if (d.train_count() < 1) fail("the dataset has no training rows");
  if (d.val_count() < 1)
    fail("the dataset has no validation rows (all " + to_string(d.train_count()) +
         " train): make it with a split below 1, or give it some with dataset:split{ split = 0.8 }");
  if (!c.seeds.empty() && c.seeds.size() != job.nets.size())
    fail("seeds: one per net, got " + to_string(c.seeds.size()) + " for " + to_string(job.nets.size()) + " nets");
  if (std::size_t(c.batch) > d.train_count())
    fail("batch " + to_string(c.batch) + " is larger than the training set (" + to_string(d.train_count()) +
         " rows)");
  if (d.train_count() >= (std::size_t(1) << 31)) fail("the training set has more than 2^31 rows");
  for (std::size_t i = 0; i < job.nets.size(); ++i) {
    const Mlp& net = *job.nets[i];
    const std::string who = "net " + to_string(i + 1) + " (" + net.spec.describe() + ")";
    for (std::size_t j = 0; j < i; ++j)
      if (job.nets[j] == job.nets[i]) fail("net " + to_string(i + 1) + " is the same network as net " + to_string(j + 1));
    try {
      net.spec.validate();
    } catch (const std::exception& e) {
      fail("net " + to_string(i + 1) + ": " + e.what());
    }
    if (net.params.size() != net.spec.param_count()) fail(who + ": parameter count does not match its spec");
    for (std::size_t j = 0; j < net.params.size(); ++j)
      if (!std::isfinite(net.params[j]))
        fail(who + ": " + net.spec.param_name(j) + " (parameter " + to_string(j + 1) + ") is not finite");
    if (net.spec.inputs != d.inputs)
      fail(who + " reads " + to_string(net.spec.inputs) + " inputs but the dataset has " + to_string(d.inputs) +
           (d.input_names.empty() ? "" : " (" + names(d.input_names) + ")"));
    if (net.spec.outputs != d.outputs)
      fail(who + " has " + to_string(net.spec.outputs) + " outputs but the dataset's targets have " +
           to_string(d.outputs));
    if (net.spec.color != d.color)
      fail(who + " learns in colour space " + shading::color_space_name(net.spec.color) + " but the dataset's targets are " +
           shading::color_space_name(d.color));
    if (!net.input_names.empty() && !d.input_names.empty() && net.input_names != d.input_names)
      fail(who + " reads {" + names(net.input_names) + "} but the dataset provides {" + names(d.input_names) + "}");
  }
  check_dataset(d);
}

namespace {
// The first net with an activation the cpu backend cannot run (a user's definition whose GLSL
// does not translate), or nullptr; `index` and `without` get its place and that activation.
const Mlp* net_without_cpu_code(const std::vector<Mlp*>& nets, std::size_t* index, Activation* without) {
  for (std::size_t i = 0; i < nets.size(); ++i)
    if (!has_cpu_code(nets[i]->spec, without)) {
      *index = i;
      return nets[i];
    }
  return nullptr;
}
}  // namespace

std::string resolve_backend(const std::string& requested, std::string* reason, const std::vector<Mlp*>& nets) {
  std::size_t i = 0;
  Activation a;
  const Mlp* custom = net_without_cpu_code(nets, &i, &a);
  if (requested == "cpu" && custom) {
    const MlpSpec& s = custom->spec;
    throw std::invalid_argument("net " + std::to_string(i + 1) + " (" + s.describe() + "): " + activation_without_cpu_code(a) +
                                ": train it with backend = \"gl\"");
  }
  if (requested != "auto") {
    if (reason) *reason = "requested";
    return requested;
  }
  if (custom && has_backend("gl")) {
    if (reason) *reason = activation_without_cpu_code(a);
    return "gl";
  }
  if (!has_backend("gl")) {
    if (reason) *reason = "no gl backend in this build";
    return "cpu";
  }
  const gl::ContextInfo& info = gl::current().info();
  if (info.software) {
    if (reason) *reason = "software renderer (" + info.renderer + "): the native cpu backend is faster";
    return "cpu";
  }
  if (reason) *reason = "hardware GPU (" + info.renderer + ")";
  return "gl";
}

namespace {
// A job with more distinct seeds than the backend takes in one call (Backend::seeds_per_call)
// trains them in calls of at most `per_call` seeds, each seed's nets in one call, the seeds in
// the order of their first net.
std::vector<NetResult> train_by_seed(Backend& backend, const std::vector<const Mlp*>& nets, const data::Dataset& d,
                                     const TrainConfig& cfg, const Progress& progress, std::size_t per_call) {
  const std::vector<uint32_t> order = cfg.distinct_seeds(nets.size());
  std::vector<NetResult> out(nets.size());
  for (std::size_t first = 0; first < order.size(); first += per_call) {
    const auto from = order.begin() + long(first), to = order.begin() + long(std::min(order.size(), first + per_call));
    std::vector<std::size_t> index;  // the call's nets in the job
    for (std::size_t j = 0; j < nets.size(); ++j)
      if (std::find(from, to, cfg.seed_of(j)) != to) index.push_back(j);
    TrainConfig one = cfg;
    one.seed = *from;
    one.seeds.clear();
    one.initial_val_mse.clear();
    std::vector<const Mlp*> some;
    for (std::size_t j : index) {
      some.push_back(nets[j]), one.initial_val_mse.push_back(cfg.initial_val_mse_of(j));
      if (to - from > 1) one.seeds.push_back(cfg.seed_of(j));
    }
    Progress mapped;
    if (progress)
      mapped = [&](const ProgressEvent& e) {
        ProgressEvent m = e;
        m.net = int(index[std::size_t(e.net)]);
        progress(m);
      };
    auto results = backend.train(some, d, one, mapped);
    for (std::size_t k = 0; k < index.size(); ++k) out[index[k]] = std::move(results[k]);
  }
  return out;
}
}  // namespace

JobResult train(const TrainJob& job) {
  validate(job);
  JobResult out;
  out.backend = resolve_backend(job.backend, &out.reason, job.nets);
  auto backend = make_backend(out.backend);
  std::vector<const Mlp*> nets(job.nets.begin(), job.nets.end());

  // One stop flag for every source: the caller's (Ctrl-C) and a progress function's error.
  std::atomic<bool> own_stop{false};
  std::atomic<bool>& stop = job.stop ? *job.stop : own_stop;
  TrainConfig cfg = job.config;
  cfg.stop = &stop;
  // Adam's settings as the floats the kernels use, so the moments (float) and the bias
  // corrections (computed in double from these) agree: beta2 0.9999999 made steps 1.83x Adam's.
  cfg.lr = double(float(cfg.lr)), cfg.beta1 = double(float(cfg.beta1)), cfg.beta2 = double(float(cfg.beta2));
  cfg.eps = double(float(cfg.eps));
  cfg.divergence.constant_mse = constant_predictor_mse(*job.data);
  // The untrained nets' validation MSE, where they have cpu code (a net whose activation's GLSL
  // does not translate is measured by its backend): one number per net whichever backend trains it.
  const data::Dataset& d = *job.data;
  cfg.initial_val_mse.assign(nets.size(), std::numeric_limits<double>::quiet_NaN());
  // The validation rows as each net's first layer reads them (the cpu kernels' input), encoded
  // here once per distinct set of encodings, on this thread (a user's encoding is a Lua
  // function), for the untrained MSE and the diagnostics after training: each had encoded them
  // again per net (a third of a 32-net frequency-encoded job's time).
  std::vector<std::pair<const std::vector<InputEncoding>*, std::vector<float>>> encoded;
  std::vector<const float*> val_rows(nets.size(), d.val_x.data());
  for (std::size_t i = 0; i < nets.size(); ++i) {
    const auto& encs = nets[i]->spec.encodings;
    if (encs.empty() || !has_cpu_code(nets[i]->spec)) continue;
    auto same = std::find_if(encoded.begin(), encoded.end(), [&](const auto& e) { return *e.first == encs; });
    if (same == encoded.end())
      same = encoded.insert(encoded.end(), {&encs, encode_rows(encs, nets[i]->spec.inputs, d.val_x.data(), d.val_count())});
    val_rows[i] = same->second.data();
  }
  const int threads = io::default_threads();
  io::parallel_for(int(nets.size()), threads, [&](int i) {
    const MlpSpec& s = nets[std::size_t(i)]->spec;
    if (!has_cpu_code(s)) return;
    CpuNet net(s, nets[std::size_t(i)]->params.data());
    cfg.initial_val_mse[std::size_t(i)] = net.mse(val_rows[std::size_t(i)], d.val_y.data(), d.val_count());
  });
  // The first exception of the progress or tick function stops the job.
  std::exception_ptr hook_error;
  auto guarded = [&](auto hook) {
    return [&hook_error, &stop, hook](const auto& event) {
      if (hook_error) return;
      try {
        hook(event);
      } catch (...) {
        hook_error = std::current_exception();
        stop.store(true);
      }
    };
  };
  Progress progress;
  if (job.progress) progress = guarded(job.progress);
  if (cfg.tick) cfg.tick = guarded(job.config.tick);

  const auto t0 = std::chrono::steady_clock::now();
  // One seed in all but form is the job's seed (what every backend reads).
  if (!cfg.seeds.empty() && std::all_of(cfg.seeds.begin(), cfg.seeds.end(), [&](uint32_t s) { return s == cfg.seeds[0]; })) {
    cfg.seed = cfg.seeds[0];
    cfg.seeds.clear();
  }
  const std::size_t per_call = std::max<std::size_t>(1, backend->seeds_per_call(job.data->train_count()));
  out.nets = cfg.distinct_seeds(nets.size()).size() <= per_call
                 ? backend->train(nets, *job.data, cfg, progress)
                 : train_by_seed(*backend, nets, *job.data, cfg, progress, per_call);
  out.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  out.device = backend->device();  // after the job: the gl backend names the kernels it ran
  if (out.nets.size() != nets.size()) throw std::logic_error("backend " + out.backend + " returned wrong result count");
  const long long steps_per_epoch = (long long)(job.data->train_count() / std::size_t(cfg.batch));

  for (std::size_t i = 0; i < nets.size(); ++i) {
    Mlp& net = *job.nets[i];
    NetResult& r = out.nets[i];
    if (r.final_params.size() != net.params.size())
      throw std::logic_error("backend " + out.backend + " returned a wrong parameter count");
    // A stop at an epoch's start is the end of the epoch before.
    if (r.interrupted && r.interrupted->step == 0 && r.interrupted->epoch > 1)
      r.interrupted = StopPoint{r.interrupted->epoch - 1, steps_per_epoch};
    r.wall_time = out.wall_time;
    r.sample_steps_per_s = out.wall_time > 0 ? double(r.steps) * job.config.batch / out.wall_time : 0.0;
    net.params = r.final_params;
    net.best_params = r.best_params;
    net.best_val_mse = r.best_val_mse;
    net.best_epoch = r.best_epoch;
    net.trained_steps += uint64_t(r.steps);
    if (net.input_names.empty()) net.input_names = job.data->input_names;
    // The conditions span the range of the data last trained on (a retraining on another range
    // moves them); a value set before stays where it still lies inside, else the middle.
    if (net.input_names == job.data->input_names) {
      std::vector<Condition> now;
      for (const auto& c : job.data->conditions) {
        double value = 0.5 * (c.min + c.max);
        for (const auto& old : net.conditions)
          if (old.name == c.name && old.value >= c.min && old.value <= c.max) value = old.value;
        now.push_back({c.name, c.min, c.max, value});
      }
      net.conditions = now;
    }
    if (job.keep == Keep::best && r.best_epoch > 0) net.params = r.best_params;
    net.touch();
  }
  io::parallel_for(int(nets.size()), threads, [&](int i) {
    out.nets[i].dead_units = dead_unit_fractions(*job.nets[i], val_rows[std::size_t(i)], d.val_count());
    out.nets[i].stuck_outputs = stuck_outputs(*job.nets[i], val_rows[std::size_t(i)], d.val_count());
  });
  // The nets keep what was trained; then the progress or tick function's error goes on to the caller.
  if (hook_error) std::rethrow_exception(hook_error);
  return out;
}

}  // namespace sn::nn
