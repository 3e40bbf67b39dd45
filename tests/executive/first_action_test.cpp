// TaskResult::first_action_time, the compute before the robot's first act, checked against what
// the plant itself saw: a plant that notes the wall time at which it first received a command
// that moves the robot or the gripper. The compute before that act cannot exceed the wall time
// elapsed until the plant received it; a task whose plant never received one has none.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <optional>

#include "executive/kinematic_plant.h"
#include "executive/task_runner.h"
#include "support/task_scenes.h"

namespace rearm::executive {
namespace {

using Clock = std::chrono::steady_clock;

// The kinematic plant, noting when it was first asked to move or to grip or release.
class WatchingPlant final : public Plant {
 public:
  WatchingPlant(const TaskSpec& spec, const Pose& start)
      : inner_(spec.world, spec.executive.robot_radius, start) {}
  Pose pose() const override { return inner_.pose(); }
  Point object_center(std::size_t i) const override { return inner_.object_center(i); }
  std::size_t object_count() const override { return inner_.object_count(); }
  bool grip(std::size_t i) override {
    note();
    return inner_.grip(i);
  }
  void release() override {
    note();
    inner_.release();
  }
  std::optional<std::size_t> held() const override { return inner_.held(); }
  void step(const Twist& u, double dt) override {
    if (u.v != 0 || u.omega != 0) note();
    inner_.step(u, dt);
  }
  double clearance() const override { return inner_.clearance(); }
  int collisions() const override { return inner_.collisions(); }
  const std::optional<Clock::time_point>& first_act() const { return first_; }

 private:
  void note() {
    if (!first_) first_ = Clock::now();
  }
  KinematicPlant inner_;
  std::optional<Clock::time_point> first_;
};

TEST(FirstAction, NoMoreThanTheWallTimeUntilThePlantFirstActs) {
  const TaskSpec spec = test_support::fig4_task();
  WatchingPlant plant(spec, test_support::fig4_start());
  const Clock::time_point start = Clock::now();
  const TaskResult r = run_task(spec, plant);
  ASSERT_EQ(r.status, TaskStatus::kCompleted) << r.reason;
  ASSERT_TRUE(plant.first_act().has_value());
  const double until_act = std::chrono::duration<double>(*plant.first_act() - start).count();
  ASSERT_TRUE(std::isfinite(r.first_action_time));
  EXPECT_GT(r.first_action_time, 0);
  EXPECT_LE(r.first_action_time, until_act);
  EXPECT_LE(r.first_action_time, r.compute_time());
}

TEST(FirstAction, NoneWhenThePlantNeverActs) {
  const TaskSpec spec = test_support::walled_in_task();
  WatchingPlant plant(spec, test_support::walled_in_start());
  const TaskResult r = run_task(spec, plant);
  ASSERT_EQ(r.status, TaskStatus::kInfeasible) << r.reason;
  EXPECT_EQ(std::isnan(r.first_action_time), !plant.first_act().has_value());
}

}  // namespace
}  // namespace rearm::executive
