// Seeded random scenes for the topology tests that compare the check with itself (cached and
// uncached) or its localized Booleans with one global geometry::subtract: walls with doors,
// rotated rectangles, star polygons, U shapes and closed boxes as familiar obstacles, disks as
// objects, placed so that shapes often touch, overlap or cross the workspace boundary (the
// cases the localization must get right). Not a truth oracle: topology_property_test has one.
#pragma once

#include <Eigen/Geometry>
#include <numbers>
#include <vector>

#include "core/rng.h"
#include "geometry/convex.h"
#include "geometry/polygon.h"
#include "support/geometry_oracle.h"

namespace rearm::topology::test_scenes {

using geometry::Disk;
using geometry::Point;
using geometry::Polygon;

inline Polygon rect(double x0, double y0, double x1, double y1) {
  return Polygon{{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}};
}

inline Polygon rotated_rect(const Point& c, double w, double h, double angle) {
  const Eigen::Rotation2Dd rot(angle);
  Polygon p;
  for (const Point& v :
       {Point(-w / 2, -h / 2), Point(w / 2, -h / 2), Point(w / 2, h / 2), Point(-w / 2, h / 2)}) {
    p.vertices.push_back(c + rot * v);
  }
  return p;
}

// A U open upwards, outer size s, wall thickness t, at c.
inline Polygon u_shape(const Point& c, double s, double t) {
  const double h = s / 2;
  return Polygon{{{c.x() - h, c.y() - h},
                  {c.x() + h, c.y() - h},
                  {c.x() + h, c.y() + h},
                  {c.x() + h - t, c.y() + h},
                  {c.x() + h - t, c.y() - h + t},
                  {c.x() - h + t, c.y() - h + t},
                  {c.x() - h + t, c.y() + h},
                  {c.x() - h, c.y() + h}}};
}

struct Scene {
  Polygon workspace;
  std::vector<Polygon> familiar;
  std::vector<Disk> objects;
  double radius = 0.2;
};

// A room of side `size` (sometimes L-shaped), 0–3 walls with doors, 0–6 blocks (rectangles,
// stars, U shapes, closed boxes), 0–12 disks of radius 0.15–0.6, a third of them at a door or
// against a wall or an obstacle.
inline Scene random_scene(Rng& rng, double size = 10) {
  Scene s;
  s.radius = rng.uniform(0.1, 0.5);
  if (rng.bernoulli(0.25)) {
    const double a = size * rng.uniform(0.4, 0.7);
    s.workspace = Polygon{{{0, 0}, {size, 0}, {size, a}, {a, a}, {a, size}, {0, size}}};
  } else {
    s.workspace = rect(0, 0, size, size);
  }
  std::vector<Point> hot;  // places objects like: doors, wall ends, obstacle sides
  const int walls = static_cast<int>(rng.uniform_int(0, 3));
  for (int w = 0; w < walls; ++w) {
    const bool horizontal = rng.bernoulli(0.5);
    const double at = rng.uniform(0.2, 0.8) * size;
    const double thick = rng.uniform(0.1, 0.4);
    const double door = rng.uniform(0.15, 0.85) * size;
    const double width = rng.uniform(0.3, 2.2);
    const double lo = door - width / 2, hi = door + width / 2;
    if (horizontal) {
      s.familiar.push_back(rect(0, at - thick / 2, lo, at + thick / 2));
      s.familiar.push_back(rect(hi, at - thick / 2, size, at + thick / 2));
      hot.emplace_back(door, at);
    } else {
      s.familiar.push_back(rect(at - thick / 2, 0, at + thick / 2, lo));
      s.familiar.push_back(rect(at - thick / 2, hi, at + thick / 2, size));
      hot.emplace_back(at, door);
    }
  }
  const int blocks = static_cast<int>(rng.uniform_int(0, 6));
  for (int b = 0; b < blocks; ++b) {
    const Point c(rng.uniform(0.05, 0.95) * size, rng.uniform(0.05, 0.95) * size);
    const double kind = rng.uniform01();
    if (kind < 0.35) {
      s.familiar.push_back(rotated_rect(c, rng.uniform(0.3, 2.0), rng.uniform(0.2, 1.5),
                                        rng.uniform(0, std::numbers::pi)));
    } else if (kind < 0.7) {
      s.familiar.push_back(
          test_support::random_star(rng, static_cast<int>(rng.uniform_int(5, 9)), 0.3, 1.2, c));
    } else if (kind < 0.85) {
      s.familiar.push_back(u_shape(c, rng.uniform(1.0, 2.5), rng.uniform(0.1, 0.4)));
    } else {  // a closed box of four walls: its inside is an island of freespace
      const double h = rng.uniform(0.8, 1.8), t = rng.uniform(0.1, 0.3);
      s.familiar.push_back(rect(c.x() - h, c.y() - h, c.x() + h, c.y() - h + t));
      s.familiar.push_back(rect(c.x() - h, c.y() + h - t, c.x() + h, c.y() + h));
      s.familiar.push_back(rect(c.x() - h, c.y() - h, c.x() - h + t, c.y() + h));
      s.familiar.push_back(rect(c.x() + h - t, c.y() - h, c.x() + h, c.y() + h));
    }
    hot.push_back(c + Point(rng.uniform(-1, 1), rng.uniform(-1, 1)));
  }
  hot.emplace_back(rng.uniform(0, size), 0.3);
  hot.emplace_back(size - 0.3, rng.uniform(0, size));
  const int objects = static_cast<int>(rng.uniform_int(0, 12));
  for (int k = 0; k < objects; ++k) {
    Disk d;
    d.radius = rng.uniform(0.15, 0.6);
    if (rng.bernoulli(0.35)) {
      d.center = hot[rng.index(hot.size())] + Point(rng.uniform(-0.6, 0.6), rng.uniform(-0.6, 0.6));
    } else {
      d.center = Point(rng.uniform(0.3, size - 0.3), rng.uniform(0.3, size - 0.3));
    }
    s.objects.push_back(d);
  }
  return s;
}

}  // namespace rearm::topology::test_scenes
