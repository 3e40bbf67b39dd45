// The closed loop's checked mode (executive/task_runner.h, TaskOptions::check_invariants):
// passive where the invariants hold (the same actions, times and poses as an unchecked run), and
// a clear InvariantViolation where they break. Truth: an overlap injected into the plant's
// ground-truth clearance (below and beyond Box2D's slop), and the model freespace test against
// exact disk and half-plane geometry.
#include <gtest/gtest.h>

#include <string>

#include "core/error.h"
#include "executive/kinematic_plant.h"
#include "executive/task_runner.h"
#include "reactive/model_space.h"
#include "support/task_scenes.h"

namespace rearm::executive {
namespace {

// The kinematic plant with `overlap` m subtracted from its clearance from step `from` on.
class OverlappingPlant final : public Plant {
 public:
  OverlappingPlant(const TaskSpec& spec, const Pose& start, int from, double overlap)
      : inner_(spec.world, spec.executive.robot_radius, start), from_(from), overlap_(overlap) {}
  Pose pose() const override { return inner_.pose(); }
  Point object_center(std::size_t i) const override { return inner_.object_center(i); }
  std::size_t object_count() const override { return inner_.object_count(); }
  bool grip(std::size_t i) override { return inner_.grip(i); }
  void release() override { inner_.release(); }
  std::optional<std::size_t> held() const override { return inner_.held(); }
  void step(const Twist& u, double dt) override {
    inner_.step(u, dt);
    ++steps_;
  }
  double clearance() const override {
    return steps_ >= from_ ? std::min(inner_.clearance(), -overlap_) : inner_.clearance();
  }
  int collisions() const override { return inner_.collisions(); }

 private:
  KinematicPlant inner_;
  int steps_ = 0;
  int from_;
  double overlap_;
};

TEST(CheckedMode, PassiveWhereTheInvariantsHold) {
  const TaskSpec spec = test_support::fig4_task();
  KinematicPlant plain(spec.world, spec.executive.robot_radius, test_support::fig4_start());
  KinematicPlant checked_plant(spec.world, spec.executive.robot_radius, test_support::fig4_start());
  TaskOptions checked;
  checked.check_invariants = true;
  const TaskResult a = run_task(spec, plain);
  const TaskResult b = run_task(spec, checked_plant, checked);
  ASSERT_EQ(a.status, TaskStatus::kCompleted) << a.reason;
  EXPECT_EQ(b.status, a.status);
  EXPECT_EQ(b.sim_time, a.sim_time);
  ASSERT_EQ(b.actions.size(), a.actions.size());
  for (std::size_t i = 0; i < a.actions.size(); ++i) {
    EXPECT_EQ(b.actions[i].action, a.actions[i].action);
  }
  EXPECT_EQ(b.path.back().x, a.path.back().x);
}

TEST(CheckedMode, AnOverlapBeyondTheSlopEndsTheRunNamingIt) {
  const TaskSpec spec = test_support::fig4_task();
  TaskOptions o;
  o.check_invariants = true;
  OverlappingPlant deep(spec, test_support::fig4_start(), 200, 2 * kInvariantSlop);
  try {
    run_task(spec, deep, o);
    ADD_FAILURE() << "an overlap of twice the slop went unreported";
  } catch (const InvariantViolation& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("overlaps"), std::string::npos) << what;
    EXPECT_NE(what.find("t = 2 s"), std::string::npos) << what;  // step 200 of 0.01 s
  }
  // Within the slop (Box2D's contact solver allows that much): no violation; unchecked, the same
  // overlap is only a clearance in the result.
  OverlappingPlant shallow(spec, test_support::fig4_start(), 200, 0.5 * kInvariantSlop);
  EXPECT_EQ(run_task(spec, shallow, o).status, TaskStatus::kCompleted);
  OverlappingPlant unchecked(spec, test_support::fig4_start(), 200, 2 * kInvariantSlop);
  const TaskResult r = run_task(spec, unchecked);
  EXPECT_EQ(r.min_clearance, -2 * kInvariantSlop);
}

TEST(CheckedMode, ModelFreespaceAgainstExactGeometry) {
  reactive::ModelSpace m;
  m.boundary.vertices = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  m.disks.push_back({{3, 3}, 1});
  m.convex.push_back(geometry::Polygon{{{6, 6}, {8, 6}, {8, 8}, {6, 8}}});
  EXPECT_FALSE(reactive::outside_model_freespace(m, {5, 5}));
  EXPECT_FALSE(reactive::outside_model_freespace(m, {4.01, 3}));  // 1 cm outside the disk
  EXPECT_TRUE(reactive::outside_model_freespace(m, {4, 3}));      // on the disk
  EXPECT_TRUE(reactive::outside_model_freespace(m, {3.5, 3.5}));  // inside it
  EXPECT_TRUE(reactive::outside_model_freespace(m, {7, 7}));      // inside the square
  EXPECT_TRUE(reactive::outside_model_freespace(m, {6, 7}));      // on its edge
  EXPECT_FALSE(reactive::outside_model_freespace(m, {5.99, 7}));
  EXPECT_TRUE(reactive::outside_model_freespace(m, {0, 5}));  // on the boundary
  EXPECT_TRUE(reactive::outside_model_freespace(m, {-1, 5}));
  EXPECT_TRUE(reactive::outside_model_freespace(m, {5, std::nan("")}));
}

}  // namespace
}  // namespace rearm::executive
