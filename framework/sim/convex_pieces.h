// Convex pieces for Box2D's polygon fixtures (docs/experiments.md, "Box2D world"):
// b2PolygonShape::Set takes a convex polygon of at most b2_maxPolygonVertices (8) vertices and
// silently replaces anything else by its convex hull (or a 1 × 1 box), so every familiar and
// unknown obstacle is cut here, in doubles and without Box2D, into pieces Set keeps as given.
#pragma once

#include <cstddef>
#include <vector>

#include "geometry/polygon.h"

namespace rearm::sim {

// b2_maxPolygonVertices of Box2D 2.4.1 (sim_world.cpp checks the two agree).
inline constexpr std::size_t kMaxPieceVertices = 8;
// Relative turn (|cross| / (|a|·|b|), the sine of the turning angle) below which a vertex counts
// as collinear with its neighbours and is dropped (geometry::remove_collinear).
inline constexpr double kCollinearTolerance = 1e-12;

// Splits a convex counter-clockwise polygon without collinear vertices into a fan of convex
// pieces of at most max_vertices vertices each: {v0, …, v(m−1)}, then {v0, v(m−1), …}, … Piece
// vertices are input vertices (bit for bit), so the pieces tile the polygon exactly. Throws
// rearm::Error when max_vertices < 3 or the polygon has fewer than 3 vertices.
std::vector<geometry::Polygon> split_convex(const geometry::Polygon& convex,
                                            std::size_t max_vertices = kMaxPieceVertices);

// Convex pieces of a simple polygon: validated (geometry::validated, any orientation),
// collinear vertices removed, kept whole when convex, otherwise cut by geometry::convex_partition
// (every piece vertex an input vertex, slivers below geometry::kSliverArea dropped), and pieces
// above max_vertices split by split_convex. Each piece is convex, counter-clockwise, has 3 to
// max_vertices vertices and no collinear vertex; the pieces' interiors are disjoint and their
// union is the polygon. Throws rearm::Error naming `what` for an invalid polygon.
std::vector<geometry::Polygon> convex_pieces(const geometry::Polygon& polygon,
                                             const char* what = "polygon",
                                             std::size_t max_vertices = kMaxPieceVertices);

}  // namespace rearm::sim
