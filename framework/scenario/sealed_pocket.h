// The sealed class's pocket (random_instance.h, "Sealed pocket") and the rigid placement of a
// shape drawn in its own frame (the pocket's, an obstacle's).
#pragma once

#include "geometry/polygon.h"

namespace rearm::scenario {

using geometry::Point;
using geometry::Polygon;

// The pocket of the sealed class in its own frame (random_instance.h, "Sealed pocket"): the
// interior [-a, a] x [0, 2a], walls of thickness t, the mouth |x| <= m/2 in the front wall.
struct PocketFrame {
  double a = 0, t = 0, m = 0;
  Polygon walls() const {
    return Polygon{{Point(-a - t, -t), Point(a + t, -t), Point(a + t, 2 * a + t),
                    Point(m / 2, 2 * a + t), Point(m / 2, 2 * a), Point(a, 2 * a), Point(a, 0),
                    Point(-a, 0), Point(-a, 2 * a), Point(-m / 2, 2 * a), Point(-m / 2, 2 * a + t),
                    Point(-a - t, 2 * a + t)}};
  }
  Point goal() const { return Point(0, a); }
  Point blocker() const { return Point(0, 2 * a + t); }
  Point mouth() const { return Point(0, 2 * a + t / 2); }
};

struct Pose {
  Point origin = Point::Zero();
  double cs = 1, sn = 0;
  Point apply(const Point& v) const {
    return origin + Point(cs * v.x() - sn * v.y(), sn * v.x() + cs * v.y());
  }
  Point inverse(const Point& x) const {
    const Point d = x - origin;
    return Point(cs * d.x() + sn * d.y(), -sn * d.x() + cs * d.y());
  }
  Polygon apply(Polygon p) const {
    for (Point& v : p.vertices) v = apply(v);
    return p;
  }
};

struct Pocket {
  PocketFrame frame;
  Pose pose;
  Point goal, blocker, mouth, outward;
  double keepout = 0;  // other points keep this far from the blocker
};

}  // namespace rearm::scenario
