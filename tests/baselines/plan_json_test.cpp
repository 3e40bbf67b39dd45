// Plan files: a plan round-trips bit for bit (numbers that need all 17 digits, negative zero,
// empty paths), and every malformed file is refused with an error naming the file and field.
#include "baselines/plan_json.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/error.h"

namespace rearm::baselines {
namespace {

const std::vector<std::string> kNames = {"M1", "M2"};

Plan sample() {
  Plan p;
  ObjectMove m;
  m.object = 1;
  m.from = Point(0.1, 1.0 / 3.0);
  m.to = Point(-0.0, 2.000000000000001);
  m.transit = {Point(0, 0), Point(std::nextafter(1.0, 2.0), 1e-300)};
  m.grasp_heading = -3.141592653589793;
  m.transfer = {Point(5.5, 6.25)};
  m.release_heading = 0.7;
  p.moves.push_back(m);
  m.object = 0;
  m.held_at_start = true;
  m.transit.clear();
  p.moves.push_back(m);
  p.final_transit = {Point(1, 2), Point(3, 4)};
  p.final_arrangement = {Point(1.25, 2.5), Point(7, 8)};
  return p;
}

TEST(PlanJson, RoundTripsBitForBit) {
  const Plan p = sample();
  const std::string text = plan_to_json(p, kNames);
  const Plan q = plan_from_json(text, kNames, "x.json");
  ASSERT_EQ(q.moves.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(q.moves[i].object, p.moves[i].object);
    EXPECT_EQ(q.moves[i].held_at_start, p.moves[i].held_at_start);
    EXPECT_EQ(q.moves[i].from, p.moves[i].from);
    EXPECT_EQ(q.moves[i].to, p.moves[i].to);
    EXPECT_EQ(q.moves[i].transit, p.moves[i].transit);
    EXPECT_EQ(q.moves[i].transfer, p.moves[i].transfer);
    EXPECT_EQ(q.moves[i].grasp_heading, p.moves[i].grasp_heading);
    EXPECT_EQ(q.moves[i].release_heading, p.moves[i].release_heading);
  }
  EXPECT_EQ(q.final_transit, p.final_transit);
  EXPECT_EQ(q.final_arrangement, p.final_arrangement);
  EXPECT_TRUE(std::signbit(q.moves[0].to.x()));
  EXPECT_EQ(plan_to_json(q, kNames), text);
  EXPECT_NE(text.find("\"object\":\"M2\""), std::string::npos);
}

void expect_refused(const std::string& text, const std::string& says) {
  try {
    plan_from_json(text, kNames, "bad.json");
    ADD_FAILURE() << "accepted: " << text;
  } catch (const Error& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind("bad.json: ", 0), 0u) << m;
    EXPECT_NE(m.find(says), std::string::npos) << m;
  }
}

std::string with(const std::string& from, const std::string& to) {
  std::string t = plan_to_json(sample(), kNames);
  const auto at = t.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return t.replace(at, from.size(), to);
}

TEST(PlanJson, MalformedFilesAreRefusedByField) {
  expect_refused("{\"format\": ", "not valid JSON");
  expect_refused("[]", "expected an object");
  expect_refused(with("\"rearm-plan\"", "\"other\""), "format");
  expect_refused(with("\"version\":1", "\"version\":2"), "version");
  expect_refused(with("\"object\":\"M2\"", "\"object\":\"M9\""),
                 "moves[0].object: unknown object 'M9'");
  expect_refused(with("\"grasp_heading\":-3.141592653589793", "\"grasp_heading\":null"),
                 "moves[0].grasp_heading: expected a number");
  expect_refused(with("\"release_heading\":0.7", "\"release_heading\":\"0.7\""),
                 "moves[0].release_heading: expected a number");
  expect_refused(with("\"from\":[0.1,", "\"from\":[0.1,0.2,"), "moves[0].from: expected [x, y]");
  expect_refused(with(",\"final_transit\"", ",\"final_transitX\""),
                 "missing field 'final_transit'");
  expect_refused(with("\"held_at_start\":false", "\"held_at_start\":0"), "held_at_start");
  expect_refused(with("\"moves\":[", "\"moves\":7,\"x\":["), "moves: expected a list");
}

TEST(PlanJson, WritingAnIndexOutOfRangeIsAnError) {
  Plan p = sample();
  p.moves[0].object = 5;
  EXPECT_THROW(plan_to_json(p, kNames), Error);
}

}  // namespace
}  // namespace rearm::baselines
