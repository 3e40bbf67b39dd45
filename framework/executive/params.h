// The interface layer's parameters (ExecutiveParams): the paper's (radii, tolerances, speeds,
// Fix-mode bounds) and the robust variant's extensions beyond it (RobustParams; docs/executive.md,
// "Robust variant"), with their named constants; the recovery counts and the compute split a run
// reports.
#pragma once

#include <array>

#include "executive/guide_path.h"
#include "executive/interface_layer.h"
#include "executive/progress_monitor.h"
#include "reactive/navigation.h"
#include "reactive/params.h"

namespace rearm::executive {

// The robust variant's extensions beyond the paper (experiments/sweeps/README.md, "Variants"),
// each a switch so a sweep can ablate it; the paper variant turns them all off. None touches
// the reactive law's safety: every motion is still the law's command through the
// discrete-time safety filter, or a straight back-up checked against everything known.
// The drop rule's clearance of the pair centre, in units of r + max ρ (the paper's early stop
// uses 2): 3 leaves at least a pair diameter between the dropped object and anything else.
inline constexpr double kDropClearance = 3;
// The drop point's levels of clearance (units of r + max ρ), tried in turn: kDropClearance,
// then in a pocket where none is reachable lower ones (the paper's early stop uses 2).
inline constexpr std::array<double, 5> kDropLevels = {kDropClearance, 2.5, 2, 1.5, 1};
// Drop points chosen again per DISASSEMBLE when a newly seen fragment takes the last one.
inline constexpr int kMaxDropRetargets = 8;
// Drop points chosen again per DISASSEMBLE after the law and every guide failed to reach the last
// (RobustParams::redrop).
inline constexpr int kMaxRedrops = 4;
// Guides planned again per action because their next waypoint left F_k (a newly seen fragment
// took it); past this the guide is dropped and the law drives at x* (the guide budget,
// GuideParams::max_recoveries, bounds what follows).
inline constexpr int kMaxGuideReplans = 8;
// m beyond the approach circle within which RobustParams::early_dock applies.
inline constexpr double kEarlyDockReach = 0.1;
// Miter limit (units of the dilation radius) of RobustParams::bevel.
inline constexpr double kBevelMiterLimit = 1.0;
// m: grid spacing of the robust release point's candidates (release_point).
inline constexpr double kReleaseStep = 0.05;
// RobustParams::release_pose (release_pose.h): headings tried at each object point; m of the
// straight last stretch; m within ℓ for the object's centre (two goal tolerances: where the
// pair stops within one, the object lies within the other); m of clearance beyond the pair's
// dilation radius along the stretch.
inline constexpr int kPoseHeadings = 24;
inline constexpr double kPoseApproach = 0.4;
inline constexpr double kPoseInside = 0.1;
inline constexpr double kPoseSlack = 0.02;
// Fix-mode entries RobustParams::object_blockers asks for per action: a Fix-mode GRASP is not
// bounded by max_fix_rounds (which counts the LTL action's), and objects that Fix mode can only
// drop back into the way would be moved forever.
inline constexpr int kMaxObjectFixes = 4;
// m by which a chosen drop point beats the drop rule, so that the early stop holds within this
// distance of it (the law converges to x* only asymptotically near obstacles).
inline constexpr double kDropSlack = 0.15;
// m: when the progress monitor fires with the centre this close to the boundary of its mapped
// freespace F_k, the robot backs out before a guide is planned. In discrete time the law of [7]
// can bring the centre onto ∂F_k (the safety filter keeps it in the closed LF(y)); there, where
// two convex pieces of a cluster meet, LF(y) shrinks to a wedge at y and every goal beyond it
// projects onto y itself: the robot stands still whatever its goal.
inline constexpr double kContactClearance = 0.02;
// m: a checked step (back-up, turn, track, withdrawal) that would end closer than this to what is
// known must not bring the robot or the carried object any closer than it is (step_clear).
inline constexpr double kStepClearance = 1e-3;
// rad: RobustParams::face turns until the bearing error to the law's goal is below this.
inline constexpr double kFaceTolerance = 0.05;
// m: RobustParams::narrow grows every movable object by these in turn, the first check that
// says objects separate x* names them.
inline constexpr double kNarrowSlacks[] = {0.05, 0.1, 0.2};
// Headings RobustParams::escape tries, evenly spaced, and the m between the clearance samples
// along each straight escape.
inline constexpr int kEscapeHeadings = 32;
// m: a looked-ahead back-up move of the pair must end at least this much clearer than the last
// best (and than where the pair stands) to be chosen (RobustParams::escape).
inline constexpr double kPairMoveGain = 1e-3;
// The pair's back-ups of an action after this many are looked ahead (RobustParams::escape); the
// first ones take the first move away. Looking ahead from the first back-up on completed 8 more
// trials of a 480-trial sweep and lost 10, most to a model point outside the model freespace.
inline constexpr int kPairLookaheadAfter = 2;
inline constexpr double kEscapeSample = 0.02;
// m of extra clearance each failed guide path asks of the next (RobustParams::widen).
inline constexpr double kGuideWiden = 0.1;
// Sides of the polygon about the robot's (or pair's) disk by which RobustParams::memory dilates
// what has been seen of an unknown obstacle (a superset of the round dilation by 2 %).
inline constexpr int kSeenDilationSides = 16;
// m closer to x* than at every earlier guide for RobustParams::persist to renew the guide budget.
inline constexpr double kPersistProgress = 0.5;

struct RobustParams {
  // When the progress monitor fires, follow waypoints of a path in the known freespace
  // (guide_path.h) instead of ending the action stuck, up to GuideParams::max_recoveries times.
  bool guide = true;
  // Keep clusters the diffeomorphism cannot purge, or where Dh turns singular or h takes a
  // centre inside F_k into a model obstacle, as convex pieces
  // (ReactiveController::set_convex_fallback) instead of ending the action stuck.
  bool convex_fallback = true;
  // When the robot's (or pair's) centre is not in its freespace (a grasp beside a wall, a
  // push), move off by back_out_step instead of ending the action stuck: straight back, else
  // straight ahead, else (carrying) a turn in place, whichever keeps the robot and the object
  // clear and moves the centre away from what it touches.
  bool back_out = true;
  double back_out_step = 0.3;  // m per back-out
  // m added to the robot's radius in every freespace the interface layer and the reactive
  // controller compute (topology checks, mapped spaces), so the law's boundary keeps the robot
  // this far from what it knows: [7] keeps the robot inside F_k but lets it slide along ∂F_k,
  // i.e. in contact, once clusters leave it only gaps to pass. 0 in the paper variant.
  double contact_margin = 0.01;
  // DISASSEMBLE drops the object at the nearest point of the pair's freespace that is clear of
  // every region and kDropClearance (r + max ρ) from everything known (guide_path.h,
  // nearest_clear_point), and stops early only there; in a pocket where none is reachable, the
  // nearest at a lower level of kDropLevels, then the clearest reachable point; the paper's
  // target (an edge midpoint of F, i.e. against an obstacle or the boundary) when none is.
  // A drop point that newly seen fragments take is chosen again, kMaxDropRetargets times per
  // action; then the paper's target and early stop serve (eight points in turn taken across
  // unexplored clutter, measured: better a drop near the robot than a stuck task), and when the
  // visible fragments cut that target off too, the object is released where the pair stands if
  // it is clear of every region (drop_short). In Fix mode the drop point also keeps off the paths
  // of the ways Fix mode was entered to open (Context::fix_ways, targets.h way_path) (measured:
  // five objects picked up and dropped back in the same spots, round after round, until the
  // Fix-mode bound ended the action).
  bool drop = true;
  // When the progress monitor fires during RELEASE and the carried object's centre already lies
  // in the goal region, goal_tolerance inside it, the object is released there (the predicate
  // holds anywhere in the region; the paper drives the pair to the region's centroid, §IV,
  // which a pocket or a cluster can make unreachable). Before the guide. Likewise a
  // DISASSEMBLE still pressed against a dilation after every back-up releases its object where
  // it stands, when the object is clear of every region (drop_short): DISASSEMBLE has only to
  // take the object out of the way, and an object Fix mode can move again is better than a
  // wedged pair (measured: a pair pushed into a corner beside its drop point).
  bool early_release = true;
  // When the mission is accepting, release again into its region every object an LTL RELEASE
  // placed and Fix mode later moved away (the formula holds, the end state would not).
  bool restore = true;
  // After the gripper closes, back straight out along the docking line (the way the robot came)
  // to the first point where the pair's centre is withdraw_clearance clear of its dilated
  // surroundings, looked ahead up to withdraw_max (else to where it is clearest): an object
  // gripped in a pocket's mouth or between obstacles is pulled out before the law of [7] steers
  // the pair, which otherwise drives on into the pocket, where the pair cannot turn around.
  // Every step keeps the robot and the object clear of everything known; the paper starts the
  // pair's navigation where the grasp ended.
  bool withdraw = true;
  // When the topology check cuts ℓ's centroid (the paper's RELEASE target, §IV) off the pair,
  // by objects or by fixed obstacles, RELEASE(M, ℓ) takes the pair to the point of ℓ it
  // reaches now that keeps the object clearest of everything known (interface_layer.h,
  // release_point), at least r + pair margin + 2 goal tolerances inside ℓ: the predicate holds
  // anywhere in ℓ, and the paper would enter Fix mode or end the action infeasible. Taking that
  // point on every RELEASE instead (measured first) completed 3 fewer of the 108 variant
  // trials and none more: a centroid the pair reaches is kept.
  bool release_point = true;
  // When neither ℓ's centroid nor a release point (release_point) lies in the pair's freespace
  // (ℓ about a pair's width, beside a wall or among objects), RELEASE(M, ℓ) sets M down from a
  // pose (release_pose.h): the pair's centre goes to a lead-in point, then straight along a
  // heading h to x* = o − (r + dock gap) h, so that M's centre lands on o, kPoseInside within
  // ℓ; the gripper opens as soon as M's centre lies goal_tolerance within ℓ. The paper has
  // only the centroid and ends the action infeasible (measured: 16 of 22 failures of an N = 8
  // crowded sweep, every obstacle familiar, were such RELEASEs beside a wall).
  bool release_pose = true;
  // When a GRASP finds no side of its object, or a RELEASE no pose in ℓ, that the movable
  // objects leave free, and the fixed obstacles alone leave one, the objects in its way
  // (within its dock, pair or stretch clearance, or separating it from the robot) go to Fix
  // mode (recovery_object_blockers.cpp), and Fix mode's drop points keep clear of that side
  // or pose (Context::keep_clear). The paper's topology check names only objects that
  // separate x* from the robot (Appendix III); an object lying on x* or beside it makes the
  // action infeasible (measured: 19 of 45 refused actions of crowded instances whose
  // certificate holds, every obstacle familiar).
  // With it, B_M of a verdict "blocked by objects" is cut down to a minimal subset whose removal
  // leaves x* reachable (blockers.h, minimal_blockers): Appendix III names every object of each
  // separating cluster, and where objects crowd one cluster holds most of them (measured: Fix
  // mode stacks past 2(N + 1) actions in 13 of 60 N = 16 crowded trials).
  bool object_blockers = true;
  // Familiar obstacles dilated with the miter limit kBevelMiterLimit (every convex corner
  // bevelled on the tangent of the disk dilation, as near as a polygon stays a superset of it)
  // in every freespace the interface layer and the controller compute, instead of
  // geometry::kMiterLimit (the mitered offset of reactive.md §2, the paper variant's): a right
  // angle's miter reaches √2 (r + ρ) from the corner, and two such corners facing across a
  // passage close it for the pair where the round dilation of the instance generator's
  // certificate leaves it open.
  bool bevel = true;
  // When the progress monitor fires during GRASP with the robot within kEarlyDockReach of the
  // object's approach circle, and docking straight from where it stands passes the checks of
  // grasp_candidates (interface_layer.h, grasp_from), the grasp aligns and docks from there
  // instead of following a guide to the chosen approach point: the law stalls beside the
  // object's dilation, a few centimetres along the circle from that point (measured: 0.16 m on
  // a corpus instance, four guides spent). Before the guide.
  bool early_dock = true;
  // After a back-up, turn in place toward the law's goal (kFaceTolerance) before the law
  // resumes: the unicycle law of [7] drives backward toward a goal behind the robot, and a
  // back-up ends facing away from where it came, so the law drove the robot straight back onto
  // the rest point it had backed out of (measured: 9 of the variants sweep's 18 failures completed
  // with it alone, 2 of its successes were lost).
  bool face = true;
  // When the law and every guide failed although the topology check finds x* reachable, the
  // objects that narrow the passage (found with every object grown by kNarrowSlacks) are
  // moved by Fix mode, as if they blocked it: a robot that released an object in a pocket and
  // stands behind it has a gap of about 10 cm past it, which the law does not get through.
  bool narrow = true;
  // Guide paths are followed straight, segment by segment (path_tracker.h), every step checked
  // against everything known, instead of as goals of the law: in a familiar obstacle's concavity
  // the law drove the robot back to the same point whatever waypoint it was given (measured).
  // The law takes over where a tracked step would not be clear.
  bool track = true;
  // A back-up of the robot alone (no object carried) goes along the clearest straight line of
  // back_out_step: of kEscapeHeadings directions, the one whose straight move stays clear of
  // everything known and ends farthest from it; the robot turns in place to it (or to its
  // reverse, whichever turn is shorter) first. The paper's heading alone offers two directions,
  // both into the walls when the law has pressed the robot into the apex of a concavity
  // (measured: the robot stayed there through four back-ups). Turning in place keeps a disk
  // robot where it is. Carrying, the pair's back-up is the move, of straight back or ahead,
  // turns in place and arcs back or ahead either way, whose look-ahead over back_out_step ends
  // with the pair centre clearest (clearest_pair_move), from the back-up after
  // kPairLookaheadAfter in an action on; before it, and without escape, the first of the
  // straight moves and turns that takes the centre away at its first step, which drove a pair
  // wedged between two obstacles back and forth between them (measured).
  bool escape = true;
  // Each guide path after a failed one (the progress monitor fired again while following it)
  // avoids what is closer than kGuideWiden more to ∂F_k than the last did (GuideParams::avoid),
  // except near the robot and x*, and falls back to the plain path when that finds none. The
  // plain A* takes the shortest way every time: measured, a pair that stalled at an object
  // dropped in a passage was guided into the same passage four times while a wide way round
  // was free. The paper has no guide.
  bool widen = true;
  // When the reactive controller finds x* cut off from the centre although the topology check
  // (familiar obstacles and objects only, paper Appendix III) found it reachable, visible
  // unknown fragments close the way, alone or together with objects: the check runs again with
  // the fragments as fixed obstacles, and objects that close the way with them are moved by Fix
  // mode (once per action). Measured: a RELEASE whose region lay past a gap between an unknown
  // obstacle and an object released earlier ended infeasible, the object never named. When the
  // check finds x* reachable, it runs again with the objects grown (grown_blockers), as
  // `narrow` does; and GRASP tries first the sides clear of the visible fragments.
  bool fragments = true;
  // Guide paths keep out of what has been seen of each unknown obstacle so far (the convex hull
  // of its fragments, perception::SemanticMap::seen, dilated by the mapped space's radius), not
  // only out of the fragments visible now: the law of [7] and F_k see the visible fragments
  // alone, so a guide planned after the robot had left a pocket of unknown obstacles led it back
  // into the same pocket (measured: most of the sweep's "revisited" failures). The hull lies in
  // the obstacle (it is convex), so a path it blocks is blocked; when it leaves none, the guide
  // runs in F_k alone, and (with `fragments`) the topology check runs again with the hulls as
  // fixed obstacles: objects that close every way together with remembered obstacles go to Fix
  // mode (measured: a pair shuttled between two passages, each closed by an unknown obstacle out
  // of sight from the other, one of them together with an object released earlier).
  bool memory = true;
  // The guide budget (GuideParams::max_recoveries) counts only guides that brought no progress:
  // when the progress monitor fires with the centre kPersistProgress closer to x* than at every
  // earlier guide of the action, the budget starts again. In dense clutter the way to x* runs
  // past unknown obstacles that the sensor reveals one at a time, each a new rest point of the
  // law; four guides ended such journeys half way (measured: most of the sweep's "revisited"
  // failures at density 0.35). The best distance drops by kPersistProgress at each renewal, so
  // an action still ends.
  bool persist = true;
  // A DISASSEMBLE whose drop point the law and every guide failed to reach chooses another one
  // (the failed point and its surroundings rejected, as for a point a fragment took), up to
  // kMaxRedrops per action, instead of ending stuck: the drop point is the interface
  // layer's choice (paper §V-B), not the task's, and the nearest clear point may lie past a
  // wall of unknown obstacles the robot had not seen when it chose it.
  bool redrop = true;
  // Deferred rebuilds (docs/executive.md "Deferred rebuilds"): a new map version rebuilds the
  // diffeomorphism only once what the map newly marks as obstacle (map_news.h) lies within
  // rebuild_margin of the disk the law keeps clear (the robot's, or the pair's, dilation
  // radius about its centre); until then the law runs on the previous build, whose obstacles
  // near the robot are those of the current map. The paper rebuilds at every map change: the
  // sensor reports new fragment parts at about its range R, where they do not yet constrain the
  // robot, and each rebuild costs milliseconds (the mapped space's exact Booleans, the
  // partitions and trees of the diffeomorphism).
  bool defer = true;
  double rebuild_margin = 1.0;       // m beyond the dilation radius
  double withdraw_clearance = 0.25;  // m beyond the pair's dilation radius
  double withdraw_max = 1.0;         // m of straight reverse travel at most
  int max_back_outs = 4;             // per action
};

// RobustParams' switches by registry key (core/switches.h): every switch the registry places in
// the executive, each once (tests/core/switches_test checks both ways).
struct RobustFlag {
  const char* key;
  bool RobustParams::*flag;
};
inline constexpr RobustFlag kRobustFlags[] = {{"guide", &RobustParams::guide},
                                              {"convex_fallback", &RobustParams::convex_fallback},
                                              {"back_out", &RobustParams::back_out},
                                              {"restore", &RobustParams::restore},
                                              {"drop", &RobustParams::drop},
                                              {"early_release", &RobustParams::early_release},
                                              {"withdraw", &RobustParams::withdraw},
                                              {"release_point", &RobustParams::release_point},
                                              {"release_pose", &RobustParams::release_pose},
                                              {"object_blockers", &RobustParams::object_blockers},
                                              {"bevel", &RobustParams::bevel},
                                              {"early_dock", &RobustParams::early_dock},
                                              {"face", &RobustParams::face},
                                              {"narrow", &RobustParams::narrow},
                                              {"track", &RobustParams::track},
                                              {"escape", &RobustParams::escape},
                                              {"widen", &RobustParams::widen},
                                              {"fragments", &RobustParams::fragments},
                                              {"memory", &RobustParams::memory},
                                              {"persist", &RobustParams::persist},
                                              {"redrop", &RobustParams::redrop},
                                              {"defer", &RobustParams::defer}};

// How often each recovery of the robust variant fired in a run.
struct RecoveryCounts {
  int guides = 0;          // guide paths followed after the progress monitor fired
  int back_outs = 0;       // straight back-ups out of a dilation
  int singular = 0;        // actions switched to convex pieces (singular Dh, y outside F)
  int fallbacks = 0;       // rebuilds that kept clusters as convex pieces
  int restores = 0;        // objects released into their regions again after Fix mode moved them
  int early_releases = 0;  // RELEASEs ended short of the centroid with the object in the region
  int withdrawals = 0;     // grasps that backed the pair out of a narrow place
  int release_points = 0;  // RELEASEs sent elsewhere in the region, its centroid cut off
  int release_poses = 0;   // RELEASEs set down from a pose, no heading-free point reachable
  int object_fixes = 0;    // Fix-mode entries for objects on a grasp side or a release pose
  int early_docks = 0;     // GRASPs docked from where the robot stalled beside the object
  int faces = 0;           // turns toward the goal after a back-up
  int narrows = 0;         // Fix-mode entries for objects narrowing a passage the law failed
  int redrops = 0;         // drop points chosen again after the law and every guide failed
  int fragment_fixes = 0;  // Fix-mode entries for objects closing the way with unknown obstacles
  int pocket_drops = 0;    // DISASSEMBLE drop points chosen where nothing is clear (a pocket)
};

// Each count's name in metrics.json and trials.csv, in column order.
struct RecoveryField {
  const char* name;
  int RecoveryCounts::*count;
};
inline constexpr RecoveryField kRecoveryFields[] = {
    {"guides", &RecoveryCounts::guides},
    {"back_outs", &RecoveryCounts::back_outs},
    {"singular_switches", &RecoveryCounts::singular},
    {"convex_fallbacks", &RecoveryCounts::fallbacks},
    {"restores", &RecoveryCounts::restores},
    {"early_releases", &RecoveryCounts::early_releases},
    {"withdrawals", &RecoveryCounts::withdrawals},
    {"release_points", &RecoveryCounts::release_points},
    {"release_poses", &RecoveryCounts::release_poses},
    {"object_fixes", &RecoveryCounts::object_fixes},
    {"early_docks", &RecoveryCounts::early_docks},
    {"faces", &RecoveryCounts::faces},
    {"narrows", &RecoveryCounts::narrows},
    {"fragment_fixes", &RecoveryCounts::fragment_fixes},
    {"pocket_drops", &RecoveryCounts::pocket_drops},
    {"redrops", &RecoveryCounts::redrops}};

struct ExecutiveParams {
  double robot_radius = 0.2;  // r (m)
  reactive::DiffeoParams diffeo;
  reactive::NavParams nav;
  GraspParams grasp;
  ProgressParams progress;
  RobustParams robust;
  GuideParams guide;
  double goal_tolerance = 0.05;        // m: MOVE, RELEASE, DISASSEMBLE reach x*
  double grasp_goal_tolerance = 0.01;  // m: the robot reaches the grasp approach point
  double align_tolerance = 1e-3;       // rad: the gripper faces the object
  double dock_speed = 0.05;            // m/s
  double backoff_speed = 0.1;          // m/s
  // After a release the robot backs off until its centre is this far (m) outside the released
  // object's dilated polygon (circumradius (ρ_i + r)/cos(π/32)).
  double backoff_margin = 0.01;
  double phase_timeout = 30;  // s allowed for align, dock and back off
  int max_fix_rounds = 8;     // Fix mode entries per LTL action
  // LTL actions after which the task ends (0: none): completed when the mission is then
  // accepting (a patrol run for a fixed number of visits), timeout otherwise.
  int max_ltl_actions = 0;
};

// Throws rearm::Error naming the first invalid field.
void validate(const ExecutiveParams& p);

// Wall time (s) the executive spent in each part of its work, for the compute split of a run:
// the mission controller's decisions and reports (paper §III), the topology checks and the
// freespaces the interface layer derives from them (Appendix III), and the diffeomorphism
// rebuilds of the reactive controller ([7], Appendix II). The rest of Executive::step is
// control (the law's evaluation, phases, targets).
struct ComputeTimes {
  double mission_s = 0;
  double topology_s = 0;
  double rebuild_s = 0;
};

}  // namespace rearm::executive
