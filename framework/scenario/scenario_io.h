// Scenario files: YAML (yaml-cpp), one scenario per file, with validation that names the file,
// the key and the reason (docs/experiments.md). The format is documented in
// experiments/scenarios/README.md (a reference file with every key, its type, unit, default
// and constraint).
#pragma once

#include <string>

#include "core/error.h"
#include "scenario/scenario.h"

namespace rearm::scenario {

// An invalid scenario: what() reads "<source>: <key>: <reason>", e.g.
// "fig3.yaml: objects[1].radius: must be finite and > 0, got -0.25 (line 12)". The key is a path
// into the file (`robot.start`, `regions[0].polygon`, `workspace[2][0]`); errors found in a file
// end their reason with the line of that key (or of its closest enclosing key); a YAML syntax
// error has the key "line L, column C"; a file that cannot be read has the key "file"; a
// document that is empty, not a mapping or more than one document has the key "<document>".
// A scenario built in code (empty Scenario::source) is named "<scenario>".
class ScenarioError : public Error {
 public:
  ScenarioError(const std::string& source, const std::string& key, const std::string& reason);
  const std::string& source() const { return source_; }
  const std::string& key() const { return key_; }
  const std::string& reason() const { return reason_; }

 private:
  std::string source_, key_, reason_;
};

// Every coordinate (m) lies in [−kMaxCoordinate, kMaxCoordinate] and every length (radii, the
// sensor range) in (0, kMaxLength]: beyond, the rounding of doubles swamps the geometry's
// tolerances (1e-9 m), and 1e308 overflows it.
inline constexpr double kMaxCoordinate = 1e4;
inline constexpr double kMaxLength = 1e4;

// Reads and validates a scenario file. Throws ScenarioError for a missing or unreadable file,
// malformed YAML (with its line), a missing required key, an unknown key, a value of the wrong
// type, and everything validate() rejects.
Scenario load_scenario(const std::string& path);
// The same from text; `source` names it in messages.
Scenario parse_scenario(const std::string& yaml, const std::string& source = "<string>");

// Checks a scenario built in code (load_scenario calls it too); throws ScenarioError naming the
// key: non-finite numbers anywhere; coordinates and lengths beyond kMaxCoordinate and kMaxLength;
// non-positive radii, ranges, limits, dt, budget; invalid or
// self-intersecting polygons (geometry::validated); non-convex unknown obstacles; empty or
// duplicate names (one namespace for regions, objects and obstacles); a region not inside the
// workspace; objects overlapping each other, an obstacle or the workspace boundary; the robot's
// start disk overlapping an obstacle or an object or leaving the workspace; an empty task.
// Also: polygons must be stored counter-clockwise (validate does not reorder them); names of
// regions, objects and obstacles must be identifiers ([A-Za-z_][A-Za-z0-9_]*, as the task names
// them) and the scenario's name a file-name-safe word; controller.p an even integer >= 2;
// epsilon, mu1, mu2, the gains and the tolerances > 0; dt <= time_budget; both iteration counts
// >= 1 and max_actions >= 0. Touching (clearance exactly 0) is not overlapping; familiar
// obstacles may touch or cross the workspace boundary. The full list, in the order checked, is
// in experiments/scenarios/README.md.
void validate(const Scenario& s);

// The scenario as YAML that parse_scenario reads back to an equal scenario, field by field and
// bit for bit (numbers printed in the shortest form that reads back exactly, at most 17
// significant digits; strings double-quoted). Every key is written, defaults included; the
// source is not (parse_scenario's argument sets it).
std::string to_yaml(const Scenario& s);

}  // namespace rearm::scenario
