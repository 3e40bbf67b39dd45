#include "symbolic/mission_controller.h"

#include <algorithm>
#include <unordered_set>

#include "core/error.h"

namespace rearm::symbolic {
namespace {

bool is_temporal(ltl::Op op) {
  using ltl::Op;
  return op == Op::Next || op == Op::Eventually || op == Op::Always || op == Op::Until ||
         op == Op::Release || op == Op::WeakUntil || op == Op::StrongRelease;
}

bool is_negating(ltl::Op op) {
  using ltl::Op;
  return op == Op::Not || op == Op::Implies || op == Op::Equiv || op == Op::Xor;
}

// Walks f with the polarity of each occurrence (negative under an odd number of
// negations; both under <-> and xor) and rejects X, negated temporal subformulas, and (unless
// allowed) every negation.
void check_polarity(const ltl::Formula& f, bool negative, bool both, bool allow_negation) {
  using ltl::Op;
  if (f.op() == Op::Next) {
    throw Error(
        "X (next) is not allowed in a mission formula: the controller needs a "
        "stutter-invariant formula (paper Section II-B), found '" +
        f.to_string() + "'");
  }
  if (!allow_negation && is_negating(f.op())) {
    throw Error("negation is not allowed in a mission formula, found '" + f.to_string() +
                "': the paper's fragment has no negation (Section II-B), and Fix mode relies "
                "on that (footnote 4): it grasps and moves whatever blocks the way, which could "
                "be what the formula forbids (->, <-> and xor negate too; rearm plan "
                "--allow-negation plans such formulas symbolically)");
  }
  if ((negative || both) && is_temporal(f.op())) {
    throw Error("negation over the temporal subformula '" + f.to_string() +
                "' is not allowed in a mission formula: the paper's fragment has no "
                "negation (Section II-B); negation may only apply to Boolean combinations "
                "of action predicates");
  }
  switch (f.op()) {
    case Op::Not:
      check_polarity(f.child(0), !negative, both, allow_negation);
      return;
    case Op::Implies:
      check_polarity(f.child(0), !negative, both, allow_negation);
      check_polarity(f.child(1), negative, both, allow_negation);
      return;
    case Op::Equiv:
    case Op::Xor:
      check_polarity(f.child(0), negative, true, allow_negation);
      check_polarity(f.child(1), negative, true, allow_negation);
      return;
    default:
      for (const ltl::Formula& c : f.children()) {
        check_polarity(c, negative, both, allow_negation);
      }
  }
}

}  // namespace

const char* to_string(MissionStatus s) {
  switch (s) {
    case MissionStatus::InProgress:
      return "in progress";
    case MissionStatus::Accepting:
      return "accepting";
    case MissionStatus::Infeasible:
      return "infeasible";
  }
  return "?";
}

void check_mission_formula(const ltl::Formula& f, const Vocabulary& vocabulary,
                           bool allow_negation) {
  check_polarity(f, false, false, allow_negation);
  for (const std::string& ap : f.atomic_propositions()) {
    vocabulary.check(Action::parse(ap));  // throws for non-predicates and unknown names
  }
}

const char* to_string(MissionForm f) {
  switch (f) {
    case MissionForm::kAuto:
      return "auto";
    case MissionForm::kExplicit:
      return "explicit";
    case MissionForm::kProduct:
      return "product";
  }
  return "?";
}

MissionForm parse_mission_form(const std::string& text) {
  if (text == "auto") return MissionForm::kAuto;
  if (text == "explicit") return MissionForm::kExplicit;
  if (text == "product") return MissionForm::kProduct;
  throw Error("unknown mission form '" + text + "' (expected auto, explicit or product)");
}

MissionController::MissionController(const ltl::Formula& formula, MissionOptions options) {
  check_mission_formula(formula, options.vocabulary, options.allow_negation);
  std::vector<std::string> extra;
  if (options.initial) {
    options.vocabulary.check(*options.initial);
    extra.push_back(options.initial->to_string());
  }
  mode_ = options.graph;
  if (options.form != MissionForm::kExplicit) {
    std::string why;
    product_ =
        ProductMission::build(formula, {options.initial, options.translate, options.graph}, &why);
    if (product_) return;
    if (options.form == MissionForm::kProduct) {
      throw Error("the product form does not apply to '" + formula.to_string() + "': " + why);
    }
  }
  nba_ = ltl::translate_actions(formula, options.translate, nullptr, extra);
  for (const std::string& ap : nba_.alphabet.aps()) actions_.push_back(Action::parse(ap));
  if (options.initial) {
    held_ = static_cast<std::size_t>(nba_.alphabet.find_ap(options.initial->to_string())) + 1;
  }
  excluded_ = ltl::LetterSet(nba_.alphabet.num_letters());
  reachable_ = read(nba_.initial, held_);  // π0 is the symbol at instant 0
  graph_ = std::make_unique<MissionGraph>(nba_, MissionGraph::Start{{}, held_}, excluded_,
                                          options.graph);
  if (graph_->d_f(node_) == MissionGraph::kInfinity) {
    set_infeasible(
        "the formula has no satisfying sequence of actions (no accepting cycle of "
        "the automaton is reachable one action at a time)");
  }
}

namespace {

// Over the automaton, or the parts' in the product form.
template <class Count>
std::size_t sum_over_automata(const ProductMission* product, const ltl::ActionNba& nba,
                              Count count) {
  if (!product) return count(nba);
  std::size_t n = 0;
  for (std::size_t i = 0; i < product->num_groups(); ++i) n += count(product->part_automaton(i));
  return n;
}

void demand_whole(bool product, const char* what) {
  if (product) {
    throw Error(std::string(what) +
                ": the mission runs in the product form (one automaton per independent part)");
  }
}

}  // namespace

std::uint32_t MissionController::automaton_state() const {
  demand_whole(product_ != nullptr, "automaton_state");
  return graph_->node(node_).state;
}

const ltl::ActionNba& MissionController::automaton() const {
  demand_whole(product_ != nullptr, "automaton");
  return nba_;
}

const MissionGraph& MissionController::graph() const {
  demand_whole(product_ != nullptr, "graph");
  return *graph_;
}

std::size_t MissionController::automaton_states() const {
  return sum_over_automata(product_.get(), nba_, [](const ltl::ActionNba& a) {
    return static_cast<std::size_t>(a.num_states());
  });
}

std::size_t MissionController::automaton_edges() const {
  return sum_over_automata(product_.get(), nba_,
                           [](const ltl::ActionNba& a) { return a.num_edges(); });
}

std::string MissionController::graph_text() const {
  return product_ ? product_->to_text() : graph_->to_text();
}

const std::vector<std::string>& MissionController::aps() const {
  return product_ ? product_->aps() : nba_.alphabet.aps();
}

MissionStatus MissionController::status() const {
  if (!product_) return status_;
  if (product_->infeasible()) return MissionStatus::Infeasible;
  return product_->accepting() ? MissionStatus::Accepting : MissionStatus::InProgress;
}

const std::string& MissionController::reason() const {
  return product_ ? product_->reason() : reason_;
}

std::uint32_t MissionController::node() const { return product_ ? product_->node() : node_; }

std::size_t MissionController::held_letter() const {
  return product_ ? product_->held_letter() : held_;
}

std::uint32_t MissionController::generation() const {
  return product_ ? product_->generation() : generation_;
}

Action MissionController::action_of(std::size_t letter) const {
  REARM_DEMAND(letter >= 1 && letter <= actions_.size(), "not an action letter");
  return actions_[letter - 1];
}

std::vector<Action> MissionController::infeasible_actions() const {
  if (product_) return product_->infeasible_actions();
  std::vector<Action> out;
  for (std::size_t l = excluded_.next(1); l < excluded_.universe(); l = excluded_.next(l + 1)) {
    out.push_back(action_of(l));
  }
  return out;
}

void MissionController::set_infeasible(std::string reason) {
  status_ = MissionStatus::Infeasible;
  reason_ = std::move(reason);
  pending_.reset();
}

// Candidate edges from the current node (Eq. 8, eq8_choices).
std::vector<MissionController::Choice> MissionController::candidates() const {
  return eq8_choices(*graph_, node_, held_, excluded_);
}

// Among the candidates, an edge the held letter already drives (no action needed) first, then
// the lowest feasible action letter; ties by edge order, so the controller is deterministic.
// With only_same_edge, only other letters of the failed edge.
std::optional<MissionController::Choice> MissionController::choose(
    bool only_same_edge, const std::optional<Choice>& failed) const {
  std::optional<Choice> best;
  for (const Choice& c : candidates()) {
    if (only_same_edge && (!failed || c.edge != failed->edge)) continue;
    if (!only_same_edge && failed && c.edge == failed->edge) continue;
    if (c.letter == held_) return c;
    if (!best || c.letter < best->letter) best = c;
  }
  return best;
}

std::vector<Action> MissionController::alternatives() const {
  if (product_) return product_->alternatives();
  std::vector<Action> out;
  if (!pending_ || status_ == MissionStatus::Infeasible) return out;
  out.push_back(action_of(pending_->letter));
  for (const Choice& c : candidates()) {
    if (c.letter == held_) continue;
    const Action a = action_of(c.letter);
    if (std::find(out.begin(), out.end(), a) == out.end()) out.push_back(a);
  }
  return out;
}

void MissionController::prefer(const Action& action) {
  if (product_) return product_->prefer(action);
  if (!pending_) throw Error("prefer: no action is pending (call next_action first)");
  for (const Choice& c : candidates()) {
    if (c.letter != held_ && action_of(c.letter) == action) {
      pending_ = c;
      return;
    }
  }
  throw Error("prefer: " + action.to_string() + " is not an alternative of the pending action");
}

std::optional<Action> MissionController::next_action() {
  if (product_) return product_->next_action();
  if (status_ == MissionStatus::Infeasible) return std::nullopt;
  if (pending_) return action_of(pending_->letter);
  // Follow edges that need no action (stuttering) until an action is needed or the mission
  // idles: a node seen twice in this call means a cycle of no-action edges.
  std::unordered_set<std::uint32_t> seen;
  for (;;) {
    const std::optional<Choice> c = choose(false, std::nullopt);
    if (!c) {
      if (!graph_current_) {  // G still counts on actions reported infeasible since
        rebuild();
        if (status_ == MissionStatus::Infeasible) return std::nullopt;
        seen.clear();  // node ids of the new G
        continue;
      }
      set_infeasible("no accepting cycle is reachable from automaton state " +
                     graph_->describe(node_) + " without the infeasible actions");
      return std::nullopt;
    }
    const MissionGraph::Edge& e = graph_->out(node_)[c->edge];
    if (c->letter != held_) {
      pending_ = c;
      return action_of(c->letter);
    }
    if (e.accepting && e.in_cycle) status_ = MissionStatus::Accepting;
    if (!seen.insert(node_).second || e.dst == node_) {
      node_ = e.dst;
      return std::nullopt;  // idling in an accepting cycle
    }
    node_ = e.dst;
  }
}

void MissionController::report_success() {
  if (product_) return product_->report_success();
  if (!pending_) throw Error("report_success: no action is pending (call next_action first)");
  const MissionGraph::Edge& e = graph_->out(node_)[pending_->edge];
  if (e.accepting && e.in_cycle) status_ = MissionStatus::Accepting;
  node_ = e.dst;
  held_ = pending_->letter;
  reachable_ = read(reachable_, held_);
  pending_.reset();
}

std::vector<std::uint32_t> MissionController::read(const std::vector<std::uint32_t>& states,
                                                   std::size_t letter) const {
  return read_holding(nba_, states, letter, read_mark_);
}

void MissionController::report_infeasible(const Action& action) {
  if (product_) return product_->report_infeasible(action);
  if (!pending_ || action_of(pending_->letter) != action) {
    throw Error("report_infeasible: " + action.to_string() +
                " is not the pending action of the mission controller");
  }
  const Choice failed = *pending_;
  pending_.reset();
  excluded_.set(failed.letter);
  graph_current_ = false;
  // 1. Another symbol of the same edge; 2. another neighbour that lowers d_F (Appendix I-C).
  if (auto c = choose(true, failed); c && c->letter != held_) {
    pending_ = c;
    return;
  }
  if (auto c = choose(false, failed); c && c->letter != held_) {
    pending_ = c;
    return;
  }
  // 3. Beyond the paper: G and d_F without every action known to be infeasible.
  rebuild();
}

// G and d_F again, without the infeasible actions, from every automaton state the actions
// performed so far can have led to: the branch the controller followed may be a dead end
// without those actions while another branch of the same word is not.
void MissionController::rebuild() {
  if (reachable_.empty()) {
    set_infeasible("the actions performed so far leave no run of the automaton");
    return;
  }
  graph_ = std::make_unique<MissionGraph>(nba_, MissionGraph::Start{reachable_, held_}, excluded_,
                                          mode_);
  node_ = graph_->start();
  ++generation_;
  graph_current_ = true;
  status_ = MissionStatus::InProgress;
  if (graph_->d_f(node_) == MissionGraph::kInfinity) {
    std::string names;
    for (const Action& a : infeasible_actions())
      names += (names.empty() ? "" : ", ") + a.to_string();
    set_infeasible(
        "no accepting cycle of the automaton is reachable, after the actions "
        "performed so far, without the infeasible actions {" +
        names + "}");
  }
}

}  // namespace rearm::symbolic
