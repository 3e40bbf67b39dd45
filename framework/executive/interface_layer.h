// The interface layer's geometric choices (paper §IV and §V-B; docs/executive.md, "Actions"
// and "Fix mode"): where the robot goes for each action, which side of an object it grips
// from, where it disassembles a blocking object to, and when it may stop early. The state
// machine that sequences them is executive.h.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "executive/region.h"
#include "geometry/polygon.h"
#include "perception/semantic_map.h"

namespace rearm::executive {

using geometry::Point;

// Signed clearance (m) of point x from everything the semantic map knows: the workspace
// boundary, the localized familiar obstacles, the visible unknown fragments and the movable
// obstacles (not the carried object), except object `except`. Negative inside any of them.
double known_clearance(const perception::SemanticMap& map, const Point& x,
                       std::string_view except = {});
// As known_clearance without the movable objects: the workspace boundary, the localized
// familiar obstacles and the visible unknown fragments.
double fixed_clearance(const perception::SemanticMap& map, const Point& x);
// Whether a geometric choice counts the movable objects as obstacles (the plan), or leaves
// them out (what the fixed obstacles alone allow; the objects in the way go to Fix mode).
enum class Objects { kCounted, kIgnored };

// GRASP(M_i): where the robot stands before gripping (paper §IV: "a collision-free location on
// the boundary of object M_i, contained in the freespace F").
struct GraspParams {
  int samples = 72;        // candidate directions around the object
  double standoff = 0.02;  // m beyond the dilated boundary ρ_i + r: the approach point
  double dock_gap = 1e-3;  // m: the gripper closes this far from contact
  // m added to the pair radius r + ρ_i for every pair computation (topology, mapped space):
  // covers the dock gap and the alignment tolerance, by which the gripped object sits off the
  // pair disk's nominal position.
  double pair_margin = 5e-3;
};

struct GraspCandidate {
  Point approach;     // robot centre before docking, on the circle ρ_i + r + standoff
  Point contact;      // robot centre when the gripper closes (gap dock_gap)
  Point pair_center;  // centre of the robot–object pair disk once gripped
  double distance;    // from the robot's current position to `approach`
};

// Candidates around object `object` (its true disk, map.object()), nearest to `robot` first,
// keeping those whose docking segment (approach → contact) keeps the robot clear (known
// clearance >= r, the object itself excepted) and whose pair disk (radius r + ρ_i +
// pair_margin) is clear of everything known but the object (with Objects::kIgnored, of the
// fixed obstacles alone). Membership in the exact freespaces is left to the caller. Throws
// rearm::Error for an unknown object or invalid parameters.
std::vector<GraspCandidate> grasp_candidates(const perception::SemanticMap& map,
                                             std::string_view object, double robot_radius,
                                             const Point& robot, const GraspParams& p,
                                             Objects objects = Objects::kCounted);

// The grasp with the robot where it stands as the approach point (docking straight toward the
// object's centre), under the same checks as grasp_candidates: the robust variant's early dock.
// nullopt when a check fails or the robot is within dock_gap of contact.
std::optional<GraspCandidate> grasp_from(const perception::SemanticMap& map,
                                         std::string_view object, double robot_radius,
                                         const Point& robot, const GraspParams& p);

// DISASSEMBLE(M_i, x*) target (paper §V-B): the midpoint of the edge of the pair's freespace F
// that maximizes the minimum distance to every other movable object (disk boundary) and every
// region of interest (0 inside one). Each midpoint is moved `inset` (m) into F along the edge's
// inward normal when that point is still in F (the reactive controller then needs no boundary
// snap), and candidates whose point is not clear of the visible unknown fragments by
// pair_radius are skipped (F ignores unknown obstacles, the reactive mapped space does not).
// Ties go to the first edge (outer boundary first, counter-clockwise). nullopt when F has no
// usable edge.
// Disks in `keep` (RobustParams::object_blockers: a grasp side or release pose being cleared)
// count in the score as the objects do.
inline constexpr double kDisassembleInset = 0.01;
std::optional<Point> disassemble_target(const geometry::Region& freespace,
                                        const perception::SemanticMap& map,
                                        std::string_view carried,
                                        const std::vector<RegionOfInterest>& regions,
                                        double pair_radius, double inset = kDisassembleInset,
                                        const std::vector<geometry::Disk>& keep = {});

// RELEASE(M_i, ℓ) target of the robust variant (the predicate holds wherever in ℓ the object
// lies, §II-B; the paper drives the pair's centre to ℓ's centroid, §IV). Candidates: the points
// of a grid of spacing `step` (m) over ℓ that lie at least `inset` (m) inside ℓ (so the object,
// within inset of the pair's centre whatever the final heading, lands inside ℓ) and in the
// pair's freespace F (exact point location). Chosen: the candidate whose clearance from
// everything known but the carried object (known_clearance) is largest, counted up to `enough`
// (m); among those reaching it, the one nearest the centroid, so that in the open the paper's
// point is kept and beside clutter the object is set down as far from it as ℓ allows. The
// centroid itself is a candidate (ties go to it). nullopt when no candidate lies in F. A region
// that would need more than kMaxReleaseCandidates grid points gets a coarser step.
inline constexpr double kMaxReleaseCandidates = 1e5;
std::optional<Point> release_point(const geometry::Region& freespace,
                                   const RegionOfInterest& region,
                                   const perception::SemanticMap& map, std::string_view carried,
                                   double inset, double enough, double step);

// The disk (centre xc, radius `radius`) meets no region of interest.
bool clear_of_regions(const Point& xc, double radius, const std::vector<RegionOfInterest>& regions);

// Early stop of DISASSEMBLE (paper §V-B): the pair disk (centre xc, radius pair_radius)
// intersects no region of interest, and xc is at least 2(r + max_k ρ_k) from every other
// object. rearm reads the paper's "all other objects in the workspace" as every obstacle the
// robot knows (movable objects, localized familiar obstacles, visible unknown fragments and the
// workspace boundary): with movable objects alone, an object blocking a corridor between two
// walls would be dropped where it was gripped and block again.
bool disassembly_done(const Point& xc, double pair_radius, double robot_radius,
                      const perception::SemanticMap& map, std::string_view carried,
                      const std::vector<RegionOfInterest>& regions);

}  // namespace rearm::executive
