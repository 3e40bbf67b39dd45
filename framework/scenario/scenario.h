// A scenario (docs/experiments.md, "Scenario files"): everything one run needs — the workspace,
// the robot, the regions of interest, the movable objects, the familiar and unknown obstacles,
// the LTL task, the controller parameters and the simulation settings. An immutable value,
// shared read-only across threads (docs/architecture.md, house style 2).
//
// Loaded from YAML and validated (scenario_io.h: load_scenario, validate) so that nothing
// invalid is ever simulated. The task formula is kept as text here: checking its names against
// the objects and regions needs the LTL parser, which the scenario module may not use; the
// experiment layer does it when it loads a scenario for a run.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/switches.h"
#include "geometry/convex.h"
#include "geometry/polygon.h"

namespace rearm::scenario {

struct Robot {
  double radius = 0.2;  // r (m)
  geometry::Point start = geometry::Point::Zero();
  double heading = 0;         // ψ at the start (rad)
  double v_max = 0.4;         // m/s
  double omega_max = 1.0;     // rad/s
  double sensor_range = 3.0;  // R (m)
};

struct NamedPolygon {
  std::string name;
  geometry::Polygon polygon;
};

struct Object {
  std::string name;
  geometry::Disk disk;  // start position and radius ρ_i
};

// m: the robust variant's default scan spacing (Controller::scan_spacing).
inline constexpr double kScanSpacing = 0.2;

// The reactive controller's and the executive's parameters (defaults: rearm's, as in
// reactive::DiffeoParams, reactive::NavParams and executive::ExecutiveParams).
struct Controller {
  int p = 20;            // R-conjunction exponent (an even integer >= 2)
  double epsilon = 1.0;  // collar width ε (m)
  double mu1 = 1.0;      // deforming-factor parameters μ1, μ2
  double mu2 = 0.05;
  double k_v = 1.0;  // unicycle gains
  double k_omega = 1.0;
  double goal_tolerance = 0.05;  // m
  // m: a visible unknown fragment changes the map (and the diffeomorphism is rebuilt) only when
  // a vertex moved by more than this. Fragments change where the sensor disk cuts an obstacle,
  // i.e. about R away from the robot, so a stale fragment only misses parts at least R - 0.1 m
  // away; 0.1 m halves the rebuilds of 0.05 m (fig5: 369 instead of 720).
  double fragment_tolerance = 0.1;
  // m: with `scan` on, the unknown fragments are read again only once the robot has travelled
  // this far since the last reading (perception::ChangeTolerances::scan_spacing; at most R/4,
  // docs/reactive.md §2). Without `scan` (the paper variant) they are read at every step.
  double scan_spacing = kScanSpacing;
  // The interface layer's behaviour where [7]'s separation assumptions break
  // (experiments/sweeps/README.md, "Variants"): "robust" (the default) runs the extensions of
  // executive::RobustParams, each switchable below; "paper" runs none (the paper's choices).
  std::string variant = "robust";
  // robust only: the registry's switches (core/switches.h), all on by default.
  SwitchSet switches;
  // m: with `defer` on, the margin beyond the dilation radius within which the map's news
  // forces a rebuild (executive::RobustParams::rebuild_margin).
  double rebuild_margin = 1.0;
};

// Sets the variant ("robust" or "paper") and every switch: all on, or all off.
inline void set_variant(Controller& c, const std::string& variant) {
  c.variant = variant;
  c.switches.set_all(variant == "robust");
}

struct Simulation {
  double dt = 0.01;           // fixed step (s)
  double time_budget = 1200;  // simulated seconds before the run ends "timeout"
  int velocity_iterations = 8;
  int position_iterations = 3;
  int max_actions = 0;  // LTL actions after which the run ends (patrols); 0: none
};

struct Scenario {
  std::string name;         // e.g. "fig3"
  std::string description;  // free text
  std::string source;       // the file it was loaded from ("" if built in code)
  geometry::Polygon workspace;
  Robot robot;
  std::vector<NamedPolygon> regions;
  std::vector<Object> objects;
  std::vector<NamedPolygon> familiar;  // possibly non-convex
  std::vector<NamedPolygon> unknown;   // convex
  std::string task;                    // LTL formula text
  // The predicate holding at the start (the paper's π0, Appendix I-B), e.g. "move(l1)"; empty:
  // none (the empty symbol). Checked against the scene by the experiment layer.
  std::string initial_predicate;
  Controller controller;
  Simulation simulation;
};

}  // namespace rearm::scenario
