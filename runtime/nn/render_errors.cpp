#include "nn/render_errors.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "io/figure.h"
#include "io/parallel.h"
#include "io/ssim.h"
#include "nn/cpu_render.h"
#include "nn/render.h"
#include "nn/render_inputs.h"

namespace sn::nn {

namespace {

// The error of one render, clamped here, against its truth (`reference`: the truth's part of
// the SSIM, prepared once per view). A NaN or infinite pixel makes both NaN: the pair cannot be
// scored, its `nonfinite` count says why, and the other pairs still are. (Clamping would score
// an infinity as 1, and an overflow that gives the cpu kernels an infinity may give the
// fragment shader NaN: one network, two scores.)
RenderError score(io::Image&& mine, const io::Image& truth, const io::SsimReference& reference, std::size_t nonfinite) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  if (nonfinite) return {nan, nan, nonfinite};
  const io::Image shown = io::clamp_colors(std::move(mine));
  return {io::mse(truth, shown, 3, &truth), io::ssim(reference, shown), nonfinite};
}

}  // namespace

std::vector<RenderError> render_errors(const std::vector<std::shared_ptr<const Mlp>>& nets,
                                       const std::vector<TruthView>& views) {
  const std::size_t nv = views.size();
  for (std::size_t k = 0; k < nv; ++k) {
    const TruthView& v = views[k];
    if (!v.gbuffer || !v.truth) throw std::invalid_argument("render_errors: view " + std::to_string(k + 1) + " lacks its G-buffer or truth");
    if (v.truth->channels != 4 || v.truth->width != v.gbuffer->width || v.truth->height != v.gbuffer->height)
      throw std::invalid_argument("render_errors: view " + std::to_string(k + 1) + "'s truth is " +
                                  std::to_string(v.truth->width) + "x" + std::to_string(v.truth->height) + "x" +
                                  std::to_string(v.truth->channels) + "; RGBA of the G-buffer's " +
                                  std::to_string(v.gbuffer->width) + "x" + std::to_string(v.gbuffer->height) + " expected");
  }
  std::vector<RenderInputs> inputs(nets.size() * nv);
  std::vector<char> on_cpu(nets.size());
  for (std::size_t i = 0; i < nets.size(); ++i) {
    if (!nets[i]) throw std::invalid_argument("render_errors: network " + std::to_string(i + 1) + " is missing");
    for (std::size_t k = 0; k < nv; ++k) inputs[i * nv + k] = render_inputs(*nets[i], *views[k].gbuffer);
    on_cpu[i] = choose_render_backend(*nets[i], {}, nullptr) == RenderBackend::cpu;
  }
  std::vector<RenderError> errors(nets.size() * nv);
  if (nets.empty()) return errors;
  // Over the truth's covered pixels (its alpha), in its colour channels.
  std::vector<io::SsimReference> references;
  for (const TruthView& v : views) references.push_back(io::ssim_reference(*v.truth, 3, v.truth));

  // Every attachment a cpu network reads, read back once per view, and its covered pixels'
  // inputs gathered once for each way of reading them (covered[gathered[at]]).
  std::vector<GBufferTexels> texels(nv);
  std::vector<std::size_t> cpu_units;  // i * nv + k
  std::vector<CoveredInputs> covered;
  std::vector<std::size_t> gathered(nets.size() * nv);
  for (std::size_t k = 0; k < nv; ++k) {
    std::vector<std::string> read;
    for (std::size_t i = 0; i < nets.size(); ++i) {
      if (!on_cpu[i]) continue;
      cpu_units.push_back(i * nv + k);
      for (const auto& a : inputs[i * nv + k].attributes)
        if (std::find(read.begin(), read.end(), a) == read.end()) read.push_back(a);
    }
    read_gbuffer(*views[k].gbuffer, read, texels[k]);
    std::vector<std::size_t> readers;  // the first unit of each way, i * nv + k
    for (std::size_t i = 0; i < nets.size(); ++i) {
      if (!on_cpu[i]) continue;
      const std::size_t at = i * nv + k;
      std::size_t r = 0;
      while (r < readers.size() && !same_inputs(nets[readers[r] / nv]->spec, inputs[readers[r]], nets[i]->spec, inputs[at])) ++r;
      if (r == readers.size()) {
        readers.push_back(at);
        gathered[at] = covered.size();
        covered.push_back(covered_inputs(nets[i]->spec, *views[k].gbuffer, texels[k], inputs[at]));
      } else {
        gathered[at] = gathered[readers[r]];
      }
    }
  }
  io::parallel_for(int(cpu_units.size()), io::default_threads(), [&](int u) {
    const std::size_t at = cpu_units[std::size_t(u)], i = at / nv, k = at % nv;
    io::Image mine;
    const std::size_t bad = cpu_render(*nets[i], *views[k].gbuffer, covered[gathered[at]], mine);
    errors[at] = score(std::move(mine), *views[k].truth, references[k], bad);
  });

  // gl networks draw on this thread, one at a time; their views are scored on the threads.
  for (std::size_t i = 0; i < nets.size(); ++i) {
    if (on_cpu[i]) continue;
    std::vector<Rendered> drawn(nv);
    for (std::size_t k = 0; k < nv; ++k) drawn[k] = render_network(nets[i], *views[k].gbuffer);
    io::parallel_for(int(nv), io::default_threads(), [&](int k) {
      errors[i * nv + std::size_t(k)] = score(std::move(drawn[std::size_t(k)].image), *views[std::size_t(k)].truth,
                                              references[std::size_t(k)], drawn[std::size_t(k)].nonfinite);
    });
  }
  return errors;
}

}  // namespace sn::nn
