// The JSON writer against hand-written documents, and its misuse errors.
#include "experiment/json_writer.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <limits>

#include "core/error.h"

namespace rearm::experiment {
namespace {

TEST(JsonWriter, CompactDocument) {
  JsonWriter j;
  j.begin_object();
  j.key("a").value(1);
  j.key("b").begin_array().value(0.5).value(true).null().value("x\"y\\z\n").end_array();
  j.key("c").begin_object().end_object();
  j.key("d").begin_array().end_array();
  j.end_object();
  EXPECT_EQ(j.str(), R"({"a":1,"b":[0.5,true,null,"x\"y\\z\n"],"c":{},"d":[]})");
}

TEST(JsonWriter, PrettyDocument) {
  JsonWriter j(true);
  j.begin_object().key("a").value(1).key("b").begin_array().value(2).end_array().end_object();
  EXPECT_EQ(j.str(), "{\n  \"a\": 1,\n  \"b\": [\n    2\n  ]\n}\n");
}

TEST(JsonWriter, NumbersReadBackExactly) {
  for (const double v : {0.1, 1.0 / 3, -2.5e-300, 6.02214076e23, 123456789.123456789}) {
    JsonWriter j;
    j.value(v);
    EXPECT_EQ(std::strtod(j.str().c_str(), nullptr), v) << j.str();
  }
  JsonWriter n;
  n.begin_array()
      .value(std::numeric_limits<double>::quiet_NaN())
      .value(-std::numeric_limits<double>::infinity())
      .end_array();
  EXPECT_EQ(n.str(), "[null,null]");
  JsonWriter c;
  c.value(std::string_view("\x01"));
  EXPECT_EQ(c.str(), "\"\\u0001\"");
}

TEST(JsonWriter, Misuse) {
  JsonWriter a;
  a.begin_object();
  EXPECT_THROW(a.value(1), Error);  // a value without a key
  EXPECT_THROW(a.str(), Error);     // not closed
  JsonWriter b;
  b.begin_array();
  EXPECT_THROW(b.key("k"), Error);
  EXPECT_THROW(b.end_object(), Error);
  JsonWriter c;
  c.value(1);
  EXPECT_THROW(c.value(2), Error);  // two top-level values
}

}  // namespace
}  // namespace rearm::experiment
