// validate() of scenario_io.h: the checks that keep an invalid scenario from ever being
// simulated (docs/experiments.md, "Scenario files"). The rules and their order are listed in
// experiments/scenarios/README.md, "Validation".
//
// Topological decisions use the exact predicates of geometry/ (validated, contains, the
// Boolean difference for a region leaving a non-convex workspace); clearances between disks
// and polygons are doubles (geometry::signed_distance). Touching is allowed: a disk at
// clearance exactly 0 from an obstacle, another disk or the workspace boundary is valid, and
// any overlap, however small, is an error.
#include <charconv>
#include <cmath>
#include <map>
#include <string>
#include <system_error>
#include <vector>

#include "core/error.h"
#include "geometry/boolean.h"
#include "geometry/distance.h"
#include "scenario/scenario_io.h"

namespace rearm::scenario {
namespace {

// The source named in messages about a scenario built in code (Scenario::source empty).
const char* const kInMemorySource = "<scenario>";

// The shortest decimal that reads back to x ("0.1", not "0.10000000000000001").
std::string num(double x) {
  char buf[64];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, x);
  REARM_DEMAND(ec == std::errc(), "to_chars failed on a double");
  return std::string(buf, end);
}

std::string show(const geometry::Point& p) { return "(" + num(p.x()) + ", " + num(p.y()) + ")"; }

bool ascii_alpha(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
bool ascii_digit(char c) { return c >= '0' && c <= '9'; }

// The identifiers of the LTL parser's action-predicate arguments (move(l1), grasp(M1)).
bool is_identifier(const std::string& s) {
  if (s.empty() || !(ascii_alpha(s[0]) || s[0] == '_')) return false;
  for (const char c : s) {
    if (!(ascii_alpha(c) || ascii_digit(c) || c == '_')) return false;
  }
  return true;
}

// A scenario name ends up in file and folder names of results.
bool is_file_name_safe(const std::string& s) {
  if (s.empty() || s[0] == '.' || s[0] == '-') return false;
  for (const char c : s) {
    if (!(ascii_alpha(c) || ascii_digit(c) || c == '_' || c == '-' || c == '.')) return false;
  }
  return true;
}

bool is_blank(const std::string& s) {
  for (const char c : s) {
    if (c != ' ' && c != '\t' && c != '\n' && c != '\r') return false;
  }
  return true;
}

class Validator {
 public:
  explicit Validator(const Scenario& s)
      : s_(s), source_(s.source.empty() ? kInMemorySource : s.source) {}

  void run() {
    if (!is_file_name_safe(s_.name)) {
      fail("name",
           "must be a non-empty name of letters, digits, '_', '-' and '.' not starting with "
           "'.' or '-' (it names result files), got '" +
               s_.name + "'");
    }
    polygon(s_.workspace, "workspace");
    robot();
    for (std::size_t i = 0; i < s_.regions.size(); ++i) {
      named_polygon(s_.regions[i], item("regions", i));
    }
    for (std::size_t i = 0; i < s_.objects.size(); ++i) object(i);
    for (std::size_t i = 0; i < s_.familiar.size(); ++i) {
      named_polygon(s_.familiar[i], item("familiar", i));
    }
    for (std::size_t i = 0; i < s_.unknown.size(); ++i) {
      named_polygon(s_.unknown[i], item("unknown", i));
      convex(s_.unknown[i].polygon, item("unknown", i) + ".polygon");
    }
    unique_names();
    if (is_blank(s_.task)) fail("task", "must be a non-empty LTL formula");
    controller();
    simulation();

    for (std::size_t i = 0; i < s_.regions.size(); ++i) region_inside_workspace(i);
    for (std::size_t i = 0; i < s_.objects.size(); ++i) object_placement(i);
    robot_placement();
  }

 private:
  [[noreturn]] void fail(const std::string& key, const std::string& reason) const {
    throw ScenarioError(source_, key, reason);
  }

  static std::string item(const char* list, std::size_t i) {
    return std::string(list) + "[" + std::to_string(i) + "]";
  }

  void positive(double x, const std::string& key) const {
    if (!(std::isfinite(x) && x > 0)) fail(key, "must be finite and > 0, got " + num(x));
  }

  void finite(double x, const std::string& key) const {
    if (!std::isfinite(x)) fail(key, "must be finite, got " + num(x));
  }

  void finite(const geometry::Point& p, const std::string& key) const {
    if (!(std::isfinite(p.x()) && std::isfinite(p.y()))) {
      fail(key, "must be a finite point, got " + show(p));
    }
    if (!(std::abs(p.x()) <= kMaxCoordinate && std::abs(p.y()) <= kMaxCoordinate)) {
      fail(key, "coordinates must lie within ±" + num(kMaxCoordinate) + " m, got " + show(p));
    }
  }

  void length(double x, const std::string& key) const {
    positive(x, key);
    if (!(x <= kMaxLength)) fail(key, "must be at most " + num(kMaxLength) + " m, got " + num(x));
  }

  // Finite, within the coordinate bound, simple, non-degenerate (geometry::validated) and stored
  // counter-clockwise.
  void polygon(const geometry::Polygon& p, const std::string& key) const {
    for (std::size_t i = 0; i < p.size(); ++i) {
      const geometry::Point& v = p.vertices[i];
      if (std::isfinite(v.x()) && std::isfinite(v.y())) {
        finite(v, key + "[" + std::to_string(i) + "]");
      }
    }
    geometry::Polygon ccw;
    try {
      ccw = geometry::validated(p, key.c_str());
    } catch (const Error& e) {
      std::string reason = e.what();
      const std::string prefix = key + ": ";
      if (reason.rfind(prefix, 0) == 0) reason.erase(0, prefix.size());
      fail(key, reason);
    }
    if (ccw.vertices != p.vertices) {
      fail(key,
           "vertices are clockwise; a Scenario stores polygons counter-clockwise "
           "(geometry::validated returns them so)");
    }
  }

  void convex(const geometry::Polygon& p, const std::string& key) const {
    if (p.is_convex()) return;
    // The first reflex vertex, by the same turn test as Polygon::is_convex.
    const std::size_t n = p.size();
    for (std::size_t i = 0; i < n; ++i) {
      const geometry::Point& a = p.vertices[i];
      const geometry::Point& b = p.vertices[(i + 1) % n];
      const geometry::Point& c = p.vertices[(i + 2) % n];
      const geometry::Point u = b - a;
      const geometry::Point v = c - b;
      if (u.x() * v.y() - u.y() * v.x() < 0) {
        fail(key, "unknown obstacles must be convex; vertex " + std::to_string((i + 1) % n) + " " +
                      show(b) + " is reflex");
      }
    }
    fail(key, "unknown obstacles must be convex");
  }

  void named_polygon(const NamedPolygon& np, const std::string& key) const {
    polygon(np.polygon, key + ".polygon");
  }

  void robot() const {
    const Robot& r = s_.robot;
    length(r.radius, "robot.radius");
    finite(r.start, "robot.start");
    finite(r.heading, "robot.heading");
    positive(r.v_max, "robot.v_max");
    positive(r.omega_max, "robot.omega_max");
    length(r.sensor_range, "robot.sensor_range");
  }

  void object(std::size_t i) const {
    const Object& o = s_.objects[i];
    finite(o.disk.center, item("objects", i) + ".center");
    length(o.disk.radius, item("objects", i) + ".radius");
  }

  // One namespace for regions, objects and obstacles: the task names regions and objects, and
  // messages and results name obstacles.
  void unique_names() const {
    std::map<std::string, std::string> first;  // name -> key of its first holder
    auto check = [&](const std::string& name, const std::string& key) {
      if (!is_identifier(name)) {
        fail(key, "must be an identifier (a letter or '_', then letters, digits or '_'), got '" +
                      name + "'");
      }
      const auto [it, inserted] = first.emplace(name, key);
      if (!inserted) fail(key, "duplicate name '" + name + "' (also " + it->second + ")");
    };
    for (std::size_t i = 0; i < s_.regions.size(); ++i) {
      check(s_.regions[i].name, item("regions", i) + ".name");
    }
    for (std::size_t i = 0; i < s_.objects.size(); ++i) {
      check(s_.objects[i].name, item("objects", i) + ".name");
    }
    for (std::size_t i = 0; i < s_.familiar.size(); ++i) {
      check(s_.familiar[i].name, item("familiar", i) + ".name");
    }
    for (std::size_t i = 0; i < s_.unknown.size(); ++i) {
      check(s_.unknown[i].name, item("unknown", i) + ".name");
    }
  }

  void controller() const {
    const Controller& c = s_.controller;
    // The R-function of order p (reactive/) is a sum of p-th powers: p even keeps it a norm.
    if (c.p < 2 || c.p % 2 != 0) {
      fail("controller.p", "must be an even integer >= 2, got " + std::to_string(c.p));
    }
    positive(c.epsilon, "controller.epsilon");
    positive(c.mu1, "controller.mu1");
    positive(c.mu2, "controller.mu2");
    positive(c.k_v, "controller.k_v");
    positive(c.k_omega, "controller.k_omega");
    positive(c.goal_tolerance, "controller.goal_tolerance");
    positive(c.fragment_tolerance, "controller.fragment_tolerance");
    positive(c.scan_spacing, "controller.scan_spacing");
    finite(c.rebuild_margin, "controller.rebuild_margin");
    if (c.rebuild_margin < 0) {
      fail("controller.rebuild_margin", "must be >= 0, got " + num(c.rebuild_margin));
    }
  }

  void simulation() const {
    const Simulation& m = s_.simulation;
    positive(m.dt, "simulation.dt");
    positive(m.time_budget, "simulation.time_budget");
    if (m.dt > m.time_budget) {
      fail("simulation.dt",
           "must not exceed simulation.time_budget (" + num(m.time_budget) + "), got " + num(m.dt));
    }
    if (m.velocity_iterations < 1) {
      fail("simulation.velocity_iterations",
           "must be an integer >= 1, got " + std::to_string(m.velocity_iterations));
    }
    if (m.position_iterations < 1) {
      fail("simulation.position_iterations",
           "must be an integer >= 1, got " + std::to_string(m.position_iterations));
    }
    if (m.max_actions < 0) {
      fail("simulation.max_actions",
           "must be an integer >= 0 (0: no limit), got " + std::to_string(m.max_actions));
    }
  }

  // Every vertex inside the (closed) workspace, then no part of the region outside it (an
  // edge can leave a non-convex workspace between two inside vertices).
  void region_inside_workspace(std::size_t i) const {
    const geometry::Polygon& p = s_.regions[i].polygon;
    const std::string key = item("regions", i) + ".polygon";
    for (std::size_t k = 0; k < p.size(); ++k) {
      if (!geometry::contains(s_.workspace, p.vertices[k])) {
        fail(key, "region '" + s_.regions[i].name + "' is not inside the workspace: vertex " +
                      std::to_string(k) + " " + show(p.vertices[k]) + " lies outside it");
      }
    }
    const geometry::RegionSet outside =
        geometry::subtract(geometry::to_set(p), geometry::to_set(s_.workspace));
    if (!outside.empty()) {
      fail(key, "region '" + s_.regions[i].name +
                    "' is not inside the workspace: an edge passes outside it (area " +
                    num(geometry::total_area(outside)) + " m² outside)");
    }
  }

  // Disk d (described as `what`, reported under `key`) must lie in the workspace and overlap
  // no obstacle and none of the first `objects` objects.
  void disk_placement(const geometry::Disk& d, const std::string& key, const std::string& what,
                      std::size_t objects) const {
    const double inner = -geometry::signed_distance(s_.workspace, d.center);
    if (inner < 0) {
      fail(key, what + ": the center " + show(d.center) + " lies outside the workspace");
    }
    if (inner < d.radius) {
      fail(key, what + " crosses the workspace boundary: the center " + show(d.center) + " is " +
                    num(inner) + " m from it, less than the radius " + num(d.radius));
    }
    auto against = [&](const std::vector<NamedPolygon>& list, const char* kind,
                       const char* list_key) {
      for (std::size_t j = 0; j < list.size(); ++j) {
        const double sd = geometry::signed_distance(list[j].polygon, d.center);
        if (sd >= d.radius) continue;
        const std::string obstacle =
            std::string(kind) + " obstacle '" + list[j].name + "' (" + item(list_key, j) + ")";
        if (sd <= 0) {
          fail(key, what + " overlaps " + obstacle + ": the center " + show(d.center) +
                        " lies inside it");
        }
        fail(key, what + " overlaps " + obstacle + ": the center " + show(d.center) + " is " +
                      num(sd) + " m from it, less than the radius " + num(d.radius));
      }
    };
    against(s_.familiar, "familiar", "familiar");
    against(s_.unknown, "unknown", "unknown");
    for (std::size_t j = 0; j < objects; ++j) {
      const geometry::Disk& o = s_.objects[j].disk;
      const double gap = (o.center - d.center).norm();
      if (gap < o.radius + d.radius) {
        fail(key, what + " overlaps object '" + s_.objects[j].name + "' (" + item("objects", j) +
                      "): the centers are " + num(gap) + " m apart, less than the sum of radii " +
                      num(o.radius + d.radius));
      }
    }
  }

  void object_placement(std::size_t i) const {
    disk_placement(s_.objects[i].disk, item("objects", i), "object '" + s_.objects[i].name + "'",
                   i);
  }

  void robot_placement() const {
    disk_placement(geometry::Disk{s_.robot.start, s_.robot.radius}, "robot.start",
                   "the robot's start disk (radius " + num(s_.robot.radius) + ")",
                   s_.objects.size());
  }

  const Scenario& s_;
  std::string source_;
};

}  // namespace

void validate(const Scenario& s) { Validator(s).run(); }

}  // namespace rearm::scenario
