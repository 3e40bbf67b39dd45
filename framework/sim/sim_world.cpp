// SimWorld on Box2D 2.4.1 (docs/experiments.md, "Box2D world"). Decisions:
// - Static shapes have no skin (m_radius = 0, Box2D's default is b2_polygonRadius = 1 cm), so a
//   Box2D contact starts where the exact shapes touch and the contact count agrees with the
//   exact clearance; a body pressed against a wall rests up to b2_linearSlop (5 mm) inside it,
//   as two pressed disks do.
// - The workspace boundary is one chain loop wound clockwise: chains are one-sided and collide
//   with what lies on the right of each edge, which for a clockwise loop is its inside.
// - Obstacles are convex pieces (convex_pieces.h) with their vertices checked in single
//   precision before b2PolygonShape::Set, and the vertex count Set kept checked after it.
// - The robot is a dynamic disk with fixed rotation: its velocity and ω are set before every step,
//   contacts stop its translation, and its heading follows the commanded ω. The velocity is the
//   chord velocity of the exact unicycle step over dt (v(cos ψ, sin ψ) when ω = 0, and to first
//   order in dt otherwise), so that Box2D's Euler step lands where executive::KinematicPlant's
//   exact step does. A held object is welded to it (stiffness 0: rigid) and gets the pair's
//   rigid-body velocity v + ω × (c − x), which satisfies the weld's velocity constraint.
// - Box2D integrates in float: at 5 m from the origin each step's c + h·v rounds by up to
//   2.4e-7 m, always the same way at a constant speed, which over 500 steps drifts ~1e-4 m; and
//   the Euler step of a welded pair turning at ω leaves the object h²ω²|c − x|/2 off its circle,
//   which the weld's position solver spreads over both bodies. The robot's pose is therefore
//   tracked in double (Impl::settle): a step in which nothing touched the robot or the held
//   object is the exact unicycle step with the object at its grip offset, Box2D decides
//   otherwise, and the bodies are re-anchored at the rounding of their poses after every step.
// - A collision is the start of touching between the robot (or the held object) and one thing
//   — the workspace boundary, an obstacle, an object — that neither was already touching: a
//   BeginContact that IsTouching() with no other touching contact to the same thing, so
//   touching two pieces of one obstacle, or two edges of a corner, is one collision.
#include "sim/sim_world.h"

#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.h"
#include "geometry/convex.h"
#include "geometry/distance.h"
#include "sim/convex_pieces.h"

namespace rearm::sim {
namespace {

// The static scene the clearance is measured against: the workspace and every familiar and
// unknown obstacle, validated.
struct StaticScene {
  geometry::Polygon workspace;
  std::vector<geometry::Polygon> obstacles;
};

static_assert(kMaxPieceVertices == b2_maxPolygonVertices,
              "convex_pieces.h must cut pieces to Box2D's b2_maxPolygonVertices");

// Radius of the skin of static shapes (see the file comment).
constexpr float kStaticSkin = 0.0f;
// Coulomb friction coefficient of every fixture (Box2D's default b2FixtureDef::friction).
constexpr float kFriction = 0.2f;
// Box2D's vertex welding distance in b2PolygonShape::Set: closer vertices become one.
constexpr float kWeldDistance = 0.5f * b2_linearSlop;
// A step's float displacement within this many float epsilons (relative to the coordinates) of
// h·v is pure integration: the rounding of c + h·v is at most one half ulp per coordinate, while
// Box2D's position corrections that matter are far larger.
constexpr double kIntegrationUlps = 4;

// What a fixture belongs to, stored in its user data: the kind in the low bits, the index of the
// obstacle or object above them. All pieces of one obstacle carry the same tag.
enum class Kind : std::uintptr_t { kBoundary = 1, kFamiliar, kUnknown, kObject, kRobot };
constexpr int kKindBits = 3;

std::uintptr_t tag(Kind kind, std::size_t index = 0) {
  return (static_cast<std::uintptr_t>(index) << kKindBits) | static_cast<std::uintptr_t>(kind);
}
Kind kind_of(std::uintptr_t t) { return static_cast<Kind>(t & ((1u << kKindBits) - 1)); }
std::size_t index_of(std::uintptr_t t) { return static_cast<std::size_t>(t >> kKindBits); }

b2Vec2 to_b2(const geometry::Point& p) {
  return b2Vec2(static_cast<float>(p.x()), static_cast<float>(p.y()));
}
geometry::Point from_b2(const b2Vec2& p) { return geometry::Point(p.x, p.y); }

std::string str(double x) {
  std::ostringstream os;
  os.precision(17);
  os << x;
  return os.str();
}
std::string str(const geometry::Point& p) { return "(" + str(p.x()) + ", " + str(p.y()) + ")"; }

bool finite_positive(double x) { return std::isfinite(x) && x > 0; }

geometry::Point rotate(const geometry::Point& p, double a) {
  const double c = std::cos(a), s = std::sin(a);
  return geometry::Point(c * p.x() - s * p.y(), s * p.x() + c * p.y());
}

// sin(a)/a, by its Taylor series 1 − a²/6 + a⁴/120 below kSincSeries (truncation < a⁶/5040).
constexpr double kSincSeries = 1e-4;
double sinc(double a) {
  if (std::abs(a) < kSincSeries) return 1 - a * a / 6 + a * a * a * a / 120;
  return std::sin(a) / a;
}

// Exact solution of ẋ = v(cos ψ, sin ψ), ψ̇ = ω over dt: the chord of an arc of radius v/ω,
// of length v·dt·sinc(ω·dt/2) along the mean heading ψ + ω·dt/2 (reactive::unicycle_step, which
// sim/ may not include). The heading is not wrapped.
Pose unicycle_step(const Pose& p, double v, double omega, double dt) {
  const double half = 0.5 * omega * dt;
  const double mid = p.psi + half;
  return Pose{p.x + v * dt * sinc(half) * geometry::Point(std::cos(mid), std::sin(mid)),
              p.psi + omega * dt};
}

void check_config(const SimConfig& c) {
  if (!finite_positive(c.dt)) throw Error("sim: dt must be finite and > 0, got " + str(c.dt));
  if (c.velocity_iterations < 1 || c.position_iterations < 1) {
    throw Error("sim: velocity and position iterations must be >= 1, got " +
                std::to_string(c.velocity_iterations) + " and " +
                std::to_string(c.position_iterations));
  }
  if (!std::isfinite(c.object_linear_damping) || c.object_linear_damping < 0 ||
      !std::isfinite(c.object_angular_damping) || c.object_angular_damping < 0) {
    throw Error("sim: object damping must be finite and >= 0, got " + str(c.object_linear_damping) +
                " (linear) and " + str(c.object_angular_damping) + " (angular)");
  }
  if (!finite_positive(c.object_density) || !finite_positive(c.robot_density)) {
    throw Error("sim: densities must be finite and > 0, got " + str(c.object_density) +
                " (objects) and " + str(c.robot_density) + " (robot)");
  }
  if (!std::isfinite(c.grip_reach) || c.grip_reach < 0) {
    throw Error("sim: grip_reach must be finite and >= 0, got " + str(c.grip_reach));
  }
  if (!std::isfinite(c.grip_cone) || c.grip_cone < 0 || c.grip_cone > std::numbers::pi) {
    throw Error("sim: grip_cone must lie in [0, pi], got " + str(c.grip_cone));
  }
}

// The vertices b2PolygonShape::Set receives for a convex piece, such that it keeps all of them:
// no two closer than Box2D's weld distance (an error: that would change the shape by
// millimetres), and every turn strictly left in float arithmetic (b2Cross > 0, Set's hull test);
// a vertex that is collinear only after rounding to float is dropped, which moves the boundary
// by the rounding alone.
std::vector<b2Vec2> box2d_vertices(const geometry::Polygon& piece, const std::string& what) {
  std::vector<b2Vec2> v;
  for (const geometry::Point& p : piece.vertices) v.push_back(to_b2(p));
  for (std::size_t i = 0; i < v.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (b2DistanceSquared(v[i], v[j]) < kWeldDistance * kWeldDistance) {
        throw Error("sim: " + what + ": vertices " + str(piece.vertices[j]) + " and " +
                    str(piece.vertices[i]) + " of a convex piece are closer than Box2D's weld " +
                    "distance " + str(kWeldDistance) + " m");
      }
    }
  }
  bool changed = true;
  while (changed && v.size() >= 3) {
    changed = false;
    for (std::size_t i = 0; i < v.size(); ++i) {
      const b2Vec2& a = v[(i + v.size() - 1) % v.size()];
      const b2Vec2& c = v[(i + 1) % v.size()];
      if (b2Cross(v[i] - a, c - v[i]) <= 0.0f) {
        v.erase(v.begin() + static_cast<std::ptrdiff_t>(i));
        changed = true;
        break;
      }
    }
  }
  if (v.size() < 3) throw Error("sim: " + what + ": a convex piece is degenerate in float");
  return v;
}

// Box2D 2.4.1 fills its process-wide table of contact functions (b2Contact::s_registers) on the
// first contact any world creates, behind an unsynchronized flag. Creating one contact here,
// under the thread-safe initialization of a function-local static, means concurrent worlds only
// ever read the table. (Its other globals, b2_gjkCalls, b2_toiCalls and the like, are statistics
// that nothing reads back.)
bool contact_table_ready() {
  static const bool ready = [] {
    b2World w(b2Vec2(0.0f, 0.0f));
    b2CircleShape circle;
    circle.m_radius = 1.0f;
    for (int k = 0; k < 2; ++k) {
      b2BodyDef bd;
      bd.type = b2_dynamicBody;
      w.CreateBody(&bd)->CreateFixture(&circle, 1.0f);
    }
    w.Step(0.01f, 1, 1);
    return w.GetContactCount() > 0;
  }();
  return ready;
}

}  // namespace

struct SimWorld::Impl : public b2ContactListener {
  SimConfig config;
  StaticScene scene;
  double robot_radius = 0;
  std::vector<geometry::Disk> objects;  // radii fixed; centres refreshed after every step

  std::unique_ptr<b2World> world;  // destroyed first: it points to this listener
  b2Body* ground = nullptr;
  b2Body* robot = nullptr;
  std::vector<b2Body*> object_bodies;
  b2Joint* weld = nullptr;
  geometry::Point x = geometry::Point::Zero();  // the robot's pose, tracked in double
  double psi = 0;
  geometry::Point grip_offset = geometry::Point::Zero();  // held object's centre, robot frame
  double grip_angle = 0;                                  // and its angle relative to ψ
  std::optional<std::size_t> held;
  // The object just released while it still touches the robot: their contact, which the weld
  // had suppressed, begins again after the release and is not a collision.
  std::optional<std::size_t> released;

  long long steps = 0;
  int collisions = 0;
  static constexpr std::size_t kMaxEvents = 100;
  std::vector<std::string> events;
  double clearance = 0;
  double min_clearance = 0;

  // --- b2ContactListener ---
  void BeginContact(b2Contact* contact) override {
    if (!contact->IsTouching()) return;
    const std::uintptr_t ta = contact->GetFixtureA()->GetUserData().pointer;
    const std::uintptr_t tb = contact->GetFixtureB()->GetUserData().pointer;
    const bool ma = moving(ta), mb = moving(tb);
    if (ma == mb) return;  // the robot and its held object, or neither of them
    const std::uintptr_t mover = ma ? ta : tb;
    const std::uintptr_t other = ma ? tb : ta;
    if (kind_of(mover) == Kind::kRobot && kind_of(other) == Kind::kObject && released &&
        index_of(other) == *released) {
      return;
    }
    if (touching_other_than(robot, other, contact)) return;
    if (held && touching_other_than(object_bodies[*held], other, contact)) return;
    ++collisions;
    if (events.size() < kMaxEvents) {
      char t[32];
      std::snprintf(t, sizeof t, "t = %.2f s: ", double(steps) * config.dt);
      events.push_back(t + describe(mover) + " touched " + describe(other));
    }
  }

  static std::string describe(std::uintptr_t t) {
    switch (kind_of(t)) {
      case Kind::kBoundary:
        return "the workspace boundary";
      case Kind::kFamiliar:
        return "familiar obstacle " + std::to_string(index_of(t));
      case Kind::kUnknown:
        return "unknown obstacle " + std::to_string(index_of(t));
      case Kind::kObject:
        return "object " + std::to_string(index_of(t));
      case Kind::kRobot:
        return "the robot";
    }
    return "?";
  }

  // The robot, or the object it holds.
  bool moving(std::uintptr_t t) const {
    return kind_of(t) == Kind::kRobot ||
           (kind_of(t) == Kind::kObject && held && index_of(t) == *held);
  }

  // Does body touch a fixture tagged `thing` through a contact other than `except`?
  static bool touching_other_than(b2Body* body, std::uintptr_t thing, const b2Contact* except) {
    for (b2ContactEdge* e = body->GetContactList(); e != nullptr; e = e->next) {
      b2Contact* c = e->contact;
      if (c == except || !c->IsTouching()) continue;
      if (c->GetFixtureA()->GetUserData().pointer == thing ||
          c->GetFixtureB()->GetUserData().pointer == thing) {
        return true;
      }
    }
    return false;
  }

  // Can the robot and object i touch at the next step's collision update: a touching contact
  // now, or Box2D's circle test (b2CollideCircles, in float) passes at the current positions?
  bool may_touch_robot(std::size_t i) const {
    if (touching_other_than(robot, tag(Kind::kObject, i), nullptr)) return true;
    const float rr = static_cast<float>(robot_radius) + static_cast<float>(objects[i].radius);
    return b2DistanceSquared(robot->GetPosition(), object_bodies[i]->GetPosition()) <= rr * rr;
  }

  // --- building ---
  void add_boundary(const geometry::Polygon& workspace) {
    std::vector<b2Vec2> v;
    for (auto it = workspace.vertices.rbegin(); it != workspace.vertices.rend(); ++it) {
      v.push_back(to_b2(*it));  // clockwise: the chain's solid side is the outside
    }
    for (std::size_t i = 0; i < v.size(); ++i) {
      const b2Vec2& next = v[(i + 1) % v.size()];
      if (b2DistanceSquared(v[i], next) <= b2_linearSlop * b2_linearSlop) {
        throw Error("sim: workspace: the edge from " + str(from_b2(v[i])) + " to " +
                    str(from_b2(next)) + " is not longer than Box2D's linear slop " +
                    str(b2_linearSlop) + " m");
      }
    }
    b2ChainShape chain;
    chain.CreateLoop(v.data(), static_cast<int32>(v.size()));
    b2FixtureDef fd;
    fd.shape = &chain;
    fd.friction = kFriction;
    fd.userData.pointer = tag(Kind::kBoundary);
    // b2ChainShape::Clone resets the radius to the default skin: set it on the fixture's copy.
    ground->CreateFixture(&fd)->GetShape()->m_radius = kStaticSkin;
  }

  void add_obstacle(const geometry::Polygon& polygon, Kind kind, std::size_t index,
                    const std::string& what) {
    for (const geometry::Polygon& piece : convex_pieces(polygon, what.c_str())) {
      const std::vector<b2Vec2> v = box2d_vertices(piece, what);
      b2PolygonShape shape;
      shape.Set(v.data(), static_cast<int32>(v.size()));
      if (shape.m_count != static_cast<int32>(v.size())) {
        throw Error("sim: " + what + ": Box2D kept " + std::to_string(shape.m_count) + " of the " +
                    std::to_string(v.size()) + " vertices of a convex piece");
      }
      b2FixtureDef fd;
      fd.shape = &shape;
      fd.friction = kFriction;
      fd.userData.pointer = tag(kind, index);
      ground->CreateFixture(&fd)->GetShape()->m_radius = kStaticSkin;
    }
  }

  b2Body* add_disk(const geometry::Point& center, double angle, double radius, double density,
                   std::uintptr_t user) {
    b2BodyDef bd;
    bd.type = b2_dynamicBody;
    bd.position = to_b2(center);
    bd.angle = static_cast<float>(angle);
    b2Body* body = world->CreateBody(&bd);
    b2CircleShape circle;
    circle.m_radius = static_cast<float>(radius);
    b2FixtureDef fd;
    fd.shape = &circle;
    fd.density = static_cast<float>(density);
    fd.friction = kFriction;
    fd.userData.pointer = user;
    body->CreateFixture(&fd);
    return body;
  }

  // --- measuring ---
  void refresh_objects() {
    for (std::size_t i = 0; i < objects.size(); ++i) {
      objects[i].center = from_b2(object_bodies[i]->GetPosition());
    }
  }

  double measure() const {
    double c =
        geometry::disk_clearance(scene.workspace, scene.obstacles, objects, x, robot_radius, held);
    if (held) {
      const geometry::Disk& d = objects[*held];
      c = std::min(c, geometry::disk_clearance(scene.workspace, scene.obstacles, objects, d.center,
                                               d.radius, held));
    }
    return c;
  }

  // Does the body touch anything (a contact that acted in the last step)?
  static bool touching(b2Body* body) {
    for (b2ContactEdge* e = body->GetContactList(); e != nullptr; e = e->next) {
      if (e->contact->IsTouching()) return true;
    }
    return false;
  }

  // The robot's pose in double (see the file comment) after a step from Box2D's p0 that was
  // meant to reach `target` (the exact unicycle step):
  //  - nothing touched the robot or the held object: the pose is `target`, and the held object
  //    sits at its grip offset from it (Box2D's Euler step of the welded pair errs by
  //    h²ω²|c − x|/2 per step, which the weld's position solver would spread over both bodies);
  //  - Box2D's float displacement is h·v for the velocity the solver left (a contact changed the
  //    velocity, no position correction): the pose advances by h·v in double;
  //  - otherwise (a position correction or a time of impact): the pose is Box2D's.
  // The bodies are then re-anchored at the rounding of their poses, so rounding never
  // accumulates.
  void settle(const b2Vec2& p0, const Pose& target) {
    const double h = static_cast<float>(config.dt);  // Box2D's step, as Box2D integrates it
    const b2Vec2 p1 = robot->GetPosition();
    const float a1 = robot->GetAngle();
    b2Body* carried = held ? object_bodies[*held] : nullptr;
    const bool free = !touching(robot) && !(carried && touching(carried));
    if (free) {
      x = target.x;
      psi = target.psi;
    } else {
      const double tol =
          kIntegrationUlps * std::numeric_limits<float>::epsilon() *
          std::max({1.0, std::abs(static_cast<double>(p1.x)), std::abs(static_cast<double>(p1.y))});
      const geometry::Point moved = from_b2(p1) - from_b2(p0);
      const geometry::Point solved = h * from_b2(robot->GetLinearVelocity());
      x = (moved - solved).lpNorm<Eigen::Infinity>() <= tol ? geometry::Point(x + solved)
                                                            : from_b2(p1);
      // Fixed rotation: only the commanded ω turns the robot.
      psi = target.psi;
    }
    // Heading within one turn of zero, where float resolves it to ~2e-7 rad; a held object in
    // contact turns back with it so that the weld's relative angle stays.
    if (std::abs(psi) > 2 * std::numbers::pi) {
      const double turns = std::round(psi / (2 * std::numbers::pi));
      psi -= turns * 2 * std::numbers::pi;
      if (carried && !free) {
        carried->SetTransform(
            carried->GetPosition(),
            static_cast<float>(carried->GetAngle() - turns * 2 * std::numbers::pi));
      }
    }
    const b2Vec2 anchor = to_b2(x);
    const float angle = static_cast<float>(psi);
    if (anchor.x != p1.x || anchor.y != p1.y || angle != a1) robot->SetTransform(anchor, angle);
    if (carried && free) {
      carried->SetTransform(to_b2(x + rotate(grip_offset, psi)),
                            static_cast<float>(psi + grip_angle));
    }
  }
};

SimWorld::SimWorld(const scenario::Scenario& s, const SimConfig& config)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  REARM_DEMAND(contact_table_ready(), "Box2D created no contact between overlapping disks");
  check_config(config);
  m.config = config;

  const scenario::Robot& r = s.robot;
  if (!finite_positive(r.radius)) {
    throw Error("sim: the robot radius must be finite and > 0, got " + str(r.radius));
  }
  if (!r.start.allFinite() || !std::isfinite(r.heading)) {
    throw Error("sim: the robot's start pose is not finite");
  }
  m.scene.workspace = geometry::remove_collinear(geometry::validated(s.workspace, "workspace"),
                                                 kCollinearTolerance);
  if (!geometry::contains(m.scene.workspace, r.start)) {
    throw Error("sim: the robot's start " + str(r.start) + " lies outside the workspace");
  }
  m.robot_radius = r.radius;
  for (const scenario::Object& o : s.objects) {
    if (!finite_positive(o.disk.radius) || !o.disk.center.allFinite()) {
      throw Error("sim: object '" + o.name + "' needs a finite centre and a finite radius > 0");
    }
    if (!geometry::contains(m.scene.workspace, o.disk.center)) {
      throw Error("sim: object '" + o.name + "' at " + str(o.disk.center) +
                  " lies outside the workspace");
    }
    m.objects.push_back(o.disk);
  }

  m.world = std::make_unique<b2World>(b2Vec2(0.0f, 0.0f));
  m.world->SetContactListener(&m);
  b2BodyDef ground;
  m.ground = m.world->CreateBody(&ground);
  m.add_boundary(m.scene.workspace);
  for (std::size_t i = 0; i < s.familiar.size(); ++i) {
    const std::string what = "familiar obstacle '" + s.familiar[i].name + "'";
    m.scene.obstacles.push_back(geometry::validated(s.familiar[i].polygon, what.c_str()));
    m.add_obstacle(m.scene.obstacles.back(), Kind::kFamiliar, i, what);
  }
  for (std::size_t i = 0; i < s.unknown.size(); ++i) {
    const std::string what = "unknown obstacle '" + s.unknown[i].name + "'";
    m.scene.obstacles.push_back(geometry::validated(s.unknown[i].polygon, what.c_str()));
    m.add_obstacle(m.scene.obstacles.back(), Kind::kUnknown, i, what);
  }

  for (std::size_t i = 0; i < m.objects.size(); ++i) {
    b2Body* b = m.add_disk(m.objects[i].center, 0, m.objects[i].radius, config.object_density,
                           tag(Kind::kObject, i));
    b->SetLinearDamping(static_cast<float>(config.object_linear_damping));
    b->SetAngularDamping(static_cast<float>(config.object_angular_damping));
    m.object_bodies.push_back(b);
  }
  m.robot = m.add_disk(r.start, r.heading, r.radius, config.robot_density, tag(Kind::kRobot));
  m.robot->SetFixedRotation(true);
  m.x = r.start;
  m.psi = r.heading;
  m.robot->SetSleepingAllowed(false);

  m.refresh_objects();
  m.clearance = m.measure();
  m.min_clearance = m.clearance;
}

SimWorld::~SimWorld() = default;

Pose SimWorld::pose() const {
  return Pose{impl_->x, std::remainder(impl_->psi, 2 * std::numbers::pi)};
}

geometry::Point SimWorld::object_center(std::size_t i) const {
  if (i >= impl_->objects.size()) {
    throw Error("sim: object index " + std::to_string(i) + " out of range (" +
                std::to_string(impl_->objects.size()) + " objects)");
  }
  return impl_->objects[i].center;
}

std::size_t SimWorld::object_count() const { return impl_->objects.size(); }

bool SimWorld::grip(std::size_t i) {
  Impl& m = *impl_;
  if (i >= m.objects.size()) {
    throw Error("sim: grip: object index " + std::to_string(i) + " out of range (" +
                std::to_string(m.objects.size()) + " objects)");
  }
  if (m.held) return false;
  const Pose p = pose();
  const geometry::Disk& d = m.objects[i];
  const geometry::Point rel = d.center - p.x;
  const double gap = rel.norm() - m.robot_radius - d.radius;
  if (gap > m.config.grip_reach) return false;
  const double bearing = std::remainder(std::atan2(rel.y(), rel.x()) - p.psi, 2 * std::numbers::pi);
  if (std::abs(bearing) > m.config.grip_cone) return false;

  b2WeldJointDef jd;
  jd.Initialize(m.robot, m.object_bodies[i], m.object_bodies[i]->GetPosition());
  jd.stiffness = 0.0f;  // rigid
  jd.damping = 0.0f;
  jd.collideConnected = false;
  m.weld = m.world->CreateJoint(&jd);
  m.held = i;
  m.released.reset();
  const double psi = m.psi;
  m.grip_offset = rotate(rel, -psi);
  m.grip_angle = m.object_bodies[i]->GetAngle() - psi;
  return true;
}

void SimWorld::release() {
  Impl& m = *impl_;
  if (!m.held) return;
  m.world->DestroyJoint(m.weld);
  m.weld = nullptr;
  b2Body* body = m.object_bodies[*m.held];
  // Re-enables the robot–object pair in the broad phase so their contact exists again.
  for (b2Fixture* f = body->GetFixtureList(); f != nullptr; f = f->GetNext()) f->Refilter();
  if (m.may_touch_robot(*m.held)) m.released = m.held;
  m.held.reset();
}

std::optional<std::size_t> SimWorld::held() const { return impl_->held; }

void SimWorld::step(double v, double omega) {
  Impl& m = *impl_;
  if (!std::isfinite(v) || !std::isfinite(omega)) {
    throw Error("sim: step: the command (v, omega) = (" + str(v) + ", " + str(omega) +
                ") is not finite");
  }
  const double dt = m.config.dt;
  if (std::abs(omega) * dt > b2_maxRotation) {
    throw Error("sim: step: |omega| = " + str(std::abs(omega)) + " rad/s turns more than " +
                "Box2D's b2_maxRotation " + str(b2_maxRotation) + " rad in one step of " + str(dt) +
                " s");
  }
  // The exact unicycle step over dt (an arc; executive::KinematicPlant takes the same one), the
  // constant velocity whose Euler step lands on it (the chord velocity; v(cos ψ, sin ψ) when
  // ω = 0), and the held object's rigid-body velocity for it, which the weld's velocity
  // constraint asks for.
  const Pose from{m.x, m.psi};
  const Pose target = unicycle_step(from, v, omega, dt);
  const geometry::Point vel = (target.x - from.x) / dt;
  geometry::Point held_vel = vel;
  if (m.held) {
    const geometry::Point rel = m.objects[*m.held].center - from.x;
    held_vel = vel + omega * geometry::Point(-rel.y(), rel.x());  // v + ω × (c − x)
  }
  if (std::max(vel.norm(), held_vel.norm()) * dt > b2_maxTranslation) {
    throw Error("sim: step: the speed " + str(std::max(vel.norm(), held_vel.norm())) +
                " m/s moves more than Box2D's b2_maxTranslation " + str(b2_maxTranslation) +
                " m in one step of " + str(dt) + " s");
  }

  m.robot->SetLinearVelocity(to_b2(vel));
  m.robot->SetAngularVelocity(static_cast<float>(omega));
  if (m.held) {
    b2Body* b = m.object_bodies[*m.held];
    b->SetLinearVelocity(to_b2(held_vel));
    b->SetAngularVelocity(static_cast<float>(omega));
  }
  const b2Vec2 p0 = m.robot->GetPosition();
  m.world->Step(static_cast<float>(dt), m.config.velocity_iterations, m.config.position_iterations);
  ++m.steps;
  m.settle(p0, target);
  if (m.released && !m.may_touch_robot(*m.released)) m.released.reset();
  m.refresh_objects();
  m.clearance = m.measure();
  m.min_clearance = std::min(m.min_clearance, m.clearance);
}

double SimWorld::time() const { return static_cast<double>(impl_->steps) * impl_->config.dt; }

int SimWorld::collisions() const { return impl_->collisions; }

std::vector<std::string> SimWorld::collision_events() const { return impl_->events; }

double SimWorld::clearance() const { return impl_->clearance; }

double SimWorld::min_clearance() const { return impl_->min_clearance; }

}  // namespace rearm::sim
