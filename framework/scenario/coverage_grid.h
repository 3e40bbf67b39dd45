// The coverage grid of the random instance generator (random_instance.cpp): which cells of a
// grid over the workspace have their centre inside some obstacle, so that a new obstacle's
// share of fresh area is measured without polygon Booleans.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "geometry/polygon.h"

namespace rearm::scenario {

class CoverageGrid {
 public:
  // A grid of square cells of side `cell` over [0, width] x [0, height].
  CoverageGrid(double width, double height, double cell);

  // Cells of p not covered yet; with commit, they become covered.
  std::size_t fresh(const geometry::Polygon& p, bool commit);
  double cell_area() const { return h_ * h_; }
  double cell_side() const { return h_; }

 private:
  double h_;
  int nx_, ny_;
  std::vector<std::uint8_t> covered_;
};

}  // namespace rearm::scenario
