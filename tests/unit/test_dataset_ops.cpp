// Dataset algebra (data/combine.h): exact row order, proportional counts, seeded choices that
// follow the documented algorithm, row filters, keys, and every refusal's message.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <numeric>
#include <set>

#include "data/combine.h"
#include "data/random.h"
#include "message_of.h"

namespace sn::data {
namespace {

// Row r of set s (0 train, 1 val) of dataset `tag`: x = {tag*1000 + s*100 + r, r/10, -r/10}
// (normal), y = {r, s, tag}: every value says where the row came from.
Dataset make(int tag, int train, int val, std::vector<std::string> names = {"normal"}) {
  Dataset d;
  d.inputs = 3;
  d.outputs = 3;
  d.input_names = std::move(names);
  d.key = "k" + std::to_string(tag);
  for (int s = 0; s < 2; ++s)
    for (int r = 0; r < (s ? val : train); ++r) {
      auto& x = s ? d.val_x : d.train_x;
      auto& y = s ? d.val_y : d.train_y;
      x.insert(x.end(), {float(tag * 1000 + s * 100 + r), float(r) / 10, -float(r) / 10});
      y.insert(y.end(), {float(r), float(s), float(tag)});
    }
  return d;
}

// The first input of every row of a set: the rows' identities.
std::vector<int> ids(const std::vector<float>& x, int width = 3) {
  std::vector<int> v;
  for (std::size_t i = 0; i < x.size(); i += width) v.push_back(int(x[i]));
  return v;
}

TEST(DatasetConcat, TrainingRowsInOrderThenValidationRows) {
  Dataset a = make(1, 3, 2), b = make(2, 2, 1);
  auto c = concat({&a, &b});
  EXPECT_EQ(ids(c->train_x), (std::vector<int>{1000, 1001, 1002, 2000, 2001}));
  EXPECT_EQ(ids(c->val_x), (std::vector<int>{1100, 1101, 2100}));
  EXPECT_EQ(c->train_y, (std::vector<float>{0, 0, 1, 1, 0, 1, 2, 0, 1, 0, 0, 2, 1, 0, 2}));
  EXPECT_EQ(c->val_y, (std::vector<float>{0, 1, 1, 1, 1, 1, 0, 1, 2}));
  EXPECT_EQ(c->input_names, std::vector<std::string>{"normal"});
  EXPECT_EQ(c->inputs, 3);
  EXPECT_EQ(c->outputs, 3);
}

TEST(DatasetConcat, KeyHashesThePartsKeysInOrder) {
  Dataset a = make(1, 2, 1), b = make(2, 2, 1);
  const std::string ab = concat({&a, &b})->key;
  EXPECT_EQ(ab.rfind("concat-", 0), 0u) << ab;
  EXPECT_EQ(ab, concat({&a, &b})->key);
  EXPECT_NE(ab, concat({&b, &a})->key);
  EXPECT_NE(ab, concat({&a, &a})->key);
  b.key.clear();  // unknown content: so is the concatenation's
  EXPECT_EQ(concat({&a, &b})->key, "");
}

TEST(DatasetConcat, NamesComeFromWhicheverPartHasThem) {
  Dataset a = make(1, 2, 1, {}), b = make(2, 2, 1);
  EXPECT_EQ(concat({&a, &b})->input_names, std::vector<std::string>{"normal"});
}

TEST(DatasetConcat, MismatchesNameThePositionAndWhatDiffers) {
  Dataset a = make(1, 2, 1), b = make(2, 2, 1), c = make(3, 2, 1);
  Dataset wide = make(4, 2, 1);
  wide.outputs = 1;
  wide.train_y.resize(2);
  wide.val_y.resize(1);
  EXPECT_EQ(message_of([&] { concat({&a, &b, &wide}); }), "dataset 3 has 1 outputs, dataset 1 has 3");
  Dataset hsv = make(5, 2, 1);
  hsv.color = shading::ColorSpace::hsv;
  EXPECT_EQ(message_of([&] { concat({&a, &hsv}); }), "dataset 2 has colour space hsv, dataset 1 has rgb");
  Dataset view = make(6, 2, 1, {"view"});
  Dataset unnamed = make(7, 2, 1, {});
  EXPECT_EQ(message_of([&] { concat({&unnamed, &a, &view}); }), "dataset 3 has inputs {view}, dataset 2 has {normal}");
  Dataset six = make(8, 0, 0, {"normal", "view"});
  six.inputs = 6;
  EXPECT_EQ(message_of([&] { concat({&a, &six}); }), "dataset 2 has 6 inputs, dataset 1 has 3");
  EXPECT_EQ(message_of([&] { concat({}); }), "no datasets to concatenate");
  (void)c;
}

TEST(DatasetSubset, CountTakesTheFirstRowsOfEachSetInProportion) {
  Dataset d = make(1, 8, 2);
  SubsetRequest r;
  r.count = 5;
  auto s = subset(d, r);
  EXPECT_EQ(ids(s->train_x), (std::vector<int>{1000, 1001, 1002, 1003}));
  EXPECT_EQ(ids(s->val_x), (std::vector<int>{1100}));
  EXPECT_EQ(s->train_y.size(), 12u);
}

TEST(DatasetSubset, CountsRoundAndKeepARowInEachSet) {
  auto counts = [](int train, int val, std::size_t count) {
    Dataset d = make(1, train, val);
    SubsetRequest r;
    r.count = count;
    auto s = subset(d, r);
    return std::pair{s->train_count(), s->val_count()};
  };
  EXPECT_EQ(counts(7, 3, 5), (std::pair<std::size_t, std::size_t>{4, 1}));   // 3.5 rounds up
  EXPECT_EQ(counts(99, 1, 10), (std::pair<std::size_t, std::size_t>{9, 1}));  // 9.9 -> 10, but val keeps one
  EXPECT_EQ(counts(1, 99, 10), (std::pair<std::size_t, std::size_t>{1, 9}));  // 0.1 -> 0, but train keeps one
  EXPECT_EQ(counts(5, 0, 3), (std::pair<std::size_t, std::size_t>{3, 0}));
  EXPECT_EQ(counts(8, 2, 10), (std::pair<std::size_t, std::size_t>{8, 2}));
  Dataset d = make(1, 8, 2);
  SubsetRequest r;
  r.count = 1;
  EXPECT_EQ(message_of([&] { subset(d, r); }),
            "count 1 cannot keep a row in both the training and the validation set (at least 2)");
  r.count = 11;
  EXPECT_EQ(message_of([&] { subset(d, r); }), "count 11 is more than the 10 rows");
}

TEST(DatasetSubset, FractionTakesThatShareOfEachSet) {
  Dataset d = make(1, 8, 2);
  SubsetRequest r;
  r.fraction = 0.5;
  auto s = subset(d, r);
  EXPECT_EQ(ids(s->train_x), (std::vector<int>{1000, 1001, 1002, 1003}));
  EXPECT_EQ(ids(s->val_x), (std::vector<int>{1100}));
  r.fraction = 0.01;
  s = subset(d, r);
  EXPECT_EQ(s->train_count(), 1u);
  EXPECT_EQ(s->val_count(), 1u);
  for (double bad : {0.0, 1.5, -0.1}) {
    r.fraction = bad;
    EXPECT_NE(message_of([&] { subset(d, r); }).find("fraction must lie in (0, 1]"), std::string::npos);
  }
  r.count = 3;
  r.fraction = 0.5;
  EXPECT_EQ(message_of([&] { subset(d, r); }), "give count or fraction, not both");
}

TEST(DatasetSubset, SeededChoiceIsAPartialFisherYatesPerSetInRowOrder) {
  Dataset d = make(1, 50, 20);
  SubsetRequest r;
  r.count = 14;  // 10 training, 4 validation rows
  r.seed = 7;
  auto s = subset(d, r);
  // The documented algorithm, written out: one SplitMix stream, training set first.
  SplitMix rng{7};
  std::vector<int> expect[2];
  for (int set = 0; set < 2; ++set) {
    std::vector<int> k((set ? 20 : 50));
    std::iota(k.begin(), k.end(), 1000 + set * 100);
    const std::size_t take = set ? 4 : 10;
    for (std::size_t i = 0; i < take; ++i) std::swap(k[i], k[i + rng.below(k.size() - i)]);
    k.resize(take);
    std::sort(k.begin(), k.end());
    expect[set] = k;
  }
  EXPECT_EQ(ids(s->train_x), expect[0]);
  EXPECT_EQ(ids(s->val_x), expect[1]);
  // Targets travel with their inputs.
  for (std::size_t i = 0; i < s->train_count(); ++i) EXPECT_EQ(s->train_y[i * 3], s->train_x[i * 3] - 1000);

  EXPECT_EQ(ids(subset(d, r)->train_x), expect[0]);  // the same seed, the same rows
  r.seed = 8;
  EXPECT_NE(ids(subset(d, r)->train_x), expect[0]);
  EXPECT_NE(ids(subset(d, r)->train_x), (std::vector<int>{1000, 1001, 1002, 1003, 1004, 1005, 1006, 1007, 1008, 1009}));
  const std::string k8 = subset(d, r)->key;
  r.seed = 7;
  EXPECT_NE(subset(d, r)->key, k8);
  EXPECT_EQ(subset(d, r)->key.rfind("subset-", 0), 0u);
}

TEST(DatasetSubset, WhereKeepsRowsWhoseComponentLiesInTheRange) {
  Dataset d = make(1, 10, 5);  // normal.y = r / 10
  SubsetRequest r;
  r.where = RowFilter{"normal", 1, 0.2, 0.35};
  auto s = subset(d, r);
  EXPECT_EQ(ids(s->train_x), (std::vector<int>{1002, 1003}));
  EXPECT_EQ(ids(s->val_x), (std::vector<int>{1102, 1103}));
  r.where = RowFilter{"normal", 2, -0.45, 0};  // normal.z = -r / 10, bounds included
  s = subset(d, r);
  EXPECT_EQ(ids(s->train_x), (std::vector<int>{1000, 1001, 1002, 1003, 1004}));
  // where first, then count of what it kept.
  r.count = 3;
  s = subset(d, r);
  EXPECT_EQ(ids(s->train_x), (std::vector<int>{1000, 1001}));
  EXPECT_EQ(ids(s->val_x), (std::vector<int>{1100}));
}

TEST(DatasetSubset, WhereRefusals) {
  Dataset d = make(1, 10, 5, {"uv", "normal"});
  d.inputs = 5;
  for (auto* x : {&d.train_x, &d.val_x}) {
    std::vector<float> wide;
    for (std::size_t i = 0; i < x->size(); i += 3) wide.insert(wide.end(), {(*x)[i], (*x)[i + 1], 0, 0, (*x)[i + 2]});
    *x = wide;
  }
  SubsetRequest r;
  r.where = RowFilter{"view", 0, 0, 1};
  EXPECT_EQ(message_of([&] { subset(d, r); }), "where: no input 'view' (the dataset's inputs: uv, normal)");
  r.where = RowFilter{"uv", 2, 0, 1};
  EXPECT_EQ(message_of([&] { subset(d, r); }), "where: input 'uv' has 2 components (u, v or 1..2), not component 3");
  r.where = RowFilter{"uv", 0, 1, 0};
  EXPECT_EQ(message_of([&] { subset(d, r); }), "where: min 1 is above max 0");
  r.where = RowFilter{"uv", 0, 1100, 2000};  // uv.u is the row id: only validation rows
  EXPECT_EQ(message_of([&] { subset(d, r); }), "where keeps no training rows (none of 10 has uv.u in [1100, 2000])");
  r.where = RowFilter{"uv", 0, 0, 1050};
  EXPECT_EQ(message_of([&] { subset(d, r); }), "where keeps no validation rows (none of 5 has uv.u in [0, 1050])");
  Dataset unnamed = make(2, 3, 1, {});
  r.where = RowFilter{"normal", 0, 0, 1};
  EXPECT_EQ(message_of([&] { subset(unnamed, r); }), "where: the dataset has no input names, so it has no input 'normal'");
  Dataset odd = make(3, 3, 1, {"normal", "view"});  // 2 names, 3 columns
  EXPECT_EQ(message_of([&] { subset(odd, r); }), "input names {normal, view} describe 6 columns, but the rows have 3 inputs");
}

TEST(DatasetSplit, PoolsTrainingThenValidationRowsAndPermutesLikeBuild) {
  Dataset d = make(1, 6, 4);
  auto s = resplit(d, 0.7, 3);
  ASSERT_EQ(s->train_count(), 7u);
  ASSERT_EQ(s->val_count(), 3u);
  std::vector<int> pool = {1000, 1001, 1002, 1003, 1004, 1005, 1100, 1101, 1102, 1103};
  SplitMix rng{3};
  std::vector<std::size_t> perm(pool.size());
  std::iota(perm.begin(), perm.end(), 0);
  for (std::size_t i = perm.size(); i > 1; --i) std::swap(perm[i - 1], perm[rng.below(i)]);
  std::vector<int> expect;
  for (std::size_t p : perm) expect.push_back(pool[p]);
  std::vector<int> got = ids(s->train_x), val = ids(s->val_x);
  got.insert(got.end(), val.begin(), val.end());
  EXPECT_EQ(got, expect);
  for (std::size_t i = 0; i < s->val_count(); ++i) EXPECT_EQ(s->val_y[i * 3 + 1], s->val_x[i * 3] >= 1100 ? 1 : 0);

  EXPECT_EQ(ids(resplit(d, 0.7, 3)->train_x), ids(s->train_x));
  EXPECT_NE(ids(resplit(d, 0.7, 4)->train_x), ids(s->train_x));
  EXPECT_NE(resplit(d, 0.7, 4)->key, s->key);
  EXPECT_EQ(s->key.rfind("split-", 0), 0u);
}

TEST(DatasetSplit, Refusals) {
  Dataset d = make(1, 1, 1);
  EXPECT_EQ(message_of([&] { resplit(d, 1.0, 1); }), "split must lie strictly between 0 and 1 (the training share), got 1");
  EXPECT_EQ(message_of([&] { resplit(d, 0.0, 1); }), "split must lie strictly between 0 and 1 (the training share), got 0");
  // Two rows split one of each, whatever the share (as every dataset splits; these were errors).
  EXPECT_EQ(resplit(d, 0.9, 1)->train_count(), 1u);
  EXPECT_EQ(resplit(d, 0.2, 1)->val_count(), 1u);
  Dataset one = make(1, 0, 1);
  EXPECT_EQ(message_of([&] { resplit(one, 0.5, 1); }), "1 row cannot be split into training and validation rows");
}

TEST(DatasetSplit, TrainRowsKeepsARowInEachSet) {
  EXPECT_EQ(train_rows(0.8, 2), 1u);
  EXPECT_EQ(train_rows(0.1, 2), 1u);
  EXPECT_EQ(train_rows(0.95, 10), 9u);
  EXPECT_EQ(train_rows(0.8, 64149), 51319u);  // the thesis' rows: round(0.8 n), as before
  EXPECT_EQ(train_rows(1.0, 5), 5u);          // sn.dataset's split = 1: no validation rows
  EXPECT_EQ(train_rows(0.5, 1), 1u);
}

}  // namespace
}  // namespace sn::data
