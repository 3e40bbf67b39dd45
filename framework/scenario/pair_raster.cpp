// PairRaster of pair_raster.h: plain doubles (accept-or-retry decisions; the exact certificate
// of solvability.h is checked on the finished instance).
#include "scenario/pair_raster.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/error.h"
#include "geometry/distance.h"

namespace rearm::scenario {

PairRaster::PairRaster(double width, double height, double clearance, double cell,
                       std::size_t max_cells)
    : width_(width), height_(height), clearance_(clearance) {
  REARM_DEMAND(width > 0 && height > 0 && clearance > 0 && cell > 0 && max_cells > 0,
               "PairRaster: non-positive size");
  h_ = std::max(cell, std::sqrt(width * height / static_cast<double>(max_cells)));
  margin_ = h_ * std::sqrt(2.0) / 2;
  nx_ = std::max(1, static_cast<int>(std::ceil(width / h_)));
  ny_ = std::max(1, static_cast<int>(std::ceil(height / h_)));
  blocked_.assign(static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_), 0);
  seen_.assign(blocked_.size(), 0);
  target_mark_.assign(blocked_.size(), 0);
  const double need = clearance_ + margin_;
  for (int iy = 0; iy < ny_; ++iy) {
    for (int ix = 0; ix < nx_; ++ix) {
      const geometry::Point c = centre(ix, iy);
      const double wall = std::min({c.x(), width_ - c.x(), c.y(), height_ - c.y()});
      if (wall < need) blocked_[static_cast<std::size_t>(iy * nx_ + ix)] = 1;
    }
  }
}

geometry::Point PairRaster::centre(int ix, int iy) const {
  return geometry::Point((ix + 0.5) * h_, (iy + 0.5) * h_);
}

int PairRaster::cell_of(const geometry::Point& p) const {
  if (!(p.x() >= 0 && p.y() >= 0 && p.x() < nx_ * h_ && p.y() < ny_ * h_)) return -1;
  const int ix = std::min(nx_ - 1, static_cast<int>(p.x() / h_));
  const int iy = std::min(ny_ - 1, static_cast<int>(p.y() / h_));
  return iy * nx_ + ix;
}

std::vector<int> PairRaster::newly_blocked(const geometry::Polygon& p) const {
  geometry::Point lo = p.vertices.front(), hi = lo;
  for (const geometry::Point& v : p.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  const double need = clearance_ + margin_;
  const int x0 = std::max(0, static_cast<int>(std::floor((lo.x() - need) / h_)));
  const int x1 = std::min(nx_ - 1, static_cast<int>(std::floor((hi.x() + need) / h_)));
  const int y0 = std::max(0, static_cast<int>(std::floor((lo.y() - need) / h_)));
  const int y1 = std::min(ny_ - 1, static_cast<int>(std::floor((hi.y() + need) / h_)));
  std::vector<int> out;
  for (int iy = y0; iy <= y1; ++iy) {
    for (int ix = x0; ix <= x1; ++ix) {
      const int k = iy * nx_ + ix;
      if (blocked_[static_cast<std::size_t>(k)] != 0) continue;
      if (geometry::distance(p, centre(ix, iy)) < need) out.push_back(k);
    }
  }
  return out;
}

void PairRaster::block(const std::vector<int>& cells) {
  for (const int k : cells) blocked_[static_cast<std::size_t>(k)] = 1;
}

bool PairRaster::connects(int source, const std::vector<std::vector<int>>& targets,
                          const std::vector<int>& extra) const {
  if (++epoch_ == 0) {  // wrapped: clear the marks
    std::fill(seen_.begin(), seen_.end(), 0);
    std::fill(target_mark_.begin(), target_mark_.end(), 0);
    epoch_ = 1;
  }
  const std::uint32_t blocked_mark = epoch_;
  // Extra cells are marked seen (never entered); the source must be free and not extra.
  for (const int k : extra) seen_[static_cast<std::size_t>(k)] = blocked_mark;
  if (!is_free(source) || seen_[static_cast<std::size_t>(source)] == blocked_mark) return false;
  // (cell, group) pairs sorted by cell; cells holding a target are marked for a quick test.
  std::vector<std::pair<int, std::size_t>> pairs;
  for (std::size_t g = 0; g < targets.size(); ++g) {
    for (const int k : targets[g]) {
      if (k < 0) continue;
      pairs.emplace_back(k, g);
      target_mark_[static_cast<std::size_t>(k)] = blocked_mark;
    }
  }
  std::sort(pairs.begin(), pairs.end());
  std::vector<char> group_done(targets.size(), 0);
  std::size_t remaining = targets.size();
  auto visit = [&](int k) {
    if (target_mark_[static_cast<std::size_t>(k)] != blocked_mark) return;
    auto it = std::lower_bound(pairs.begin(), pairs.end(), std::make_pair(k, std::size_t{0}));
    for (; it != pairs.end() && it->first == k; ++it) {
      if (group_done[it->second] == 0) {
        group_done[it->second] = 1;
        --remaining;
      }
    }
  };
  stack_.clear();
  stack_.push_back(source);
  seen_[static_cast<std::size_t>(source)] = blocked_mark;
  while (!stack_.empty() && remaining > 0) {
    const int k = stack_.back();
    stack_.pop_back();
    visit(k);
    const int ix = k % nx_, iy = k / nx_;
    const int next[4] = {ix > 0 ? k - 1 : -1, ix + 1 < nx_ ? k + 1 : -1, iy > 0 ? k - nx_ : -1,
                         iy + 1 < ny_ ? k + nx_ : -1};
    for (const int n : next) {
      if (n < 0 || blocked_[static_cast<std::size_t>(n)] != 0 ||
          seen_[static_cast<std::size_t>(n)] == blocked_mark) {
        continue;
      }
      seen_[static_cast<std::size_t>(n)] = blocked_mark;
      stack_.push_back(n);
    }
  }
  return remaining == 0;
}

}  // namespace rearm::scenario
