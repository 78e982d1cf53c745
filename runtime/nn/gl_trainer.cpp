#include "nn/gl_trainer.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <numeric>
#include <stdexcept>
#include <thread>

#include "gl/buffer.h"
#include "gl/buffer_texture.h"
#include "gl/context.h"
#include "gl/program.h"
#include "io/text.h"
#include "nn/gl_forward.h"
#include "nn/mlp_per_net.h"
#include "nn/mlp_shader.h"
#include "nn/shuffle.h"

namespace sn::nn {

namespace {

using Kernel = GlTrainOptions::Kernel;

// The options' kernel, or where they leave it automatic SHADENET_GL_KERNEL's, so that a benchmark
// can price both kernels on one device without a rebuild.
Kernel kernel_in_use(Kernel asked) {
  const char* force = std::getenv("SHADENET_GL_KERNEL");
  if (asked != Kernel::automatic || !force || !*force) return asked;
  const std::string name = force;
  if (name == "auto") return Kernel::automatic;
  if (name == "per_sample") return Kernel::per_sample;
  if (name == "per_net") return Kernel::per_net;
  throw std::invalid_argument("SHADENET_GL_KERNEL='" + name +
                              "': unknown gl training kernel (valid: auto, per_sample, per_net)");
}

// Mirrors NetControl in shaders/include/mlp/train_io.glsl (std430).
struct GlControl {
  int32_t limit = 0, done = 0, status = 0, remaining = 0;
  uint32_t first_row = 0;
  uint32_t t0 = 0;
  float sample_limit = 0;
  int32_t pad = 0;
  double loss_sum = 0;
};
static_assert(sizeof(GlControl) == 40, "GlControl must match the shader's std430 layout");
constexpr std::size_t kControlWords = sizeof(GlControl) / 4;

enum Status { kOk = 0, kStopped = 1, kLate = 2, kCut = 3, kExploded = 4 };

// A probe run's counting loop bound: far above any loop budget, so it counts what is left.
constexpr int kProbeCount = 1 << 22;

// A round of dispatches (one per architecture, run_epoch) aims at this long, so that a stop
// (Ctrl-C, a progress function's "stop") is seen within about this time even in a long epoch;
// chunking never changes a result (the kernel carries the loss sum and Adam's t across
// dispatches). Without a loop limiter (a hardware GPU) the first dispatch of an architecture
// holds kFirstChunk steps and later ones are sized from the round's measured time per step.
constexpr double kRoundSeconds = 0.25;
constexpr long long kFirstChunk = 64;

// The epoch's orders, one permutation of the rows per seed of the call, take at most this much
// GPU memory (Backend::seeds_per_call); a call of Table 4.1's ten seeds takes 2 MB.
constexpr std::size_t kMaxOrderBytes = std::size_t(256) << 20;

struct NetRun {
  int index = 0;         // into the job's nets
  uint32_t order_base = 0;  // where its seed's permutation starts in the order buffer
  bool active = true;    // false once diverged
  long long step = 0;    // steps done in the current epoch
  long long t = 0;       // Adam steps applied in this run
  double loss_sum = 0;   // this epoch's sum of minibatch squared errors
  long long stop_at = -1;  // >= 0: the step (0-based) whose update is not finite; stop before it
  int epochs_done = 0;
  float sample_limit = 0;  // the divergence rule's bound on a sample's squared error
  DivergenceKind stop_kind = DivergenceKind::nonfinite;  // why stop_at
};

struct Group {
  MlpSpec spec;
  std::vector<NetRun> runs;
  std::shared_ptr<gl::Program> program;
  TrainLayout layout;
  std::unique_ptr<gl::Buffer> state, scratch, control;
  std::unique_ptr<gl::Buffer> staged;  // what the last dispatch made, state's layout (mlp/train_io.glsl)
  std::unique_ptr<gl::BufferTexture> state_texture;  // the per-network kernel reads state through it
  int after_steps = 0;  // loop iterations a dispatch runs after its steps (staging, the loss sum, the check)
  long long chunk = 0;      // steps per dispatch now (timed, at most max_chunk)
  long long max_chunk = 0;  // the loop budget's bound (or steps_per_dispatch when forced)
  GlGroupReport report;
};

struct DataBuffers {
  std::unique_ptr<gl::Buffer> train_x, train_y, val_x, val_y, order, bias;
  uint32_t bias_len = 0;
  // train_x, train_y, order as textures (made when a group uses the per-network kernel).
  std::unique_ptr<gl::BufferTexture> train_x_texture, train_y_texture, order_texture;
};

// Sized for reading as a texture too (gl::texture_buffer_size).
std::unique_ptr<gl::Buffer> upload_floats(const std::vector<float>& v) {
  auto b = std::make_unique<gl::Buffer>(gl::ElemType::float32, gl::texture_buffer_size(std::max<std::size_t>(1, v.size())));
  if (!v.empty()) b->upload(v.data(), 0, v.size());
  return b;
}

class Job {
 public:
  Job(const std::vector<const Mlp*>& nets, const data::Dataset& data, const TrainConfig& cfg, const GlTrainOptions& opt)
      : nets_(nets), data_(data), cfg_(cfg), opt_(opt) {
    rows_ = uint32_t(data.train_count());
    steps_ = (long long)(rows_ / uint32_t(cfg.batch));
    results_.resize(nets.size());
  }

  std::vector<NetResult> run(const Progress& progress, std::vector<GlGroupReport>& report) {
    upload_data();
    make_groups();
    // The untrained nets' validation MSE: the job's (nn/train.h), else measured here.
    for (Group& g : groups_) {
      std::vector<double> mse;
      for (const NetRun& r : g.runs) mse.push_back(cfg_.initial_val_mse_of(std::size_t(r.index)));
      if (std::any_of(mse.begin(), mse.end(), [](double v) { return std::isnan(v); })) {
        const std::vector<double> measured = validation_mse(g);
        for (std::size_t k = 0; k < mse.size(); ++k)
          if (std::isnan(mse[k])) mse[k] = measured[k];
      }
      for (std::size_t k = 0; k < g.runs.size(); ++k) {
        results_[std::size_t(g.runs[k].index)].initial_val_mse = mse[k];
        g.runs[k].sample_limit = cfg_.divergence.sample_limit(mse[k], g.spec.outputs);
      }
    }
    for (int e = 0; e < cfg_.epochs; ++e) {
      if (cfg_.stop_requested()) break;
      upload_order(uint32_t(e));
      if (e == 0)
        for (Group& g : groups_) plan_chunks(g);
      run_epoch(e);
      if (!finish_epoch(e, progress)) break;
    }
    // Stopped: every net still training ends where it is (a partial epoch's steps are kept).
    if (cfg_.stop_requested())
      for (Group& g : groups_)
        for (NetRun& r : g.runs)
          if (r.active && r.epochs_done < cfg_.epochs)
            results_[std::size_t(r.index)].interrupted = StopPoint{r.epochs_done + 1, r.step};
    for (Group& g : groups_) {
      for (NetRun& r : g.runs) {
        NetResult& res = results_[std::size_t(r.index)];
        res.final_params = download_params(g, std::size_t(&r - g.runs.data()));
        res.steps = r.t;
      }
      g.report.steps_per_dispatch = g.chunk;
      report.push_back(g.report);
    }
    return std::move(results_);
  }

 private:
  void upload_data() {
    for (const Mlp* n : nets_) {
      if (!n) throw std::invalid_argument("gl trainer: null network");
      if (n->spec.inputs != data_.inputs || n->spec.outputs != data_.outputs)
        throw std::invalid_argument("gl trainer: " + n->spec.describe() + " does not match the dataset's " +
                                    std::to_string(data_.inputs) + " inputs and " + std::to_string(data_.outputs) +
                                    " outputs");
    }
    if (cfg_.batch < 1 || steps_ < 1)
      throw std::invalid_argument("gl trainer: batch " + std::to_string(cfg_.batch) + " does not fit " +
                                  std::to_string(rows_) + " training rows");
    buf_.train_x = upload_floats(data_.train_x);
    buf_.train_y = upload_floats(data_.train_y);
    buf_.val_x = upload_floats(data_.val_x);
    buf_.val_y = upload_floats(data_.val_y);
    const std::size_t orders = seeds_.size() * std::size_t(steps_ * cfg_.batch);
    if (orders * 4 > kMaxOrderBytes)
      throw std::invalid_argument("gl trainer: the permutations of " + std::to_string(seeds_.size()) + " seeds of " +
                                  std::to_string(rows_) + " rows exceed one call's " +
                                  std::to_string(kMaxOrderBytes >> 20) + " MB (GlTrainer::seeds_per_call)");
    buf_.order = std::make_unique<gl::Buffer>(gl::ElemType::uint32, gl::texture_buffer_size(orders));
    upload_bias_corrections();
  }

  // (1 - beta1^t, 1 - beta2^t) in float for t = 1.. until both round to 1 (they only grow
  // towards 1), at most the run's steps: from a table, every chunking of the run sees the same.
  void upload_bias_corrections() {
    const long long total = steps_ * cfg_.epochs;
    // The table's length: until beta^t falls below float's half ulp of 1 (2^-25), for the larger
    // beta. Refused past 2^25 entries (256 MB; beta 0.999999 needs 1.7e7), before building it:
    // for beta 0.9999999 and a long job it took 3 GB and 13 s, and more ran out of memory.
    auto length = [](double beta) { return beta <= 0 ? 1.0 : std::ceil(-25.0 * std::log(2.0) / std::log(beta)) + 1; };
    const double needed = std::min(double(total), std::max(length(cfg_.beta1), length(cfg_.beta2)));
    constexpr double kMaxCorrections = 33554432.0;
    if (needed > kMaxCorrections)
      throw std::invalid_argument("gl trainer: adam beta1 = " + io::number_text(cfg_.beta1) + ", beta2 = " +
                                  io::number_text(cfg_.beta2) + " over " + std::to_string(total) +
                                  " steps need a table of " + io::number_text(needed) +
                                  " bias corrections, above its 2^25: betas further from 1 (1 - beta >= 1e-6), fewer "
                                  "epochs, or the cpu backend");
    std::vector<float> bc;
    bc.reserve(2 * std::size_t(needed));
    for (long long t = 1; t <= total; ++t) {
      float c1 = float(1.0 - std::pow(cfg_.beta1, double(t))), c2 = float(1.0 - std::pow(cfg_.beta2, double(t)));
      if (c1 == 1.0f && c2 == 1.0f) break;
      bc.push_back(c1);
      bc.push_back(c2);
    }
    buf_.bias_len = uint32_t(bc.size() / 2);
    buf_.bias = upload_floats(bc);
  }

  // Nets of the same architecture share a program and a dispatch.
  void make_groups() {
    const std::size_t max_shared =
        opt_.max_shared_bytes ? opt_.max_shared_bytes : std::size_t(gl::current().info().max_shared_memory);
    for (std::size_t i = 0; i < nets_.size(); ++i) {
      Group* g = nullptr;
      for (Group& x : groups_)
        if (x.spec.same_shape(nets_[i]->spec)) g = &x;
      if (!g) {
        groups_.emplace_back();
        g = &groups_.back();
        g->spec = nets_[i]->spec;
      }
      NetRun r;
      r.index = int(i);
      const auto slot = std::find(seeds_.begin(), seeds_.end(), cfg_.seed_of(i)) - seeds_.begin();
      r.order_base = uint32_t(std::size_t(slot) * std::size_t(steps_ * cfg_.batch));
      g->runs.push_back(r);
    }
    const Kernel kernel = kernel_in_use(opt_.kernel);
    for (Group& g : groups_) {
      const std::size_t P = g.spec.param_count(), PQ = padded_chunks(g.spec), n = g.runs.size();
      const bool want_per_net =
          kernel == Kernel::per_net || (kernel == Kernel::automatic && gl::current().info().software);
      const bool data_fits = std::max(buf_.train_x->count(), buf_.order->count()) <= gl::BufferTexture::max_texels();
      g.layout = plan_train_layout(g.spec, cfg_.batch, max_shared, want_per_net && data_fits);
      if (kernel == Kernel::per_net && !g.layout.per_net)
        throw std::invalid_argument("gl trainer: " + g.spec.describe() +
                                    (data_fits ? " is too large for the per-network kernel"
                                               : ": the dataset is larger than the driver's texture buffers, which the "
                                                 "per-network kernel reads"));
      gl::ProgramDesc desc;
      desc.compute = g.layout.per_net ? "mlp_train_per_net.comp" : "mlp_train.comp";
      desc.defines = train_defines(g.spec, cfg_.batch, g.layout, cfg_.loss);
      desc.includes = mlp_includes(g.spec);
      g.program = gl::get_program(desc);
      g.state = std::make_unique<gl::Buffer>(gl::ElemType::vec4, gl::texture_buffer_size(3 * PQ * n));  // params, m = 0, v = 0
      for (std::size_t k = 0; k < n; ++k) {
        const Mlp& net = *nets_[std::size_t(g.runs[k].index)];
        if (net.params.size() != P) throw std::invalid_argument("gl trainer: " + net.spec.describe() + " has no parameters");
        auto padded = pack_padded(g.spec, net.params.data());
        g.state->upload(padded.data(), 4 * 3 * PQ * k, padded.size());
      }
      g.staged = std::make_unique<gl::Buffer>(gl::ElemType::vec4, g.state->count());
      g.scratch = std::make_unique<gl::Buffer>(gl::ElemType::vec4, std::max<std::size_t>(1, g.layout.scratch_vec4s * n));
      g.control = std::make_unique<gl::Buffer>(gl::ElemType::uint32, kControlWords * n);
      if (g.layout.per_net) {
        g.state_texture = std::make_unique<gl::BufferTexture>(*g.state);
        if (!buf_.train_x_texture) {
          buf_.train_x_texture = std::make_unique<gl::BufferTexture>(*buf_.train_x);
          buf_.train_y_texture = std::make_unique<gl::BufferTexture>(*buf_.train_y);
          buf_.order_texture = std::make_unique<gl::BufferTexture>(*buf_.order);
        }
      }
      // After the steps: the loop staging the parameters, the loss sum's, the check's two passes
      // (a loop of n passes spends n + 1), a margin.
      g.after_steps = g.layout.per_net ? int(PQ) + 8
                                       : int((PQ + std::size_t(cfg_.batch) - 1) / std::size_t(cfg_.batch)) + cfg_.batch + 8;
      g.report.arch = g.spec.describe();
      g.report.nets = int(n);
      g.report.layout = g.layout.describe();
      g.report.per_net = g.layout.per_net;
    }
  }

  // The epoch's permutation of each seed, one after another, computed here by nn/shuffle.h (the
  // code the cpu backend and the oracle run: the same order by construction) and uploaded once
  // per epoch for all networks; in the kernel its cycle-walking loop would spend llvmpipe's loop
  // budget, per sample. A net reads its seed's from its order_base.
  void upload_order(uint32_t epoch) {
    const std::size_t n = std::size_t(steps_ * cfg_.batch);
    std::vector<uint32_t> order(n * seeds_.size());
    for (std::size_t s = 0; s < seeds_.size(); ++s) {
      EpochShuffle perm(seeds_[s], epoch, rows_);
      for (std::size_t k = 0; k < n; ++k) order[s * n + k] = perm(uint32_t(k));
    }
    buf_.order->upload(order.data(), 0, order.size());
  }

  // Starts the group's dispatch over `ctl`; nothing orders its writes before later reads (the
  // caller's barrier does, one for every dispatch issued before it).
  void issue(Group& g, const std::vector<GlControl>& ctl, bool probe) {
    g.control->upload(ctl.data(), 0, ctl.size() * kControlWords);
    const gl::Buffer* bind[8] = {buf_.train_x.get(), buf_.train_y.get(), buf_.order.get(), g.state.get(),
                                 g.scratch.get(),    g.control.get(),    buf_.bias.get(),  g.staged.get()};
    for (unsigned i = 0; i < 8; ++i) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, i, bind[i]->id());
    if (g.layout.per_net) {
      g.state_texture->bind(0);
      buf_.train_x_texture->bind(1);
      buf_.train_y_texture->bind(2);
      buf_.order_texture->bind(3);
    }
    // Every uniform, every dispatch: the program is cached and shared, and a job nested in this
    // one's progress function (another net of the same architecture) sets its own values on it.
    gl::Program& p = *g.program;
    p.set_uniform("u_beta1", {cfg_.beta1});
    p.set_uniform("u_beta2", {cfg_.beta2});
    p.set_uniform("u_eps", {cfg_.eps});
    p.set_uniform("u_bias_len", {double(buf_.bias_len)});
    p.set_uniform("u_lr", {probe ? 0.0 : cfg_.lr});
    p.set_uniform("u_probe", {probe ? 1.0 : 0.0});
    p.set_uniform("u_probe_count", {double(kProbeCount)});
    std::size_t groups = ctl.size();
    if (g.layout.per_net) {
      // Up to kNetsPerGroup networks a workgroup, but at least one workgroup per renderer thread
      // (llvmpipe runs one per CPU) while there are networks for them.
      const std::size_t threads = std::max(1u, std::thread::hardware_concurrency());
      groups = std::max((ctl.size() + kNetsPerGroup - 1) / kNetsPerGroup, std::min(ctl.size(), threads));
      p.set_uniform("u_groups", {double(groups)});
    }
    gl::dispatch_without_barrier(p, unsigned(groups));
  }

  // The control words of the group's last dispatch (after the caller's barrier).
  void read_back(Group& g, std::size_t nets, std::vector<GlControl>& result) {
    result.resize(nets);
    g.control->download(result.data(), 0, nets * kControlWords);
  }

  // On a software renderer, two probe dispatches of the first network (1 and 2 steps, learning
  // rate 0, nothing committed) count the loop budget left after them; the difference is one
  // step's cost. A GPU has no loop limiter and is not probed.
  void plan_chunks(Group& g) {
    auto remaining_after = [&](int steps) {
      std::vector<GlControl> ctl(g.runs.size()), out;
      ctl[0].limit = steps;
      issue(g, ctl, true);
      glMemoryBarrier(GL_ALL_BARRIER_BITS);
      read_back(g, ctl.size(), out);
      return (long long)out[0].remaining;
    };
    const long long r1 = gl::current().info().software ? remaining_after(1) : kProbeCount;
    if (r1 >= kProbeCount) {
      g.max_chunk = steps_;  // no limiter: up to one dispatch per epoch, as time allows
      g.chunk = std::min(steps_, kFirstChunk);
    } else {
      const long long cost = r1 - remaining_after(2);
      g.report.loop_budget = r1;
      g.report.loop_cost_per_step = cost;
      const long long margin = 16 + r1 / 50;
      if (r1 < g.after_steps + margin || cost <= 0)
        throw loop_budget_error(g.spec, "training step");
      g.chunk = g.max_chunk = std::min(steps_, 1 + (r1 - g.after_steps - margin) / cost);
    }
    if (opt_.steps_per_dispatch > 0) g.chunk = g.max_chunk = std::min(steps_, opt_.steps_per_dispatch);
  }

  // Sizes the group's next dispatches from the last round: `steps` of it took `seconds`.
  void time_chunks(Group& g, long long steps, double seconds) {
    if (opt_.steps_per_dispatch > 0 || steps < 1 || !(seconds > 0)) return;
    const double per_step = seconds / double(steps);
    // With a tick, short enough for the caller to tick between rounds on time.
    const double target = cfg_.tick ? std::min(kRoundSeconds, cfg_.tick_seconds) : kRoundSeconds;
    g.chunk = std::clamp((long long)(target / per_step), 1LL, g.max_chunk);
  }

  void diverge(NetRun& r, int epoch) {
    r.active = false;
    results_[std::size_t(r.index)].diverged = Divergence{epoch + 1, r.stop_at + 1, r.stop_kind};
  }

  // The group's next dispatch: each net that has steps left this epoch, up to the group's chunk.
  // False when none has.
  bool prepare(Group& g, int e, std::vector<GlControl>& ctl) {
    ctl.assign(g.runs.size(), GlControl{});
    bool any = false;
    for (std::size_t k = 0; k < g.runs.size(); ++k) {
      NetRun& r = g.runs[k];
      if (r.active && r.stop_at >= 0 && r.step == r.stop_at) diverge(r, e);
      if (!r.active || r.step >= steps_) continue;
      const long long end = r.stop_at >= 0 ? r.stop_at : steps_;
      ctl[k].limit = int32_t(std::min(g.chunk, end - r.step));
      ctl[k].first_row = r.order_base + uint32_t(r.step * cfg_.batch);
      ctl[k].loss_sum = r.loss_sum;
      ctl[k].t0 = uint32_t(r.t);
      ctl[k].sample_limit = r.sample_limit;
      any = true;
    }
    return any;
  }

  // What the kernel reports for each net of a dispatch; `seconds` sizes the next one.
  void settle(Group& g, int e, const std::vector<GlControl>& ctl, const std::vector<GlControl>& out, double seconds) {
    ++g.report.dispatches;
    bool cut = false, cut_at_one = false;
    std::vector<char> sound(g.runs.size(), 0);  // its staged state is committed
    for (std::size_t k = 0; k < g.runs.size(); ++k) {
      if (ctl[k].limit <= 0) continue;
      NetRun& r = g.runs[k];
      const GlControl& c = out[k];
      switch (c.status) {
        case kOk:
          if (c.done != ctl[k].limit)
            throw std::logic_error("gl trainer: the kernel finished " + std::to_string(c.done) + " of " +
                                   std::to_string(ctl[k].limit) + " steps and gave no reason");
          [[fallthrough]];
        case kStopped:
        case kExploded:
          sound[k] = 1;
          r.step += c.done;
          r.t += c.done;
          r.loss_sum = c.loss_sum;
          if (c.status != kOk) {
            r.stop_at = r.step;
            r.stop_kind = c.status == kExploded ? DivergenceKind::exploded : DivergenceKind::nonfinite;
            diverge(r, e);
          }
          break;
        case kLate:  // nothing committed: re-run up to the step before the bad one
          r.stop_at = r.step + c.done - 1;
          ++g.report.divergence_reruns;
          break;
        case kCut:
          cut = true;
          cut_at_one = cut_at_one || ctl[k].limit == 1;
          break;
        default:
          throw std::logic_error("gl trainer: unknown kernel status " + std::to_string(c.status));
      }
    }
    commit(g, sound);
    if (!cut) {
      long long longest = 0;
      for (const GlControl& c : ctl) longest = std::max<long long>(longest, c.limit);
      time_chunks(g, longest, seconds);
      return;
    }
    ++g.report.cut_dispatches;
    if (cut_at_one)
      throw loop_budget_error(g.spec, "training step");
    g.chunk = std::max(1LL, g.chunk / 2);
    g.max_chunk = g.chunk;
  }

  // The staged state of each net whose dispatch was sound becomes its state (runs of neighbours in
  // one copy); the others' stays as it was before the dispatch.
  void commit(Group& g, const std::vector<char>& sound) {
    const std::size_t per_net = 4 * 3 * padded_chunks(g.spec);  // floats
    for (std::size_t k = 0; k < sound.size();) {
      std::size_t end = k;
      while (end < sound.size() && sound[end]) ++end;
      if (end > k) g.state->copy_from(*g.staged, k * per_net, k * per_net, (end - k) * per_net);
      k = end + (end == k);
    }
  }

  // Epoch e of every group, in rounds: each group with steps left gets one dispatch, and all of a
  // round's are issued before any is read back, so a GPU may run the architectures' workgroups
  // side by side (one architecture's are as many as its networks). A round is sized to take
  // about kRoundSeconds: each group's chunk from the round's time. A software renderer runs one
  // dispatch at a time whatever is issued: there each group is a round of its own, sized by its
  // own time (rounds of every group only added dispatches: Table 4.1 --quick --backend gl took
  // 11.4-15.1 s against 10.0-12.5 s, 4 alternating runs).
  void run_epoch(int e) {
    std::vector<std::size_t> all(groups_.size());
    std::iota(all.begin(), all.end(), std::size_t(0));
    const bool together = opt_.rounds == GlTrainOptions::Rounds::automatic
                              ? !gl::current().info().software
                              : opt_.rounds == GlTrainOptions::Rounds::all_architectures;
    if (together) return run_rounds(e, all);
    for (std::size_t i : all) run_rounds(e, {i});
  }

  void run_rounds(int e, const std::vector<std::size_t>& groups) {
    std::vector<std::vector<GlControl>> ctl(groups_.size()), out(groups_.size());
    for (;;) {
      std::vector<std::size_t> round;
      for (std::size_t i : groups)
        if (prepare(groups_[i], e, ctl[i])) round.push_back(i);
      if (round.empty() || cfg_.stop_requested()) return;
      const auto t0 = std::chrono::steady_clock::now();
      for (std::size_t i : round) issue(groups_[i], ctl[i], false);
      glMemoryBarrier(GL_ALL_BARRIER_BITS);  // one for the round's dispatches
      for (std::size_t i : round) read_back(groups_[i], ctl[i].size(), out[i]);
      const auto t1 = std::chrono::steady_clock::now();
      const double seconds = std::chrono::duration<double>(t1 - t0).count();
      if (cfg_.tick && std::chrono::duration<double>(t1 - last_tick_).count() >= cfg_.tick_seconds) {
        last_tick_ = t1;
        tick(e);
      }
      for (std::size_t i : round) settle(groups_[i], e, ctl[i], out[i], seconds);
    }
  }

  // Every dispatch binds what it uses, so whatever the tick draws in between cannot disturb it.
  void tick(int e) {
    long long sum = 0, nets = 0;
    for (const Group& g : groups_)
      for (const NetRun& r : g.runs)
        if (r.epochs_done == e) sum += r.active ? r.step : steps_, ++nets;
    cfg_.tick(TickEvent{e + 1, cfg_.epochs, nets ? sum / nets : steps_, steps_});
  }

  std::vector<float> download_params(const Group& g, std::size_t k) {
    const std::size_t PQ = padded_chunks(g.spec);
    std::vector<float> padded(4 * PQ), p(g.spec.param_count());
    g.state->download(padded.data(), 4 * 3 * PQ * k, padded.size());
    unpack_padded(g.spec, padded.data(), p.data());
    return p;
  }

  // Validation MSE of every net of the group (the run's loss too when `loss`).
  std::vector<double> validation_mse(Group& g, std::vector<double>* loss = nullptr) {
    const std::size_t val_rows = data_.val_count(), PQ = padded_chunks(g.spec);
    std::vector<double> sums(g.runs.size(), 0.0);
    if (!val_rows) return sums;
    const GlParams params{g.state.get(), 0, 3 * PQ, int(g.runs.size())};
    const double denom = double(val_rows) * g.spec.outputs;
    sums = gl_squared_errors(g.spec, params, *buf_.val_x, *buf_.val_y, val_rows);
    for (double& v : sums) v /= denom;
    if (loss) {
      *loss = gl_squared_errors(g.spec, params, *buf_.val_x, *buf_.val_y, val_rows, cfg_.loss);
      for (double& v : *loss) v /= denom;
    }
    return sums;
  }

  // Validation of every net that finished epoch e (a stop may leave some part-way); returns
  // false when none is left to train.
  bool finish_epoch(int e, const Progress& progress) {
    bool any_active = false;
    for (Group& g : groups_) {
      bool any_done = false;
      for (const NetRun& r : g.runs) any_done = any_done || (r.active && r.step == steps_);
      if (!any_done) {
        for (const NetRun& r : g.runs) any_active = any_active || r.active;
        continue;
      }
      // The run's own loss too, unless it is the MSE.
      std::vector<double> losses;
      const std::vector<double> mse = validation_mse(g, cfg_.loss.kind != LossKind::l2 ? &losses : nullptr);
      for (std::size_t k = 0; k < g.runs.size(); ++k) {
        NetRun& r = g.runs[k];
        if (!r.active) continue;
        if (r.step != steps_) {
          any_active = true;
          continue;
        }
        const double denom = double(steps_) * cfg_.batch * g.spec.outputs;
        const double train = r.loss_sum / denom;
        const double val = mse[k];
        const double val_loss = losses.empty() ? val : losses[k];
        std::vector<float> p = download_params(g, k);
        NetResult& res = results_[std::size_t(r.index)];
        if (!res.end_epoch(cfg_, steps_, train, val, val_loss, p.data(), p.size())) r.active = false;
        r.step = 0;
        r.loss_sum = 0;
        r.epochs_done = e + 1;
        any_active = any_active || r.active;
        if (progress) progress(ProgressEvent{r.index, e + 1, train, val, val_loss, &p});
      }
    }
    return any_active;
  }

  const std::vector<const Mlp*>& nets_;
  const data::Dataset& data_;
  const TrainConfig& cfg_;
  const GlTrainOptions& opt_;
  uint32_t rows_ = 0;
  long long steps_ = 0;
  const std::vector<uint32_t> seeds_ = cfg_.distinct_seeds(nets_.size());  // the order buffer's slots
  DataBuffers buf_;
  std::vector<Group> groups_;
  std::vector<NetResult> results_;
  std::chrono::steady_clock::time_point last_tick_ = std::chrono::steady_clock::now();
};

}  // namespace

// The renderer, and after a job the kernels it ran (SHADENET_GL_KERNEL's names): they round
// differently, so records made with each must not pass for one device's.
std::string GlTrainer::device() const {
  const auto& i = gl::current().info();
  std::string d = i.renderer + " (OpenGL " + i.version + ")";
  const bool per_net = std::any_of(report_.begin(), report_.end(), [](const GlGroupReport& r) { return r.per_net; });
  const bool per_sample = std::any_of(report_.begin(), report_.end(), [](const GlGroupReport& r) { return !r.per_net; });
  if (per_net || per_sample)
    d += per_net && per_sample ? ", per_net and per_sample kernels" : per_net ? ", per_net kernel" : ", per_sample kernel";
  return d;
}

std::vector<NetResult> GlTrainer::train(const std::vector<const Mlp*>& nets, const data::Dataset& data,
                                        const TrainConfig& cfg, const Progress& progress) {
  report_.clear();
  if (nets.empty()) return {};
  Job job(nets, data, cfg, options_);
  return job.run(progress, report_);
}

std::size_t GlTrainer::seeds_per_call(std::size_t train_rows) const {
  const std::size_t rows = std::max<std::size_t>(1, train_rows);
  return std::max<std::size_t>(1, std::min(kMaxOrderBytes / 4, gl::BufferTexture::max_texels()) / rows);
}

std::unique_ptr<Backend> make_gl_backend() { return std::make_unique<GlTrainer>(); }

}  // namespace sn::nn
