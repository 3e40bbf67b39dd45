#include "symbolic/action.h"

#include <algorithm>

#include "core/error.h"
#include "core/suggest.h"
#include "ltl/formula.h"

namespace rearm::symbolic {
namespace {

std::string strip_spaces(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c != ' ' && c != '\t') out += c;
  }
  return out;
}

std::string join(const std::vector<std::string>& xs) {
  std::string out;
  for (const std::string& x : xs) out += (out.empty() ? "" : ", ") + x;
  return out.empty() ? "(none)" : out;
}

}  // namespace

std::string Action::to_string() const {
  switch (kind) {
    case ActionKind::Move:
      return "move(" + region + ")";
    case ActionKind::Grasp:
      return "grasp(" + object + ")";
    case ActionKind::Release:
      return "release(" + object + "," + region + ")";
  }
  return "";
}

Action Action::parse(const std::string& predicate) {
  const std::string p = strip_spaces(predicate);
  if (!ltl::is_action_predicate(p)) {
    throw Error("'" + predicate +
                "' is not an action predicate: expected move(REGION), grasp(OBJECT) or "
                "release(OBJECT,REGION)");
  }
  const auto open = p.find('(');
  const std::string verb = p.substr(0, open);
  const std::string args = p.substr(open + 1, p.size() - open - 2);
  Action a;
  if (verb == "move") {
    a.kind = ActionKind::Move;
    a.region = args;
  } else if (verb == "grasp") {
    a.kind = ActionKind::Grasp;
    a.object = args;
  } else {
    const auto comma = args.find(',');
    a.kind = ActionKind::Release;
    a.object = args.substr(0, comma);
    a.region = args.substr(comma + 1);
  }
  return a;
}

void Vocabulary::check(const Action& a) const {
  if (empty()) return;
  auto known = [](const std::vector<std::string>& xs, const std::string& x) {
    return std::find(xs.begin(), xs.end(), x) != xs.end();
  };
  if (!a.object.empty() && !known(objects, a.object)) {
    throw Error("unknown object '" + a.object + "' in " + a.to_string() +
                " (known objects: " + join(objects) + ")" + did_you_mean(a.object, objects));
  }
  if (!a.region.empty() && !known(regions, a.region)) {
    throw Error("unknown region '" + a.region + "' in " + a.to_string() +
                " (known regions: " + join(regions) + ")" + did_you_mean(a.region, regions));
  }
}

}  // namespace rearm::symbolic
