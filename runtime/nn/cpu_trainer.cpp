#include "nn/cpu_trainer.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <string>

#include "nn/cpu_net.h"
#include "nn/encoding_define.h"
#include "io/parallel.h"
#include "nn/shuffle.h"

namespace sn::nn {

namespace {

std::string cpu_model() {
  std::ifstream f("/proc/cpuinfo");
  for (std::string line; std::getline(f, line);)
    if (line.rfind("model name", 0) == 0) {
      auto colon = line.find(':');
      if (colon != std::string::npos) return line.substr(line.find_first_not_of(' ', colon + 1));
    }
  return "unknown cpu";
}

// A dataset's training and validation rows under one set of input encodings (nn/encoding.h),
// encoded in double and rounded to float once per run: (train + val rows) x encoded width x 4
// bytes for each distinct set of encodings among the run's networks.
struct EncodedRows {
  std::vector<InputEncoding> encodings;
  const float *train = nullptr, *val = nullptr;
  std::vector<float> train_rows, val_rows;
};

std::unique_ptr<EncodedRows> encode_data(const std::vector<InputEncoding>& encs, const data::Dataset& d, int threads) {
  auto r = std::make_unique<EncodedRows>();
  r->encodings = encs;
  const std::size_t w = std::size_t(encoded_width(encs, d.inputs));
  r->train_rows.resize(d.train_count() * w);
  r->val_rows.resize(d.val_count() * w);
  // In blocks of rows over the machine's threads (sin, cos, erfc per value add up).
  constexpr std::size_t kBlock = 4096;
  const std::size_t nt = (d.train_count() + kBlock - 1) / kBlock, nv = (d.val_count() + kBlock - 1) / kBlock;
  // A user's encoding (a Lua function) runs on this thread alone.
  io::parallel_for(int(nt + nv), single_threaded(encs) ? 1 : threads, [&](int b) {
    const bool train = std::size_t(b) < nt;
    const std::size_t first = (train ? std::size_t(b) : std::size_t(b) - nt) * kBlock;
    const std::size_t count = std::min(kBlock, (train ? d.train_count() : d.val_count()) - first);
    const float* x = (train ? d.train_x.data() : d.val_x.data()) + first * std::size_t(d.inputs);
    float* out = (train ? r->train_rows.data() : r->val_rows.data()) + first * w;
    encode_rows(encs, d.inputs, x, count, out);
  });
  // A user's twin against its GLSL on every row this backend trains on (the definition checked
  // sample inputs only); built-ins are held to theirs by the tests.
  check_on_rows(encs, d.inputs, d.train_x.data(), r->train_rows.data(), d.train_count(), "training row");
  check_on_rows(encs, d.inputs, d.val_x.data(), r->val_rows.data(), d.val_count(), "validation row");
  r->train = r->train_rows.data();
  r->val = r->val_rows.data();
  return r;
}

// A net's minibatches of one epoch, packed for the kernel (nn/cpu_net.h pack_minibatch): the
// epoch's packed minibatches it shares with other nets, or its own, packed a chunk of steps at a
// time from its order of the rows.
class Minibatches {
 public:
  Minibatches(const float* shared, const float* x, const float* y, int inputs, int outputs, const uint32_t* order,
              int batch, long long steps)
      : shared_(shared), x_(x), y_(y), in_(inputs), out_(outputs), order_(order), batch_(batch), steps_(steps),
        floats_(minibatch_floats(batch, inputs, outputs)) {}
  // Step s's minibatch; valid until the next call.
  const float* at(long long s) {
    if (shared_) return shared_ + std::size_t(s) * floats_;
    if (s < first_ || s >= first_ + kChunk) {
      first_ = s;
      own_.resize(std::size_t(kChunk) * floats_);
      for (long long k = 0; k < kChunk && s + k < steps_; ++k)
        pack_minibatch(x_, y_, in_, out_, order_ + (s + k) * batch_, batch_, own_.data() + std::size_t(k) * floats_);
    }
    return own_.data() + std::size_t(s - first_) * floats_;
  }

 private:
  static constexpr long long kChunk = 32;
  const float *shared_, *x_, *y_;
  int in_, out_;
  const uint32_t* order_;
  int batch_;
  long long steps_;
  std::size_t floats_;
  long long first_ = -kChunk;
  std::vector<float> own_;
};

// Every net's rows, epoch by epoch: its seed's shuffle, and its minibatches packed for the
// kernel. A step that gathered its own rows cost more (a float at a time, read back at once as
// vectors; docs/performance.md). The nets of one seed that read the same rows (a group: a
// sweep's architectures) share one packed epoch, while the job's packed epochs fit in
// `shared_bytes`; beyond that each net packs its own. Two epochs are held, so that the next
// one is prepared (a task per seed) while this one trains.
class EpochRows {
 public:
  // The default bound: Table 4.1's packed epochs (10 seeds) take 37 MB.
  static constexpr std::size_t kSharedBytes = std::size_t(256) << 20;
  EpochRows(const std::vector<uint32_t>& seed_of, const std::vector<const EncodedRows*>& rows_of,
            const std::vector<int>& inputs_of, const data::Dataset& d, int batch, std::size_t shared_bytes)
      : d_(d), batch_(batch), steps_(d.train_count() / std::size_t(batch)), net_group_(seed_of.size()) {
    std::size_t bytes = 0;
    for (std::size_t i = 0; i < seed_of.size(); ++i) {
      std::size_t j = std::size_t(std::find(seeds_.begin(), seeds_.end(), seed_of[i]) - seeds_.begin());
      if (j == seeds_.size()) seeds_.push_back(seed_of[i]);
      std::size_t g = 0;
      while (g < groups_.size() && (groups_[g].rows != rows_of[i] || groups_[g].seed != j)) ++g;
      if (g == groups_.size()) {
        groups_.push_back({rows_of[i], j, inputs_of[i], {}});
        bytes += 2 * std::size_t(steps_) * minibatch_floats(batch, inputs_of[i], d.outputs) * sizeof(float);
      }
      net_group_[i] = g;
    }
    shared_ = bytes <= shared_bytes;
    for (auto& o : orders_) o.assign(seeds_.size(), std::vector<uint32_t>(std::size_t(steps_) * std::size_t(batch)));
  }
  long long steps() const { return steps_; }
  int tasks() const { return int(seeds_.size()); }
  // Task j of epoch e (0-based): seed j's order of the rows, and its groups' packed minibatches.
  void prepare(int e, int j) {
    std::vector<uint32_t>& order = orders_[e & 1][std::size_t(j)];
    EpochShuffle perm(seeds_[std::size_t(j)], uint32_t(e), uint32_t(d_.train_count()));
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = perm(uint32_t(k));
    if (!shared_) return;
    for (Group& g : groups_) {
      if (g.seed != std::size_t(j)) continue;
      const std::size_t f = minibatch_floats(batch_, g.inputs, d_.outputs);
      std::vector<float>& packed = g.packed[e & 1];
      packed.resize(std::size_t(steps_) * f);
      for (long long s = 0; s < steps_; ++s)
        pack_minibatch(g.rows->train, d_.train_y.data(), g.inputs, d_.outputs, order.data() + s * batch_, batch_,
                       packed.data() + std::size_t(s) * f);
    }
  }
  // Net i's minibatches of epoch e, once prepare(e, its seed) has run.
  Minibatches minibatches(int i, int e) const {
    const Group& g = groups_[net_group_[std::size_t(i)]];
    return Minibatches(shared_ ? g.packed[e & 1].data() : nullptr, g.rows->train, d_.train_y.data(), g.inputs,
                       d_.outputs, orders_[e & 1][g.seed].data(), batch_, steps_);
  }

 private:
  struct Group {
    const EncodedRows* rows;
    std::size_t seed;  // index into seeds_
    int inputs;        // floats per row of rows->train
    std::vector<float> packed[2];
  };
  const data::Dataset& d_;
  int batch_;
  long long steps_;
  std::vector<uint32_t> seeds_;
  std::vector<Group> groups_;
  std::vector<std::size_t> net_group_;
  bool shared_ = false;
  std::vector<std::vector<uint32_t>> orders_[2];  // per epoch parity, per seed
};

// What one task of an epoch trains: a net alone, or two in lock-step (nn/cpu_net.h CpuNetPair).
struct Unit {
  int net[2] = {-1, -1};
  std::unique_ptr<CpuNetPair> pair;
};

// Pairs nets of one architecture and loss (each on its own minibatches) where the kernel has
// the pair mode, as long as every thread still gets a unit: two nets on two threads train
// faster apart.
std::vector<Unit> plan_units(const std::vector<std::unique_ptr<CpuNet>>& work,
                             const std::vector<const EncodedRows*>& rows_of, int threads) {
  const int count = int(work.size());
  int pairs_left = CpuNetPair::available() ? std::max(0, std::min(count / 2, count - threads)) : 0;
  std::vector<char> used(std::size_t(count), 0);
  std::vector<Unit> units;
  for (int i = 0; i < count; ++i) {
    if (used[i]) continue;
    Unit u;
    u.net[0] = i;
    for (int j = i + 1; j < count && pairs_left > 0; ++j)
      if (!used[j] && rows_of[i] == rows_of[j] && CpuNetPair::can_pair(*work[i], *work[j])) {
        u.net[1] = j;
        u.pair = std::make_unique<CpuNetPair>(*work[i], *work[j]);
        used[j] = 1;
        --pairs_left;
        break;
      }
    units.push_back(std::move(u));
  }
  // Largest first: the threads take units in this order, and a large one taken last would leave
  // the other threads idle at every epoch's end (a sweep lists its small networks first).
  std::stable_sort(units.begin(), units.end(), [&](const Unit& a, const Unit& b) {
    return work[a.net[0]]->spec().param_count() > work[b.net[0]]->spec().param_count();
  });
  return units;
}

class CpuBackend : public Backend {
 public:
  CpuBackend(int threads, std::size_t shared_bytes)
      : threads_(threads > 0 ? threads : io::default_threads()), shared_bytes_(shared_bytes) {}

  std::string name() const override { return "cpu"; }
  std::size_t seeds_per_call(std::size_t) const override { return SIZE_MAX; }  // one job: pairs form across seeds
  std::string device() const override {
    return cpu_model() + ", " + std::to_string(threads_) + " threads, " + cpu_kernel_name() + " kernel";
  }

  std::vector<NetResult> train(const std::vector<const Mlp*>& nets, const data::Dataset& data, const TrainConfig& cfg,
                               const Progress& progress) override {
    const int count = int(nets.size());
    std::vector<std::unique_ptr<CpuNet>> work(static_cast<std::size_t>(count));
    std::vector<NetResult> results(static_cast<std::size_t>(count));
    // Rows as each net's first layer reads them: the dataset's own, or encoded once per distinct
    // set of input encodings for the whole run.
    std::vector<const EncodedRows*> rows_of(static_cast<std::size_t>(count));
    std::vector<std::unique_ptr<EncodedRows>> encoded;
    const EncodedRows plain{{}, data.train_x.data(), data.val_x.data(), {}, {}};
    for (int i = 0; i < count; ++i) {
      const auto& encs = nets[i]->spec.encodings;
      const EncodedRows* r = &plain;
      if (!encs.empty()) {
        r = nullptr;
        for (const auto& e : encoded)
          if (e->encodings == encs) r = e.get();
        if (!r) r = encoded.emplace_back(encode_data(encs, data, threads_)).get();
      }
      rows_of[i] = r;
    }
    io::parallel_for(count, threads_, [&](int i) {
      work[i] = std::make_unique<CpuNet>(nets[i]->spec, nets[i]->params.data());
      work[i]->set_loss(cfg.loss);
      const double given = cfg.initial_val_mse_of(std::size_t(i));
      results[i].initial_val_mse =
          std::isnan(given) ? work[i]->mse(rows_of[i]->val, data.val_y.data(), data.val_count()) : given;
      work[i]->set_sample_limit(cfg.divergence.sample_limit(results[i].initial_val_mse, nets[i]->spec.outputs));
    });

    std::vector<Unit> units = plan_units(work, rows_of, threads_);

    std::vector<uint32_t> seed_of(static_cast<std::size_t>(count));
    std::vector<int> inputs_of(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) seed_of[i] = cfg.seed_of(std::size_t(i)), inputs_of[i] = nets[i]->spec.width(0);
    EpochRows rows(seed_of, rows_of, inputs_of, data, cfg.batch, shared_bytes_);
    const long long steps = rows.steps();
    if (cfg.epochs > 0) io::parallel_for(rows.tasks(), threads_, [&](int j) { rows.prepare(0, j); });
    std::vector<AdamStep> adam(static_cast<std::size_t>(steps));
    long long t = 0;  // Adam's step counter, the same for every net of the run
    io::WatchBeat beat(cfg.tick ? cfg.tick_seconds : 1.0);  // the tick's, across epochs
    for (int e = 0; e < cfg.epochs; ++e) {
      if (cfg.stop_requested()) break;
      for (long long s = 0; s < steps; ++s) adam[std::size_t(s)] = AdamStep::at(cfg, ++t);

      std::vector<char> finished(static_cast<std::size_t>(count), 0);
      // Steps each net has applied in this epoch, for the tick (-1: not training this epoch).
      std::vector<std::atomic<long long>> applied(static_cast<std::size_t>(count));
      for (int i = 0; i < count; ++i) applied[i] = results[i].diverged ? -1 : 0;
      // Net i's step s of this epoch; false when refused (the net has diverged).
      auto take = [&](int i, long long s, bool ok, double loss, DivergenceKind why, double& sum) {
        NetResult& r = results[i];
        if (!ok) {
          r.diverged = Divergence{e + 1, s + 1, why};
          applied[i] = steps;
          return false;
        }
        sum += loss;
        ++r.steps;
        applied[i].store(s + 1, std::memory_order_relaxed);
        return true;
      };
      auto interrupt = [&](int i, long long s) {
        results[i].interrupted = StopPoint{e + 1, s};
        applied[i] = steps;
      };
      auto end_epoch = [&](int i, double sum) {
        CpuNet& net = *work[i];
        const double val = net.mse(rows_of[i]->val, data.val_y.data(), data.val_count());
        const double val_loss =
            cfg.loss.kind == LossKind::l2 ? val : net.mean_loss(rows_of[i]->val, data.val_y.data(), data.val_count());
        std::vector<float> p(net.spec().param_count());
        net.get_params(p.data());
        results[i].end_epoch(cfg, steps, sum / double(steps), val, val_loss, p.data(), p.size());
        finished[i] = 1;
      };
      // Net i alone from step `from` on, with the epoch's loss sum so far.
      auto train_alone = [&](int i, long long from, double sum) {
        CpuNet& net = *work[i];
        Minibatches mb = rows.minibatches(i, e);
        for (long long s = from; s < steps; ++s) {
          if (cfg.stop_requested()) return interrupt(i, s);
          double loss;
          DivergenceKind why = DivergenceKind::nonfinite;
          const bool ok = net.step(mb.at(s), cfg.batch, adam[std::size_t(s)], &loss, &why);
          if (!take(i, s, ok, loss, why, sum)) return;
        }
        end_epoch(i, sum);
      };
      auto train_epoch = [&](int u) {
        Unit& unit = units[std::size_t(u)];
        if (!unit.pair) {
          if (!results[unit.net[0]].diverged) train_alone(unit.net[0], 0, 0.0);
          return;
        }
        double sum[2] = {0, 0};
        Minibatches mb[2] = {rows.minibatches(unit.net[0], e), rows.minibatches(unit.net[1], e)};
        for (long long s = 0; s < steps; ++s) {
          if (cfg.stop_requested()) {
            for (int h = 0; h < 2; ++h) unit.pair->get(h, *work[unit.net[h]]), interrupt(unit.net[h], s);
            return;
          }
          double loss[2];
          bool ok[2];
          DivergenceKind why[2] = {DivergenceKind::nonfinite, DivergenceKind::nonfinite};
          const float* both[2] = {mb[0].at(s), mb[1].at(s)};
          if (!unit.pair->step(both, cfg.batch, adam[std::size_t(s)], loss, ok, why)) {
            // A net diverged: the pair splits, and the other one goes on alone.
            for (int h = 0; h < 2; ++h) unit.pair->get(h, *work[unit.net[h]], ok[h]);
            unit.pair.reset();
            int alone = -1;
            for (int h = 0; h < 2; ++h)
              if (take(unit.net[h], s, ok[h], loss[h], why[h], sum[h])) alone = h;
            if (alone >= 0) {
              unit.net[0] = unit.net[alone];
              train_alone(unit.net[0], s + 1, sum[alone]);
            }
            return;
          }
          for (int h = 0; h < 2; ++h) take(unit.net[h], s, true, loss[h], why[h], sum[h]);
        }
        for (int h = 0; h < 2; ++h) unit.pair->get(h, *work[unit.net[h]]), end_epoch(unit.net[h], sum[h]);
      };
      // The units, then the next epoch's rows (on threads the units leave idle, or last).
      const int next = e + 1 < cfg.epochs ? rows.tasks() : 0, tasks = int(units.size()) + next;
      auto task = [&](int u) {
        if (u < int(units.size())) train_epoch(u);
        else rows.prepare(e + 1, u - int(units.size()));
      };
      if (cfg.tick) {
        // The nets train on threads of their own; this thread ticks.
        io::parallel_for_watched(tasks, threads_, beat, task, [&] {
          long long sum = 0, nets = 0;
          for (const auto& a : applied)
            if (long long v = a.load(std::memory_order_relaxed); v >= 0) sum += v, ++nets;
          cfg.tick(TickEvent{e + 1, cfg.epochs, nets ? sum / nets : steps, steps});
        });
      } else {
        io::parallel_for(tasks, threads_, task);
      }
      if (progress)
        for (int i = 0; i < count; ++i)
          if (finished[i]) {
            std::vector<float> p(work[i]->spec().param_count());
            work[i]->get_params(p.data());
            progress({i, e + 1, results[i].train_loss.back(), results[i].val_mse.back(), results[i].val_loss.back(), &p});
          }
    }
    // Stopped between epochs: every net still training ends after its last finished epoch.
    if (cfg.stop_requested())
      for (NetResult& r : results)
        if (!r.diverged && !r.interrupted && r.epochs_done() < cfg.epochs) r.interrupted = StopPoint{r.epochs_done() + 1, 0};
    for (int i = 0; i < count; ++i) {
      results[i].final_params.resize(nets[i]->spec.param_count());
      work[i]->get_params(results[i].final_params.data());
    }
    return results;
  }

 private:
  int threads_;
  std::size_t shared_bytes_;
};

}  // namespace

std::unique_ptr<Backend> make_cpu_backend(int threads, std::size_t shared_bytes) {
  return std::make_unique<CpuBackend>(threads, shared_bytes);
}
std::unique_ptr<Backend> make_cpu_backend(int threads) { return make_cpu_backend(threads, EpochRows::kSharedBytes); }
std::unique_ptr<Backend> make_cpu_backend() { return make_cpu_backend(0); }

}  // namespace sn::nn
