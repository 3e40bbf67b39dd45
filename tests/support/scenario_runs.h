// Shared checks of the end-to-end recovery tests (tests/experiment/escape_test.cpp,
// fragments_test.cpp, saddle_test.cpp): a scenario run on a plant must complete safely with the
// robot's final position exactly inside the scenario's first region.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "experiment/run_scenario.h"
#include "geometry/polygon.h"
#include "scenario/scenario.h"

namespace rearm::test_support {

// Runs `s` on `plant`; expects it completed with 0 collisions, a positive minimum clearance
// and the robot's last position in s.regions[0] (exact point location). Returns the record.
inline experiment::RunRecord expect_reaches_first_region(const scenario::Scenario& s,
                                                         experiment::PlantKind plant) {
  experiment::RunOptions o;
  o.plant = plant;
  experiment::RunRecord r = experiment::run_scenario(s, o);
  EXPECT_EQ(r.result.status, executive::TaskStatus::kCompleted) << r.result.reason;
  EXPECT_EQ(r.result.collisions, 0);
  EXPECT_GT(r.result.min_clearance, 0);
  EXPECT_FALSE(r.result.path.empty());
  if (!r.result.path.empty()) {
    EXPECT_TRUE(geometry::contains(s.regions.at(0).polygon, r.result.path.back().x));
  }
  return r;
}

// Test-name suffix of a plant parameter: "kinematic" or "box2d".
inline std::string plant_name(const ::testing::TestParamInfo<experiment::PlantKind>& info) {
  return info.param == experiment::PlantKind::kKinematic ? "kinematic" : "box2d";
}

}  // namespace rearm::test_support
