// Fuzz target: sn.dataset.load (data/dataset_file.h). An input in three parts (sidecar JSON,
// inputs .npy, targets .npy; see fuzz_input.h) is a NumPy dataset, any other input a CSV file.
#include <exception>

#include "data/dataset_file.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  std::vector<std::string> parts = sn::fuzz::split_parts(data, size);
  std::string path;
  if (parts.size() == 3) {
    path = sn::fuzz::scratch_file("input.json", parts[0].data(), parts[0].size());
    sn::fuzz::scratch_file("input.inputs.npy", parts[1].data(), parts[1].size());
    sn::fuzz::scratch_file("input.targets.npy", parts[2].data(), parts[2].size());
  } else {
    path = sn::fuzz::scratch_file("input.csv", data, size);
  }
  try {
    auto d = sn::data::load_dataset(path);
    // Every row a trainer may read must be there, inputs and targets alike.
    const sn::data::Dataset& s = *d;
    bool whole = s.inputs > 0 && s.outputs > 0 && s.train_x.size() % s.inputs == 0 &&
                 s.val_x.size() % s.inputs == 0 && s.train_y.size() == s.train_count() * s.outputs &&
                 s.val_y.size() == s.val_count() * s.outputs;
    if (!whole) __builtin_trap();
  } catch (const std::exception&) {
  }
  return 0;
}
