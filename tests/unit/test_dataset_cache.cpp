// The dataset cache is bounded by count and by bytes: it held 16 datasets of any size after the
// script had dropped them (16 of 2^24 rows, ~9.6 GB).
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "data/dataset_cache.h"
#include "io/limits.h"

namespace sn::data {
namespace {

std::shared_ptr<Dataset> rows_of(std::size_t bytes) {
  auto d = std::make_shared<Dataset>();
  d->inputs = 1, d->outputs = 1;
  d->train_x.resize(bytes / sizeof(float) / 2);
  d->train_y.resize(bytes / sizeof(float) / 2);
  return d;
}

TEST(DatasetCache, HoldsAtMostItsCountOfSmallDatasets) {
  clear_dataset_cache();
  for (int i = 0; i < 20; ++i) cached("test-small " + std::to_string(i), [] { return rows_of(1024); });
  EXPECT_EQ(dataset_stats().cached, kDatasetCacheCapacity);
  // The most recent ones stay: the 20th is answered from the cache, the 1st is built again.
  const auto builds = dataset_stats().builds;
  cached("test-small 19", [] { return rows_of(1024); });
  EXPECT_EQ(dataset_stats().builds, builds);
  cached("test-small 0", [] { return rows_of(1024); });
  EXPECT_EQ(dataset_stats().builds, builds + 1);
  clear_dataset_cache();
}

TEST(DatasetCache, HoldsAtMostItsBytesOfLargeDatasets) {
  clear_dataset_cache();
  const io::Limits was = io::limits();
  io::Limits small = was;
  small.dataset_cache_bytes = 1 << 20;
  io::set_limits(small);
  const std::size_t big = (1 << 20) / 5 * 2;  // two fit, three do not
  for (int i = 0; i < 3; ++i) cached("test-big " + std::to_string(i), [&] { return rows_of(big); });
  EXPECT_EQ(dataset_stats().cached, 2u);
  // One larger than the bound alone is still kept: it was just built and is about to be used.
  auto huge = cached("test-huge", [&] { return rows_of((1 << 20) + 1024); });
  EXPECT_EQ(dataset_stats().cached, 1u);
  EXPECT_EQ(dataset_bytes(*huge), std::size_t(1 << 20) + 1024);
  io::set_limits(was);
  clear_dataset_cache();
}

}  // namespace
}  // namespace sn::data
