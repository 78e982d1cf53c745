// What part of the input domain a dataset covers. A network trained on (normal, view) rows only
// learns the directions it saw (the hanging cloth has no normal with y above 0.40), so datasets
// are binned on the sphere of normals and the hemisphere of views, and any other set of rows (a
// dataset, a scene's covered pixels) can be measured against those bins.
//
// The bin scheme (docs/lua-api/datasets.md, "Coverage", says the same):
//   normal n (normalised): bands uniform in y = cos(theta), theta from world +y, band b holding
//     y in [-1 + 2b/B, -1 + 2(b+1)/B) (the last band also holds y = 1) x sectors uniform in
//     phi = atan2(z, x) taken in [0, 2pi), sector s holding phi in [2pi s/S, 2pi (s+1)/S).
//     Bin index b * S + s. Equal area (Archimedes): every bin is 4pi / (B S) sr; 16 x 32 = 512.
//   view v (normalised), in the normal's frame, only where n.v > 0: bands uniform in
//     cos(theta_v) = n.v over (0, 1], band k holding n.v in [k/B, (k+1)/B) (the last also 1) x
//     azimuth psi = atan2(v.b, v.t) in [0, 2pi), t = world +y projected onto the tangent plane
//     (world +z when |n.x|, |n.z| leave no direction: sqrt(x^2 + z^2) < 1e-6), b = n x t.
//     Every bin is 2pi / (B S) sr; 8 x 32 = 256.
// Rows whose normal or view is zero or not finite are `invalid`: in no bin. Rows with n.v <= 0
// (views at or below the tangent plane, e.g. interpolated normals at silhouettes) have a normal
// bin and are counted `below_horizon`, with no view bin. A bin is covered when it holds at least
// min_count rows.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "data/dataset.h"
#include "io/image.h"
#include "scene/scene.h"

namespace sn::data {

struct BinScheme {
  int normal_bands = 16, normal_sectors = 32;
  int view_bands = 8, view_sectors = 32;

  int normal_bins() const { return normal_bands * normal_sectors; }
  int view_bins() const { return view_bands * view_sectors; }
  // Throws unless every count is in 1..kMaxDivisions.
  void check() const;
  // One line naming the scheme, e.g. for a result table.
  std::string text() const;
};
constexpr int kMaxDivisions = 1024;

// Bin of a normal (any length; -1 when zero or not finite).
int normal_bin(const BinScheme& s, double nx, double ny, double nz);
// View bin of (n, v) (any lengths; -1 when either is zero or not finite, or n.v <= 0).
int view_bin(const BinScheme& s, const double n[3], const double v[3]);
// Solid angle of one bin, which is the same for every bin of a set (equal area).
double normal_bin_solid_angle(const BinScheme& s);
double view_bin_solid_angle(const BinScheme& s);

// Rows of (normal, view) pairs in memory: row i's normal is normal[i * stride + 0..2], its view
// view[i * stride + 0..2].
struct DirectionRows {
  const float* normal = nullptr;
  const float* view = nullptr;
  std::size_t stride = 0, rows = 0;
};

// A dataset's training and validation rows, read where its inputs "normal" and "view" sit.
// Throws naming the dataset's inputs when it has no such inputs 3 wide; `what` starts the message.
std::vector<DirectionRows> dataset_directions(const Dataset& d, const std::string& what);

// Every covered pixel of every view in every pose of a scene as 6 floats (normal, view), from G-buffers
// gathered on the GPU (no lighting is evaluated).
std::vector<float> scene_directions(const scene::Scene& s);

struct Histogram {
  BinScheme scheme;
  std::vector<uint32_t> normal, view;  // rows per bin
  std::size_t rows = 0;                // every row looked at
  std::size_t invalid = 0;             // zero or non-finite normal or view: in no bin
  std::size_t below_horizon = 0;       // n.v <= 0: a normal bin, no view bin
  std::size_t non_unit = 0;            // normal or view length off 1 by more than 1e-3 (binned by direction)
  double normal_y_min = 0, normal_y_max = 0;  // of the valid rows' normalised normals
};

// Throws when there are no rows at all.
Histogram histogram(const std::vector<DirectionRows>& rows, const BinScheme& scheme);

// Bins holding at least min_count rows (min_count >= 1).
std::size_t covered_bins(const std::vector<uint32_t>& counts, int min_count);

// Share of `other`'s valid rows that fall where `mine` is not covered: the normal's bin, the view's
// bin (a view below the horizon counts as outside unless `mine` has min_count such rows), either.
struct Outside {
  std::size_t rows = 0;  // other's valid rows: the denominator
  double normal = 0, view = 0, either = 0;
};
// Throws when `other` has no valid row.
Outside outside(const Histogram& mine, int min_count, const std::vector<DirectionRows>& other);

struct CoverageFigure {
  std::string title;
  std::string against;  // what `other` is, for the legend ("the scene (sphere)"); empty = no other
  int min_count = 1;
};
// Both maps side by side: the normal sphere (phi across, y = cos(theta) up) and the view
// hemisphere (psi across, cos(theta_v) up), on one scale so equal page areas are equal solid
// angles; covered bins coloured by row count (log), uncovered grey, and where `other` (may be
// null) has rows in a bin `mine` does not cover, red. A colour bar, axis labels and a legend.
io::Image coverage_figure(const Histogram& mine, const Histogram* other, const CoverageFigure& f);

}  // namespace sn::data
