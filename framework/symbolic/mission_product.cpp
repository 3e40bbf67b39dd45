#include "symbolic/mission_product.h"

#include <algorithm>
#include <numeric>
#include <set>

#include "core/error.h"

namespace rearm::symbolic {
namespace {

std::size_t find_root(std::vector<std::size_t>& parent, std::size_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

bool has_negation(const ltl::Formula& f) {
  using ltl::Op;
  const Op op = f.op();
  if (op == Op::Not || op == Op::Implies || op == Op::Equiv || op == Op::Xor) return true;
  for (const ltl::Formula& c : f.children()) {
    if (has_negation(c)) return true;
  }
  return false;
}

}  // namespace

std::vector<ltl::Formula> independent_groups(const ltl::Formula& f) {
  if (f.op() != ltl::Op::And) return {f};
  const std::vector<ltl::Formula>& c = f.children();
  std::vector<std::size_t> parent(c.size());
  std::iota(parent.begin(), parent.end(), 0);
  std::map<std::string, std::size_t> owner;  // proposition -> a conjunct naming it
  for (std::size_t i = 0; i < c.size(); ++i) {
    for (const std::string& ap : c[i].atomic_propositions()) {
      const auto [it, fresh] = owner.emplace(ap, i);
      if (!fresh) parent[find_root(parent, i)] = find_root(parent, it->second);
    }
  }
  std::vector<std::vector<ltl::Formula>> parts;
  std::map<std::size_t, std::size_t> part_of_root;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const auto [it, fresh] = part_of_root.emplace(find_root(parent, i), parts.size());
    if (fresh) parts.emplace_back();
    parts[it->second].push_back(c[i]);
  }
  std::vector<ltl::Formula> groups;
  for (auto& p : parts) groups.push_back(ltl::Formula::conj(std::move(p)));
  return groups;
}

bool pausable(const ltl::ActionNba& nba) {
  for (std::uint32_t q = 0; q < nba.num_states(); ++q) {
    bool loop = false;
    for (const auto& e : nba.out[q]) loop = loop || (e.dst == q && e.guard.test(0));
    if (!loop) return false;
  }
  return true;
}

std::unique_ptr<ProductMission> ProductMission::build(const ltl::Formula& f, const Options& options,
                                                      std::string* why) {
  const std::vector<ltl::Formula> parts = independent_groups(f);
  auto refuse = [&](std::string text) {
    if (why) *why = std::move(text);
    return nullptr;
  };
  if (parts.size() < 2) return refuse("the formula is not a conjunction of independent parts");
  // Without negation a part is monotone in its predicates, so a word in which the part reads
  // the empty symbol while others act satisfies it no better than the word holding its own
  // last action instead: the part's own G (held-letter semantics) loses no plan. With negation
  // the empty symbol can be what a part needs (G F !p), which its own G cannot hold.
  if (has_negation(f)) return refuse("the formula has negation (the product form needs none)");
  std::unique_ptr<ProductMission> m(new ProductMission());
  m->aps_ = f.atomic_propositions();
  if (options.initial) {
    const std::string p0 = options.initial->to_string();
    if (std::find(m->aps_.begin(), m->aps_.end(), p0) == m->aps_.end()) m->aps_.push_back(p0);
  }
  for (const std::string& ap : m->aps_) m->actions_.push_back(Action::parse(ap));
  m->group_of_.assign(m->aps_.size() + 1, -1);
  m->mode_ = options.graph;
  m->excluded_ = ltl::LetterSet(m->aps_.size() + 1);
  if (options.initial) {
    const auto it = std::find(m->aps_.begin(), m->aps_.end(), options.initial->to_string());
    m->held_ = static_cast<std::size_t>(it - m->aps_.begin()) + 1;
  }
  for (const ltl::Formula& part : parts) {
    auto g = std::make_unique<Group>();
    g->formula = part;
    g->nba = ltl::translate_actions(part, options.translate);
    if (!pausable(g->nba)) {
      return refuse("the part '" + part.to_string() +
                    "' cannot wait while others act (a state without a self-loop under the "
                    "empty symbol)");
    }
    const std::size_t index = m->groups_.size();
    g->global.assign(g->nba.alphabet.num_letters(), 0);
    for (std::size_t l = 1; l < g->global.size(); ++l) {
      const std::string& ap = g->nba.alphabet.aps()[l - 1];
      const auto it = std::find(m->aps_.begin(), m->aps_.end(), ap);
      g->global[l] = static_cast<std::size_t>(it - m->aps_.begin()) + 1;
      m->group_of_[g->global[l]] = static_cast<int>(index);
    }
    g->excluded = ltl::LetterSet(g->nba.alphabet.num_letters());
    m->groups_.push_back(std::move(g));
  }
  // π0: the group naming it holds it; to every other group it is the empty symbol.
  for (std::size_t i = 0; i < m->groups_.size(); ++i) {
    Group& g = *m->groups_[i];
    std::size_t local = 0;
    if (m->held_ != 0 && m->group_of_[m->held_] == static_cast<int>(i)) {
      local = static_cast<std::size_t>(std::find(g.global.begin(), g.global.end(), m->held_) -
                                       g.global.begin());
    }
    g.last = local;
    g.holding = true;  // its view of π0 (the empty symbol when π0 is not its own)
    g.reachable = read_holding(g.nba, g.nba.initial, local, m->scratch_);
    g.graph =
        std::make_unique<MissionGraph>(g.nba, MissionGraph::Start{{}, local}, g.excluded, m->mode_);
  }
  if (m->d_f() == MissionGraph::kInfinity) {
    m->set_infeasible(
        "the formula has no satisfying sequence of actions (no accepting cycle of "
        "the automaton is reachable one action at a time)");
  }
  return m;
}

std::uint32_t ProductMission::d_f() const {
  std::uint64_t sum = 0;
  for (const auto& g : groups_) {
    const std::uint32_t d = g->graph->d_f(g->node);
    if (d == MissionGraph::kInfinity) return MissionGraph::kInfinity;
    sum += d;
  }
  return static_cast<std::uint32_t>(std::min<std::uint64_t>(sum, MissionGraph::kInfinity - 1));
}

// Done: in V_F with an accepting edge of its cycle driven by the letter it last held. Its
// automaton can stay where it is while the robot holds another group's letter (pausable), so
// the group stays done.
bool ProductMission::idle(const Group& g) const {
  if (!g.graph->in_vf(g.node)) return false;
  for (const MissionGraph::Edge& e : g.graph->out(g.node)) {
    if (e.accepting && e.in_cycle && e.letters.test(g.last)) return true;
  }
  return false;
}

// The choices of the whole-automaton controller's choose(), per group (eq8_choices): a group
// that no longer holds its own letter has none that counts as held.
std::vector<ProductMission::Choice> ProductMission::candidates(const Group& g,
                                                               std::size_t index) const {
  std::vector<Choice> out;
  const std::optional<std::size_t> held =
      g.holding ? std::optional<std::size_t>(g.last) : std::nullopt;
  for (const EdgeChoice& c : eq8_choices(*g.graph, g.node, held, g.excluded)) {
    out.push_back(Choice{index, c.edge, c.letter});
  }
  return out;
}

std::optional<ProductMission::Choice> ProductMission::choose(
    bool only_same_edge, const std::optional<Choice>& failed) const {
  if (d_f() == MissionGraph::kInfinity) return std::nullopt;
  std::optional<Choice> best;
  for (std::size_t gi = 0; gi < groups_.size(); ++gi) {  // open_choices() without its copy
    const Group& g = *groups_[gi];
    if (idle(g)) continue;
    for (const Choice& c : candidates(g, gi)) {
      const bool same = failed && c.group == failed->group && c.edge == failed->edge;
      if (only_same_edge ? !same : same) continue;
      if (g.holding && c.letter == g.last) return c;  // nothing to do
      if (!best || global_of(c) < global_of(*best)) best = c;
    }
  }
  return best;
}

Action ProductMission::action_of(const Choice& c) const {
  const std::size_t l = global_of(c);
  REARM_DEMAND(l >= 1 && l <= actions_.size(), "not an action letter");
  return actions_[l - 1];
}

void ProductMission::set_infeasible(std::string reason) {
  infeasible_ = true;
  accepting_ = false;
  reason_ = std::move(reason);
  pending_.reset();
}

std::optional<Action> ProductMission::next_action() {
  if (infeasible_) return std::nullopt;
  if (pending_) return action_of(*pending_);
  for (;;) {
    const std::optional<Choice> c = choose(false, std::nullopt);
    if (!c) {
      if (std::all_of(groups_.begin(), groups_.end(), [&](const auto& g) { return idle(*g); })) {
        accepting_ = true;
        return std::nullopt;
      }
      if (rebuild_stale()) continue;
      if (infeasible_) return std::nullopt;
      set_infeasible("no accepting cycle is reachable without the infeasible actions");
      return std::nullopt;
    }
    Group& g = *groups_[c->group];
    if (!(g.holding && c->letter == g.last)) {
      pending_ = c;
      return action_of(*c);
    }
    g.node = g.graph->out(g.node)[c->edge].dst;  // a move the held letter drives: each lowers
                                                 // d_F, so the loop ends
  }
}

void ProductMission::report_success() {
  if (!pending_) throw Error("report_success: no action is pending (call next_action first)");
  const Choice c = *pending_;
  pending_.reset();
  Group& g = *groups_[c.group];
  const int before = group_of_[held_];
  if (before >= 0 && before != static_cast<int>(c.group)) {
    Group& h = *groups_[static_cast<std::size_t>(before)];  // now reads the empty symbol
    h.holding = false;  // (h held a letter of its own, never the empty symbol)
    h.reachable = read_holding(h.nba, h.reachable, 0, scratch_);
  }
  g.node = g.graph->out(g.node)[c.edge].dst;
  g.last = c.letter;
  g.holding = true;
  g.reachable = read_holding(g.nba, g.reachable, c.letter, scratch_);
  held_ = global_of(c);
  accepting_ = false;
}

void ProductMission::report_infeasible(const Action& action) {
  if (!pending_ || action_of(*pending_) != action) {
    throw Error("report_infeasible: " + action.to_string() +
                " is not the pending action of the mission controller");
  }
  const Choice failed = *pending_;
  pending_.reset();
  Group& g = *groups_[failed.group];
  g.excluded.set(failed.letter);
  excluded_.set(global_of(failed));
  g.current = false;
  for (const bool same_edge : {true, false}) {  // Appendix I-C's two alternatives
    if (auto c = choose(same_edge, failed);
        c && !(groups_[c->group]->holding && c->letter == groups_[c->group]->last)) {
      pending_ = c;
      return;
    }
  }
  rebuild_stale();
}

void ProductMission::rebuild(Group& g) {
  if (g.reachable.empty()) {
    set_infeasible("the actions performed so far leave no run of the automaton of '" +
                   g.formula.to_string() + "'");
    return;
  }
  g.graph = std::make_unique<MissionGraph>(
      g.nba, MissionGraph::Start{g.reachable, g.holding ? g.last : 0}, g.excluded, mode_);
  g.node = g.graph->start();
  ++g.generation;
  g.current = true;
  if (g.graph->d_f(g.node) == MissionGraph::kInfinity) {
    std::string names;
    for (const Action& a : infeasible_actions()) {
      names += (names.empty() ? "" : ", ") + a.to_string();
    }
    set_infeasible("no accepting cycle of the automaton of '" + g.formula.to_string() +
                   "' is reachable, after the actions performed so far, without the "
                   "infeasible actions {" +
                   names + "}");
  }
}

// Rebuilds every group whose G still counts on an infeasible action; false when none was stale.
bool ProductMission::rebuild_stale() {
  bool any = false;
  for (auto& g : groups_) {
    if (g->current || infeasible_) continue;
    rebuild(*g);
    any = true;
  }
  return any && !infeasible_;
}

std::vector<ProductMission::Choice> ProductMission::open_choices() const {
  std::vector<Choice> out;
  for (std::size_t gi = 0; gi < groups_.size(); ++gi) {
    if (idle(*groups_[gi])) continue;
    for (const Choice& c : candidates(*groups_[gi], gi)) out.push_back(c);
  }
  return out;
}

std::vector<Action> ProductMission::alternatives() const {
  std::vector<Action> out;
  if (!pending_ || infeasible_) return out;
  out.push_back(action_of(*pending_));
  for (const Choice& c : open_choices()) {
    const Action a = action_of(c);
    if (std::find(out.begin(), out.end(), a) == out.end()) out.push_back(a);
  }
  return out;
}

void ProductMission::prefer(const Action& action) {
  if (!pending_) throw Error("prefer: no action is pending (call next_action first)");
  for (const Choice& c : open_choices()) {
    if (action_of(c) == action) {
      pending_ = c;
      return;
    }
  }
  throw Error("prefer: " + action.to_string() + " is not an alternative of the pending action");
}

std::vector<Action> ProductMission::infeasible_actions() const {
  std::vector<Action> out;
  for (std::size_t l = excluded_.next(1); l < excluded_.universe(); l = excluded_.next(l + 1)) {
    out.push_back(actions_[l - 1]);
  }
  return out;
}

std::uint32_t ProductMission::node() const {
  std::vector<std::uint32_t> key;
  for (const auto& g : groups_) {
    key.insert(key.end(),
               {g->generation, g->node, static_cast<std::uint32_t>(g->last), g->holding ? 1u : 0u});
  }
  const auto [it, fresh] = interned_.emplace(key, static_cast<std::uint32_t>(interned_.size()));
  return it->second;
}

std::uint32_t ProductMission::generation() const {
  std::uint32_t n = 0;
  for (const auto& g : groups_) n += g->generation;
  return n;
}

std::string ProductMission::to_text() const {
  std::string s = "product of " + std::to_string(groups_.size()) +
                  " independent parts (docs/symbolic.md, product form); d_F " +
                  (d_f() == MissionGraph::kInfinity ? std::string("inf") : std::to_string(d_f())) +
                  "\n";
  for (std::size_t i = 0; i < groups_.size(); ++i) {
    s += "part " + std::to_string(i + 1) + ": " + groups_[i]->formula.to_string() + "\n";
    s += groups_[i]->graph->to_text();
  }
  return s;
}

}  // namespace rearm::symbolic
