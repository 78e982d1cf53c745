// Datasets as files other tools read: NumPy arrays with a JSON sidecar, or CSV for small sets.
// docs/lua-api/datasets.md ("Combining, saving and loading") describes both formats.
//
//   NumPy  <stem>.json          the sidecar: widths, rows per set, colour space, input names
//          <stem>.inputs.npy    (rows, inputs)  float32, training rows first, then validation
//          <stem>.targets.npy   (rows, outputs) float32, same order
//   CSV    one header line (normal_x,...,r,g,b,set), one line per row, set = train | val
//
// Loading checks everything (shapes, dtype, sizes, fields, finite values) and names the file.
#pragma once
#include <memory>
#include <string>

#include "data/dataset.h"

namespace sn::data {

enum class DatasetFormat { numpy, csv };

struct DatasetPaths {
  DatasetFormat format = DatasetFormat::numpy;
  std::string main;              // what load_dataset takes: the sidecar or the CSV file
  std::string inputs, targets;   // the arrays (numpy only)
};

// The files a path names: ".json" or no extension -> numpy (the sidecar gets ".json"), ".csv"
// -> CSV; throws for any other extension.
DatasetPaths dataset_paths(const std::string& path);

// Writes the dataset; returns the paths written. Every file is written atomically and the
// sidecar last, after any old sidecar at that path was removed: a failed or interrupted export
// never leaves a sidecar over missing or mismatched arrays. A sidecar path that is a symbolic
// link is written where it leads, the arrays beside that sidecar and named after it (the link
// stays; main is the path given, which loads it).
DatasetPaths export_dataset(const Dataset& d, const std::string& path);

// Reads what export_dataset wrote (or a sidecar and arrays made elsewhere, e.g. with numpy).
// The arrays are looked for beside the sidecar, through links: beside the file a linked sidecar
// path leads to.
// The dataset's key is a hash of its content (the same rows give the same key however they
// were stored); the sidecar's "source_key" is the key of the dataset that was exported.
std::shared_ptr<Dataset> load_dataset(const std::string& path);

// The CSV header line of a dataset (without '\n'); throws when the input names cannot be column
// names (names that are not G-buffer attributes: the NumPy format keeps any names).
std::string csv_header(const Dataset& d);

}  // namespace sn::data
