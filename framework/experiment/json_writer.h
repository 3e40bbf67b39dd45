// A small streaming JSON writer for result files: keys in the order written, numbers with 17
// significant digits (so a value reads back bit for bit and the same run writes the same bytes;
// fewer for drawing data, where 9 are plenty), non-finite numbers as null, strings escaped.
// Optionally indented for files people read.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace rearm::experiment {

class JsonWriter {
 public:
  // digits: significant digits of every number, in [1, 17].
  explicit JsonWriter(bool pretty = false, int digits = 17);

  JsonWriter& begin_object();
  JsonWriter& end_object();
  JsonWriter& begin_array();
  JsonWriter& end_array();
  JsonWriter& key(std::string_view k);
  JsonWriter& value(double v);
  JsonWriter& value(int v) { return value(static_cast<std::int64_t>(v)); }
  JsonWriter& value(std::int64_t v);
  JsonWriter& value(std::uint64_t v);
  JsonWriter& value(bool v);
  JsonWriter& value(std::string_view v);
  JsonWriter& value(const char* v) { return value(std::string_view(v)); }
  JsonWriter& null();

  // The document; throws rearm::Error when an object or array is still open.
  std::string str() const;

 private:
  void before_value();
  void newline();
  bool pretty_;
  int digits_;
  std::string out_;
  struct Level {
    bool object;
    int count;
  };
  std::vector<Level> stack_;
  bool after_key_ = false;
};

}  // namespace rearm::experiment
