#include "sim/convex_pieces.h"

#include <string>
#include <utility>

#include "core/error.h"
#include "geometry/convex.h"
#include "geometry/partition.h"

namespace rearm::sim {

std::vector<geometry::Polygon> split_convex(const geometry::Polygon& convex,
                                            std::size_t max_vertices) {
  if (max_vertices < 3) {
    throw Error("split_convex: max_vertices must be >= 3, got " + std::to_string(max_vertices));
  }
  if (convex.size() < 3) {
    throw Error("split_convex: a polygon needs >= 3 vertices, got " +
                std::to_string(convex.size()));
  }
  std::vector<geometry::Polygon> out;
  std::vector<geometry::Point> rest = convex.vertices;
  // Each cut keeps v0 and the piece's last vertex: the rest shrinks by max_vertices − 2.
  while (rest.size() > max_vertices) {
    const auto last = rest.begin() + static_cast<std::ptrdiff_t>(max_vertices);
    out.push_back(geometry::Polygon{std::vector<geometry::Point>(rest.begin(), last)});
    rest.erase(rest.begin() + 1, last - 1);
  }
  out.push_back(geometry::Polygon{std::move(rest)});
  return out;
}

std::vector<geometry::Polygon> convex_pieces(const geometry::Polygon& polygon, const char* what,
                                             std::size_t max_vertices) {
  const geometry::Polygon simple =
      geometry::remove_collinear(geometry::validated(polygon, what), kCollinearTolerance);
  std::vector<geometry::Polygon> convex;
  if (simple.is_convex()) {
    convex.push_back(simple);
  } else {
    convex = geometry::convex_partition(simple);
  }
  std::vector<geometry::Polygon> out;
  for (const geometry::Polygon& piece : convex) {
    const geometry::Polygon clean = geometry::remove_collinear(piece, kCollinearTolerance);
    for (geometry::Polygon& p : split_convex(clean, max_vertices)) out.push_back(std::move(p));
  }
  return out;
}

}  // namespace rearm::sim
