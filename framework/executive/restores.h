// The robust variant's restores (RobustParams::restore; docs/executive.md, "Robust variant"):
// what the LTL RELEASEs placed, which of those objects Fix mode moved since, and at the end of
// an accepting mission, which to release into its region again (as interface-layer actions, at
// most 2 × (objects + 1) per task) and how the task ends.
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "executive/region.h"
#include "perception/semantic_map.h"

namespace rearm::executive {

class Restores {
 public:
  // An LTL RELEASE(object, region) succeeded; an LTL GRASP(object) did.
  void placed(const std::string& object, const std::string& region);
  void grasped(const std::string& object);
  // Fix mode is about to move `object` (recorded for a restore only when an LTL RELEASE placed
  // it and `restore` is on).
  void displaced(const std::string& object, bool restore);
  // The next object to release into its region again (object, region), counted; nullopt when
  // none is left or the limit is reached.
  std::optional<std::pair<std::string, std::string>> next(
      const perception::SemanticMap& map, const std::vector<RegionOfInterest>& regions);
  // The placed objects the map locates outside their region: "M1 not in l1, …", or "".
  std::string moved(const perception::SemanticMap& map,
                    const std::vector<RegionOfInterest>& regions) const;
  std::size_t count() const { return count_; }
  static std::size_t limit(const perception::SemanticMap& map);  // 2 (objects + 1)

 private:
  std::map<std::string, std::string> placed_;  // object → region of its last LTL release
  std::vector<std::pair<std::string, std::string>> displaced_;  // moved by Fix mode since
  std::size_t count_ = 0;
};

}  // namespace rearm::executive
