// The static scene files of `rearm diffeo` (experiments/scenes/README.md): a strict reader for
// one small, documented subset of YAML, so the command needs no YAML library (yaml-cpp stays
// inside scenario/, docs/architecture.md).
//
//   # comment (from '#' to the end of the line, anywhere)
//   workspace: [[0,0],[20,0],[20,20],[0,20]]
//   robot: {radius: 0.2, sensing_range: 5, start: [1,1], heading: 0, goal: [18,18]}
//   familiar:
//     - [[x,y],[x,y],...]
//   unknown:
//     - [[x,y],...]
//   movable:
//     - {center: [x,y], radius: r}
//   params: {epsilon: 1.0, mu1: 1.0, mu2: 0.05, p: 20}
//
// Grammar: top-level keys start in column 1, each once, in any order. A key is followed on
// its line either by one flow value, or by nothing and then a block list of "- <flow value>"
// lines (indented or not). Flow values are numbers, [a, b, ...] lists and {key: value, ...}
// maps; one may continue over several lines while a bracket is open. Numbers are decimal
// (strtod syntax); NaN and infinities (any spelling, or an overflowing literal) are
// rejected. No strings, anchors, tags or multi-document streams.
//
// Schema: `workspace` (a simple polygon, >= 3 vertices, either orientation) and `robot` are
// required; in `robot`, `radius` (> 0), `start` and `goal` are required, `sensing_range`
// (> 0, default 5 m) and `heading` (rad, default 0) optional. `familiar` (simple polygons,
// possibly non-convex; they may cross the workspace boundary), `unknown` (convex polygons) and
// `movable` (disks) default to empty lists ([] is allowed); `params` sets any of the
// reactive::DiffeoParams fields epsilon, mu1, mu2, p (an even integer),
// root_radius_fraction, boundary_center_offset, sliver_area (defaults: params.h). Unknown
// keys, missing required keys, duplicate keys, malformed polygons (self-intersecting, repeated
// vertices, zero area), a non-convex unknown obstacle, and a start or goal closer than the
// robot radius to an obstacle or outside the workspace are errors.
//
// Every error is a rearm::Error whose message starts with "FILE:LINE: " and says what is
// wrong.
#pragma once

#include <string>
#include <vector>

#include "geometry/polygon.h"
#include "reactive/mapped_space.h"
#include "reactive/params.h"

namespace rearm::cli {

struct SceneFile {
  std::string name;                  // the file name, for messages
  reactive::SemanticInput semantic;  // workspace and obstacles, undilated
  double radius = 0;                 // robot radius r
  double sensing_range = 5.0;        // R (m)
  geometry::Point start = geometry::Point::Zero();
  double heading = 0;  // ψ at the start (rad)
  geometry::Point goal = geometry::Point::Zero();
  reactive::DiffeoParams params;
  // Source lines of the entries above, for later messages.
  int workspace_line = 0;
  int robot_line = 0;
  std::vector<int> familiar_lines, unknown_lines, movable_lines;
};

// Parses the text of a scene file; `name` is used in messages. Throws rearm::Error.
SceneFile parse_scene(const std::string& text, const std::string& name);

// Reads and parses a scene file. Throws rearm::Error (also when it cannot be read).
SceneFile read_scene_file(const std::string& path);

}  // namespace rearm::cli
