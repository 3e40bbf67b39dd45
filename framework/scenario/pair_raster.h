// A conservative raster of the robot–object pair's freespace, used by the random instance
// generator (random_instance.h) to reject obstacles that would break the solvability
// certificate (solvability.h) while it samples; the exact check runs once at the end.
//
// Cells of side h cover [0, width] x [0, height]. A cell is free when its centre has clearance
// >= clearance + m to the boundary and to every committed obstacle, m = h·√2/2 (half the cell
// diagonal). Every point of a free cell then has clearance >= clearance, and so has the segment
// between the centres of two 4-adjacent free cells (each of its points is within h/2 < m of one
// of them; clearance is 1-Lipschitz): raster connectivity of free cells implies connectivity of
// the true freespace of a disk of radius `clearance`. The converse fails (a passage narrower
// than about 2m + h more than the disk's diameter can be closed in the raster): the raster only
// ever rejects too much.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/polygon.h"

namespace rearm::scenario {

class PairRaster {
 public:
  // cell: the preferred side h (m), enlarged so that the raster has at most max_cells cells.
  PairRaster(double width, double height, double clearance, double cell, std::size_t max_cells);

  double cell_side() const { return h_; }
  double margin() const { return margin_; }
  // The cell holding p, or -1 when p lies outside the raster.
  int cell_of(const geometry::Point& p) const;
  bool is_free(int cell) const {
    return cell >= 0 && blocked_[static_cast<std::size_t>(cell)] == 0;
  }
  // Free cells whose centre is closer than clearance + m to the polygon (or inside it).
  std::vector<int> newly_blocked(const geometry::Polygon& p) const;
  void block(const std::vector<int>& cells);
  // Whether, with `extra` cells blocked too, a 4-connected flood fill of free cells from
  // `source` reaches at least one cell of every target group.
  bool connects(int source, const std::vector<std::vector<int>>& targets,
                const std::vector<int>& extra) const;

 private:
  geometry::Point centre(int ix, int iy) const;

  double width_, height_, clearance_, h_, margin_;
  int nx_, ny_;
  std::vector<std::uint8_t> blocked_;
  // Flood-fill scratch (one raster per generator, so no shared state between threads).
  mutable std::vector<std::uint32_t> seen_, target_mark_;
  mutable std::uint32_t epoch_ = 0;
  mutable std::vector<int> stack_;
};

}  // namespace rearm::scenario
