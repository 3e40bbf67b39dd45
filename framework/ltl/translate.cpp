// LTL -> Büchi translation after P. Gastin and D. Oddoux, "Fast LTL to Büchi automata
// translation", CAV 2001 (the algorithm of LTL2BA, the tool the paper used).
//
// Pipeline (each stage with the simplifications of the 2001 paper):
//  1. rewrite() (ltl/simplify.h) to negation normal form with LTL rewriting rules.
//  2. Very weak alternating automaton (VWAA, GO §2): states are the non-Boolean
//     subformulas; δ is computed compositionally (GO Def. 2.2) with transitions
//     (guard, successor set); dominated transitions are removed (GO §2, "simplification").
//     Departure: acceptance is carried by transitions, not states (as in LTL3BA, Babiak et
//     al., TACAS 2012). A U/F state f owns an acceptance set "leave f" marked on its
//     transitions whose successor set does not contain f; a state G F a owns the set "a
//     started", marked on its transitions that start a, with the unmarked loop (t, {GFa}).
//     GF a is thus one VWAA state instead of two, which is what makes a conjunction of n GF
//     formulas one generalized state (n+1 Büchi states after degeneralization) instead of
//     2^n (GO §3 on GF formulas).
//  3. Transition-based generalized Büchi automaton (GO §3): states are sets of VWAA
//     states, a transition is a product of one transition per member. A transition is in
//     acceptance set f iff f is not in the source set or f's own component is marked
//     (the on-the-fly form of GO's T_f). Dominated transitions are dropped during the
//     product; equivalent states are merged (bisimulation with marks).
//  4. Degeneralization to a state-based Büchi automaton (GO §4) with levels, level
//     jumping over consecutive marks, and SCC information: inside SCCs that cannot be
//     accepting all states keep level 0, so e.g. F p1 & ... & F pn keeps 2^n states.
//     Then states that cannot reach an accepting cycle are removed and bisimilar states
//     merged.
// The two alphabets share this code (templates over ltl/alphabet.h): with ActionAlphabet
// guards are sets of the N+1 letters, so a product needing two actions at once is empty
// and dropped on the spot (docs/symbolic.md: exclusivity applied during construction).
#include "ltl/translate.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <functional>
#include <unordered_map>
#include <utility>
#include <vector>

#include "core/error.h"
#include "core/scc.h"
#include "ltl/simplify.h"

namespace rearm::ltl {
namespace {

using StateSet = std::vector<std::uint32_t>;  // sorted VWAA state ids

// Small dynamic bitset for acceptance marks.
struct Marks {
  std::vector<std::uint64_t> w;
  bool test(std::size_t i) const { return i / 64 < w.size() && ((w[i / 64] >> (i % 64)) & 1u); }
  void set(std::size_t i) {
    if (w.size() <= i / 64) w.resize(i / 64 + 1, 0);
    w[i / 64] |= std::uint64_t{1} << (i % 64);
  }
  Marks& operator|=(const Marks& o) {
    if (w.size() < o.w.size()) w.resize(o.w.size(), 0);
    for (std::size_t i = 0; i < o.w.size(); ++i) w[i] |= o.w[i];
    return *this;
  }
  Marks intersection(const Marks& o) const {
    Marks r;
    r.w.resize(std::min(w.size(), o.w.size()));
    for (std::size_t i = 0; i < r.w.size(); ++i) r.w[i] = w[i] & o.w[i];
    return r;
  }
  bool subset_of(const Marks& o) const {
    for (std::size_t i = 0; i < w.size(); ++i) {
      const std::uint64_t ow = i < o.w.size() ? o.w[i] : 0;
      if (w[i] & ~ow) return false;
    }
    return true;
  }
  bool operator==(const Marks& o) const {
    const std::size_t n = std::max(w.size(), o.w.size());
    for (std::size_t i = 0; i < n; ++i) {
      if ((i < w.size() ? w[i] : 0) != (i < o.w.size() ? o.w[i] : 0)) return false;
    }
    return true;
  }
  std::size_t hash() const {
    std::size_t h = 0x345;
    for (std::size_t i = 0; i < w.size(); ++i) {
      if (w[i]) h = h * 1000003u ^ (w[i] + i);
    }
    return h;
  }
};

std::uint64_t signature(const StateSet& s) {
  std::uint64_t sig = 0;
  for (std::uint32_t x : s) sig |= std::uint64_t{1} << (x % 64);
  return sig;
}

StateSet set_union(const StateSet& a, const StateSet& b) {
  StateSet out;
  out.reserve(a.size() + b.size());
  std::set_union(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
  return out;
}

bool includes(const StateSet& big, const StateSet& small) {
  return std::includes(big.begin(), big.end(), small.begin(), small.end());
}

struct StateSetHash {
  std::size_t operator()(const StateSet& s) const {
    std::size_t h = s.size();
    for (std::uint32_t x : s) h = h * 0x9e3779b97f4a7c15ULL + x;
    return h;
  }
};

class Clock {
 public:
  explicit Clock(const TranslateOptions& o)
      : start_(std::chrono::steady_clock::now()), options_(o) {}
  double ms() const {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_)
        .count();
  }
  // The time budget alone, inside loops whose single pass can outlast it (the dominance test of
  // a state with 2^n transitions); the clock is read every 64 polls.
  void poll(const char* stage) {
    if ((++polls_ & 63u) == 0) check_time(stage);
  }
  void check(const char* stage, std::size_t states) {
    if (states > options_.max_states) {
      throw BudgetExceeded(std::string("ltl translation: ") + stage + " exceeds the budget of " +
                           std::to_string(options_.max_states) + " states");
    }
    if ((++ticks_ & 255u) == 0) check_time(stage);
  }

 private:
  void check_time(const char* stage) const {
    if (ms() > options_.max_seconds * 1000.0) {
      throw BudgetExceeded(std::string("ltl translation: ") + stage +
                           " exceeds the time budget of " + std::to_string(options_.max_seconds) +
                           " s");
    }
  }

  std::chrono::steady_clock::time_point start_;
  const TranslateOptions& options_;
  std::uint32_t ticks_ = 0;
  std::uint32_t polls_ = 0;
};

template <class A>
struct Trans {
  typename A::Guard guard;
  StateSet succ;
  Marks marks;
  std::uint64_t sig = 0;  // signature(succ), a quick subset filter
};

// Drops transitions dominated by another one (GO: t is useless when some t' has a weaker
// guard, a smaller successor set and at least its marks) and or-s the guards of
// transitions with equal successors and marks.
template <class A>
void simplify_transitions(const A& alpha, std::vector<Trans<A>>& ts, Clock& clock) {
  if (ts.size() < 2) return;
  // Merge equal (succ, marks): sort by a key, or adjacent equals.
  auto less = [](const Trans<A>& a, const Trans<A>& b) {
    if (a.sig != b.sig) return a.sig < b.sig;
    if (a.succ != b.succ) return a.succ < b.succ;
    return a.marks.w < b.marks.w;
  };
  std::sort(ts.begin(), ts.end(), less);
  std::size_t k = 0;
  for (std::size_t i = 0; i < ts.size(); ++i) {
    if (k > 0 && ts[k - 1].sig == ts[i].sig && ts[k - 1].succ == ts[i].succ &&
        ts[k - 1].marks == ts[i].marks) {
      ts[k - 1].guard = alpha.disj(ts[k - 1].guard, ts[i].guard);
    } else {
      if (k != i) ts[k] = std::move(ts[i]);
      ++k;
    }
  }
  ts.resize(k);
  // Dominance: a dominator has a successor set no larger than the dominated one.
  std::stable_sort(ts.begin(), ts.end(), [](const Trans<A>& a, const Trans<A>& b) {
    return a.succ.size() < b.succ.size();
  });
  std::vector<char> dead(ts.size(), 0);
  for (std::size_t i = 0; i < ts.size(); ++i) {
    clock.poll("simplifying the transitions");
    const Trans<A>& a = ts[i];  // candidate to drop
    for (std::size_t j = 0; j < ts.size() && ts[j].succ.size() <= a.succ.size(); ++j) {
      if (i == j || dead[j]) continue;
      const Trans<A>& b = ts[j];  // dominating?
      if ((b.sig & ~a.sig) != 0) continue;
      if (!includes(a.succ, b.succ) || !a.marks.subset_of(b.marks)) continue;
      if (alpha.implies(a.guard, b.guard)) {
        dead[i] = 1;
        break;
      }
    }
  }
  k = 0;
  for (std::size_t i = 0; i < ts.size(); ++i) {
    if (dead[i]) continue;
    if (k != i) ts[k] = std::move(ts[i]);
    ++k;
  }
  ts.resize(k);
}

// Adds t to a simplified list, keeping it simplified in O(|ts|).
template <class A>
void add_transition(const A& alpha, std::vector<Trans<A>>& ts, Trans<A> t) {
  for (const Trans<A>& b : ts) {
    if ((b.sig & ~t.sig) == 0 && includes(t.succ, b.succ) && t.marks.subset_of(b.marks) &&
        alpha.implies(t.guard, b.guard)) {
      return;  // dominated (or equal)
    }
  }
  std::size_t k = 0;
  for (std::size_t i = 0; i < ts.size(); ++i) {
    const Trans<A>& a = ts[i];
    const bool dominated = (t.sig & ~a.sig) == 0 && includes(a.succ, t.succ) &&
                           a.marks.subset_of(t.marks) && alpha.implies(a.guard, t.guard);
    if (dominated) continue;
    if (k != i) ts[k] = std::move(ts[i]);
    ++k;
  }
  ts.resize(k);
  ts.push_back(std::move(t));
}

template <class A>
std::vector<Trans<A>> product(const A& alpha, const std::vector<Trans<A>>& x,
                              const std::vector<Trans<A>>& y, Clock& clock) {
  if (x.size() == 1 && x[0].succ.empty() && x[0].marks.w.empty() &&
      alpha.implies(alpha.top(), x[0].guard)) {
    return y;  // (t, {}) is the unit of the product; y is already simplified
  }
  std::vector<Trans<A>> out;
  out.reserve(x.size() * y.size());
  for (const Trans<A>& a : x) {
    clock.poll("the transition product");
    for (const Trans<A>& b : y) {
      auto g = alpha.conj(a.guard, b.guard);
      if (alpha.is_false(g)) continue;
      Trans<A> t{std::move(g), set_union(a.succ, b.succ), a.marks, a.sig | b.sig};
      t.marks |= b.marks;
      out.push_back(std::move(t));
    }
  }
  simplify_transitions(alpha, out, clock);
  return out;
}

// ---------------------------------------------------------------------------------------
// Stage 2: the very weak alternating automaton.
template <class A>
class Vwaa {
 public:
  Vwaa(A& alpha, Clock& clock) : alpha_(alpha), clock_(clock) {}

  // \bar{f} of GO: the DNF of f as sets of states (supersets removed).
  std::vector<StateSet> dnf(const Formula& f) {
    switch (f.op()) {
      case Op::True:
        return {StateSet{}};
      case Op::False:
        return {};
      case Op::And: {
        std::vector<StateSet> acc{StateSet{}};
        for (const Formula& c : f.children()) {
          std::vector<StateSet> next;
          for (const StateSet& a : acc) {
            for (const StateSet& b : dnf(c)) next.push_back(set_union(a, b));
          }
          acc = minimal(std::move(next));
          clock_.check("the initial state sets", acc.size());
        }
        return acc;
      }
      case Op::Or: {
        std::vector<StateSet> acc;
        for (const Formula& c : f.children()) {
          for (StateSet& s : dnf(c)) acc.push_back(std::move(s));
        }
        return minimal(std::move(acc));
      }
      default:
        return {StateSet{state(f)}};
    }
  }

  // Transitions of VWAA state `s`, with its own acceptance marks.
  const std::vector<Trans<A>>& transitions(std::uint32_t s) {
    while (state_trans_.size() <= s) state_trans_.emplace_back();
    if (state_done_.size() <= s) state_done_.resize(s + 1, false);
    if (state_done_[s]) return state_trans_[s];
    const Formula f = formulas_[s];
    std::vector<Trans<A>> ts;
    if (is_gf(f)) {
      // G F a: (guard(a), succ(a) + {s}) marked "a started"; (t, {s}) unmarked.
      for (const Trans<A>& t : delta(f.child(0).child(0))) {
        Trans<A> u{t.guard, set_union(t.succ, StateSet{s}), {}, 0};
        u.sig = signature(u.succ);
        u.marks.set(acc_of_[s]);
        ts.push_back(std::move(u));
      }
      ts.push_back(Trans<A>{alpha_.top(), StateSet{s}, {}, signature(StateSet{s})});
      simplify_transitions(alpha_, ts, clock_);
    } else {
      // δ(f) is simplified; marking the transitions that leave f cannot make one dominate
      // another (a dominator already had a smaller successor set, so it leaves f if the
      // dominated one does).
      ts = delta(f);
      if (acc_of_[s] >= 0) {  // U/F state: marked when it is left
        for (Trans<A>& t : ts) {
          if (!std::binary_search(t.succ.begin(), t.succ.end(), s)) t.marks.set(acc_of_[s]);
        }
      }
    }
    state_trans_[s] = std::move(ts);
    state_done_[s] = true;
    return state_trans_[s];
  }

  std::size_t num_states() const { return formulas_.size(); }
  std::size_t num_acceptance_sets() const { return num_acc_; }
  // The VWAA state owning acceptance set i.
  std::uint32_t owner(std::size_t i) const { return acc_owner_[i]; }

 private:
  static bool is_gf(const Formula& f) {
    return f.op() == Op::Always && f.child(0).op() == Op::Eventually;
  }

  std::uint32_t state(const Formula& f) {
    auto it = ids_.find(f);
    if (it != ids_.end()) return it->second;
    const auto id = static_cast<std::uint32_t>(formulas_.size());
    formulas_.push_back(f);
    ids_.emplace(f, id);
    int acc = -1;
    if (f.op() == Op::Until || f.op() == Op::Eventually || is_gf(f)) {
      acc = static_cast<int>(num_acc_++);
      acc_owner_.push_back(id);
    }
    acc_of_.push_back(acc);
    clock_.check("the alternating automaton", formulas_.size());
    return id;
  }

  static std::vector<StateSet> minimal(std::vector<StateSet> sets) {
    std::sort(sets.begin(), sets.end(),
              [](const StateSet& a, const StateSet& b) { return a.size() < b.size(); });
    std::vector<StateSet> out;
    for (StateSet& s : sets) {
      bool redundant = false;
      for (const StateSet& o : out) {
        if (includes(s, o)) {
          redundant = true;
          break;
        }
      }
      if (!redundant) out.push_back(std::move(s));
    }
    return out;
  }

  Trans<A> make(typename A::Guard g, StateSet succ) {
    const std::uint64_t sig = signature(succ);
    return Trans<A>{std::move(g), std::move(succ), {}, sig};
  }

  // GO Def. 2.2 (unmarked): δ(f) for any NNF formula f, memoized.
  const std::vector<Trans<A>>& delta(const Formula& f) {
    auto it = delta_.find(f);
    if (it != delta_.end()) return it->second;
    std::vector<Trans<A>> ts;
    const auto& c = f.children();
    switch (f.op()) {
      case Op::True:
        ts.push_back(make(alpha_.top(), {}));
        break;
      case Op::False:
        break;
      case Op::Ap:
        ts.push_back(make(alpha_.ap(ap_index(f.name()), true), {}));
        break;
      case Op::Not:
        REARM_DEMAND(c[0].op() == Op::Ap, "translation expects negation normal form");
        ts.push_back(make(alpha_.ap(ap_index(c[0].name()), false), {}));
        break;
      case Op::And:
        ts = delta(c[0]);
        for (std::size_t i = 1; i < c.size(); ++i) ts = product(alpha_, ts, delta(c[i]), clock_);
        break;
      case Op::Or:
        for (const Formula& x : c) {
          for (const Trans<A>& t : delta(x)) ts.push_back(t);
        }
        simplify_transitions(alpha_, ts, clock_);
        break;
      case Op::Next:
        for (StateSet& s : dnf(c[0])) ts.push_back(make(alpha_.top(), std::move(s)));
        break;
      case Op::Until: {  // δ(b) ∪ δ(a) ⊗ {(t, {a U b})}
        const std::uint32_t self = state(f);
        ts = delta(c[1]);
        for (Trans<A> t : delta(c[0])) {
          t.succ = set_union(t.succ, StateSet{self});
          t.sig = signature(t.succ);
          ts.push_back(std::move(t));
        }
        simplify_transitions(alpha_, ts, clock_);
        break;
      }
      case Op::Eventually: {  // δ(a) ∪ {(t, {F a})}
        const std::uint32_t self = state(f);
        ts = delta(c[0]);
        add_transition(alpha_, ts, make(alpha_.top(), StateSet{self}));
        break;
      }
      case Op::Release: {  // δ(b) ⊗ (δ(a) ∪ {(t, {a R b})})
        const std::uint32_t self = state(f);
        std::vector<Trans<A>> right = delta(c[0]);
        right.push_back(make(alpha_.top(), StateSet{self}));
        ts = product(alpha_, delta(c[1]), right, clock_);
        break;
      }
      case Op::Always: {  // δ(a) ⊗ {(t, {G a})}; for G F a see transitions()
        const std::uint32_t self = state(f);
        if (is_gf(f)) {
          ts.push_back(make(alpha_.top(), StateSet{self}));  // GF a == X GF a
        } else {
          ts = product(alpha_, delta(c[0]),
                       std::vector<Trans<A>>{make(alpha_.top(), StateSet{self})}, clock_);
        }
        break;
      }
      default:
        REARM_DEMAND(false, "translation expects negation normal form");
    }
    return delta_.emplace(f, std::move(ts)).first->second;
  }

  std::uint32_t ap_index(const std::string& name) {
    const int i = alpha_.find_ap(name);
    REARM_DEMAND(i >= 0, "proposition missing from the alphabet: " + name);
    return static_cast<std::uint32_t>(i);
  }

  A& alpha_;
  Clock& clock_;
  std::vector<Formula> formulas_;
  std::unordered_map<Formula, std::uint32_t, FormulaHash> ids_;
  std::vector<int> acc_of_;
  std::vector<std::uint32_t> acc_owner_;
  std::size_t num_acc_ = 0;
  std::unordered_map<Formula, std::vector<Trans<A>>, FormulaHash> delta_;
  std::vector<std::vector<Trans<A>>> state_trans_;
  std::vector<bool> state_done_;
};

// ---------------------------------------------------------------------------------------
// Stage 3: transition-based generalized Büchi automaton.
template <class A>
struct Tgba {
  struct Edge {
    std::uint32_t dst;
    typename A::Guard guard;
    Marks marks;
  };
  std::vector<std::vector<Edge>> out;
  std::vector<std::uint32_t> initial;
  std::size_t num_acc = 0;
  std::size_t num_edges() const {
    std::size_t n = 0;
    for (const auto& o : out) n += o.size();
    return n;
  }
};

template <class A>
Tgba<A> build_tgba(A& alpha, Vwaa<A>& vwaa, const Formula& f, Clock& clock) {
  Tgba<A> g;
  std::unordered_map<StateSet, std::uint32_t, StateSetHash> ids;
  std::vector<StateSet> sets;
  auto id_of = [&](const StateSet& s) {
    auto [it, inserted] = ids.emplace(s, static_cast<std::uint32_t>(sets.size()));
    if (inserted) {
      sets.push_back(s);
      g.out.emplace_back();
      clock.check("the generalized Büchi automaton", sets.size());
    }
    return it->second;
  };
  for (const StateSet& s : vwaa.dnf(f)) g.initial.push_back(id_of(s));
  for (std::size_t i = 0; i < sets.size(); ++i) {
    const StateSet e = sets[i];
    std::vector<Trans<A>> ts{Trans<A>{alpha.top(), {}, {}, 0}};
    for (std::uint32_t s : e) ts = product(alpha, ts, vwaa.transitions(s), clock);
    // The number of acceptance sets is known once every reachable state has been seen;
    // marks of sets whose owner is absent from e are added after the exploration.
    for (Trans<A>& t : ts) {
      const std::uint32_t dst = id_of(t.succ);
      g.out[i].push_back({dst, std::move(t.guard), std::move(t.marks)});
    }
  }
  // GO's T_f for a set f whose owner is absent from the source: the transition is in T_f
  // iff f is absent from the target too. (A branch can only stay in f forever through
  // looping transitions of f's own component, which are never marked.)
  g.num_acc = vwaa.num_acceptance_sets();
  std::vector<Marks> absent(sets.size());
  for (std::size_t i = 0; i < sets.size(); ++i) {
    for (std::size_t a = 0; a < g.num_acc; ++a) {
      if (!std::binary_search(sets[i].begin(), sets[i].end(), vwaa.owner(a))) absent[i].set(a);
    }
  }
  for (std::size_t i = 0; i < sets.size(); ++i) {
    for (auto& e : g.out[i]) e.marks |= absent[i].intersection(absent[e.dst]);
  }
  return g;
}

// Keeps the states reachable from the initial ones that can reach an accepting SCC
// (`accepting_scc` decides on an SCC from its states), renumbering them in increasing
// order. Returns the renumbering (old -> new, ~0u for removed states).
template <class G, class Dst, class SetDst, class AccSccFn>
std::vector<std::uint32_t> prune(G& g, Dst dst_of, SetDst set_dst, AccSccFn accepting_scc) {
  const std::uint32_t n = static_cast<std::uint32_t>(g.out.size());
  std::vector<bool> reach(n, false);
  std::vector<std::uint32_t> todo(g.initial.begin(), g.initial.end());
  for (std::uint32_t s : todo) reach[s] = true;
  while (!todo.empty()) {
    const std::uint32_t s = todo.back();
    todo.pop_back();
    for (const auto& e : g.out[s]) {
      const std::uint32_t d = dst_of(e);
      if (!reach[d]) {
        reach[d] = true;
        todo.push_back(d);
      }
    }
  }
  std::uint32_t count = 0;
  const std::vector<std::uint32_t> comp = strongly_connected_components(g.out, dst_of, &count);
  std::vector<std::vector<std::uint32_t>> members(count);
  for (std::uint32_t s = 0; s < n; ++s) members[comp[s]].push_back(s);
  // SCCs come successors first: a state is useful when its SCC accepts or an edge leads
  // to a useful SCC.
  std::vector<bool> useful_scc(count, false);
  for (std::uint32_t c = 0; c < count; ++c) {
    bool useful = accepting_scc(members[c], comp);
    for (std::uint32_t s : members[c]) {
      for (const auto& e : g.out[s]) {
        if (comp[dst_of(e)] != c && useful_scc[comp[dst_of(e)]]) useful = true;
      }
    }
    useful_scc[c] = useful;
  }
  std::vector<std::uint32_t> renum(n, ~0u);
  std::uint32_t k = 0;
  for (std::uint32_t s = 0; s < n; ++s) {
    if (reach[s] && useful_scc[comp[s]]) renum[s] = k++;
  }
  G h;
  h.out.resize(k);
  for (std::uint32_t s = 0; s < n; ++s) {
    if (renum[s] == ~0u) continue;
    for (auto& e : g.out[s]) {
      const std::uint32_t d = dst_of(e);
      if (renum[d] == ~0u) continue;
      set_dst(e, renum[d]);
      h.out[renum[s]].push_back(std::move(e));
    }
  }
  for (std::uint32_t s : g.initial) {
    if (renum[s] != ~0u) h.initial.push_back(renum[s]);
  }
  std::sort(h.initial.begin(), h.initial.end());
  h.initial.erase(std::unique(h.initial.begin(), h.initial.end()), h.initial.end());
  g.out = std::move(h.out);
  g.initial = std::move(h.initial);
  return renum;
}

// Coarsest bisimulation by partition refinement. `sig_edges(s)` lists (dst, guard, key)
// triples; two states stay together iff they are in the same initial class and, per
// (class of dst, key), the disjunction of their guards is the same.
template <class A, class EdgesFn>
std::vector<std::uint32_t> bisimulation(const A& alpha, std::uint32_t n,
                                        std::vector<std::uint32_t> cls, EdgesFn edges,
                                        std::uint32_t& num_classes) {
  using Guard = typename A::Guard;
  struct Item {
    std::uint32_t dst_class;
    std::size_t key;
    Guard guard;
  };
  // Renumber the initial classes densely: the loop stops when a round adds no class.
  std::uint32_t old_count = 0;
  {
    std::unordered_map<std::uint32_t, std::uint32_t> dense;
    for (std::uint32_t& c : cls) c = dense.emplace(c, dense.size()).first->second;
    old_count = static_cast<std::uint32_t>(dense.size());
  }
  for (;;) {
    std::vector<std::vector<Item>> sigs(n);
    for (std::uint32_t s = 0; s < n; ++s) {
      std::vector<Item>& items = sigs[s];
      edges(s, [&](std::uint32_t dst, const Guard& g, std::size_t key) {
        items.push_back(Item{cls[dst], key, g});
      });
      std::sort(items.begin(), items.end(), [](const Item& a, const Item& b) {
        return a.dst_class != b.dst_class ? a.dst_class < b.dst_class : a.key < b.key;
      });
      // Or the guards of items with the same (class, key).
      std::size_t k = 0;
      for (std::size_t i = 0; i < items.size(); ++i) {
        if (k > 0 && items[k - 1].dst_class == items[i].dst_class &&
            items[k - 1].key == items[i].key) {
          items[k - 1].guard = alpha.disj(items[k - 1].guard, items[i].guard);
        } else {
          if (k != i) items[k] = std::move(items[i]);
          ++k;
        }
      }
      items.resize(k);
    }
    auto same = [&](std::uint32_t a, std::uint32_t b) {
      if (cls[a] != cls[b] || sigs[a].size() != sigs[b].size()) return false;
      for (std::size_t i = 0; i < sigs[a].size(); ++i) {
        const Item& x = sigs[a][i];
        const Item& y = sigs[b][i];
        if (x.dst_class != y.dst_class || x.key != y.key || !(x.guard == y.guard)) return false;
      }
      return true;
    };
    auto hash = [&](std::uint32_t s) {
      std::size_t h = cls[s] * 0x9e3779b97f4a7c15ULL;
      for (const Item& it : sigs[s]) {
        h = (h ^ it.dst_class) * 1000003u ^ it.key ^ (A::guard_hash(it.guard) << 1);
      }
      return h;
    };
    std::unordered_map<std::size_t, std::vector<std::uint32_t>> buckets;  // hash -> reps
    std::vector<std::uint32_t> next(n);
    std::vector<std::uint32_t> rep_class;
    std::uint32_t k = 0;
    for (std::uint32_t s = 0; s < n; ++s) {
      auto& reps = buckets[hash(s)];
      bool found = false;
      for (std::uint32_t r : reps) {
        if (same(r, s)) {
          next[s] = next[r];
          found = true;
          break;
        }
      }
      if (!found) {
        next[s] = k++;
        reps.push_back(s);
      }
    }
    cls = std::move(next);
    if (k == old_count) {
      num_classes = k;
      return cls;
    }
    old_count = k;
  }
}

template <class A>
void merge_tgba_states(const A& alpha, Tgba<A>& g) {
  const std::uint32_t n = static_cast<std::uint32_t>(g.out.size());
  if (n == 0) return;
  // Mark sets are compared exactly: each distinct set gets a dense id (the bisimulation key).
  struct MarksHash {
    std::size_t operator()(const Marks& m) const { return m.hash(); }
  };
  std::unordered_map<Marks, std::size_t, MarksHash> mark_ids;
  std::vector<std::vector<std::size_t>> key(n);
  for (std::uint32_t s = 0; s < n; ++s) {
    for (const auto& e : g.out[s])
      key[s].push_back(mark_ids.emplace(e.marks, mark_ids.size()).first->second);
  }
  std::uint32_t k = 0;
  const auto cls = bisimulation(
      alpha, n, std::vector<std::uint32_t>(n, 0),
      [&](std::uint32_t s, auto&& emit) {
        for (std::size_t i = 0; i < g.out[s].size(); ++i) {
          emit(g.out[s][i].dst, g.out[s][i].guard, key[s][i]);
        }
      },
      k);
  if (k == n) return;
  // Equivalent states have the same guards per (destination class, marks): the merged state
  // takes the edges of one representative.
  Tgba<A> h;
  h.num_acc = g.num_acc;
  h.out.resize(k);
  std::vector<bool> done(k, false);
  for (std::uint32_t s = 0; s < n; ++s) {
    if (done[cls[s]]) continue;
    done[cls[s]] = true;
    auto& out = h.out[cls[s]];
    for (const auto& e : g.out[s]) {
      bool merged = false;
      for (auto& o : out) {
        if (o.dst == cls[e.dst] && o.marks == e.marks) {
          o.guard = alpha.disj(o.guard, e.guard);
          merged = true;
          break;
        }
      }
      if (!merged) out.push_back({cls[e.dst], e.guard, e.marks});
    }
  }
  for (std::uint32_t s : g.initial) h.initial.push_back(cls[s]);
  std::sort(h.initial.begin(), h.initial.end());
  h.initial.erase(std::unique(h.initial.begin(), h.initial.end()), h.initial.end());
  g = std::move(h);
}

// An SCC of the generalized automaton can hold an accepting run only if it has an inner
// edge and its inner edges together carry every mark.
template <class A>
bool accepting_scc(const Tgba<A>& g, const std::vector<std::uint32_t>& members,
                   const std::vector<std::uint32_t>& comp) {
  Marks seen;
  bool cyclic = false;
  for (std::uint32_t s : members) {
    for (const auto& e : g.out[s]) {
      if (comp[e.dst] == comp[s]) {
        cyclic = true;
        seen |= e.marks;
      }
    }
  }
  for (std::size_t a = 0; a < g.num_acc && cyclic; ++a) cyclic = seen.test(a);
  return cyclic;
}

// ---------------------------------------------------------------------------------------
// Stage 4: degeneralization (GO §4) with SCC information, then Büchi simplifications.
template <class A>
Automaton<A> degeneralize(const A& alpha, const Tgba<A>& g, Clock& clock) {
  Automaton<A> ba;
  ba.alphabet = alpha;
  const std::uint32_t n = static_cast<std::uint32_t>(g.out.size());
  const std::size_t k = g.num_acc;
  std::uint32_t count = 0;
  const auto comp = strongly_connected_components(
      g.out, [](const auto& e) { return e.dst; }, &count);
  std::vector<std::vector<std::uint32_t>> members(count);
  for (std::uint32_t s = 0; s < n; ++s) members[comp[s]].push_back(s);
  std::vector<bool> acc_scc(count, false);
  for (std::uint32_t c = 0; c < count; ++c) acc_scc[c] = accepting_scc(g, members[c], comp);
  // BA states (tgba state, level); level k means "every set seen": accepting.
  std::unordered_map<std::uint64_t, std::uint32_t> ids;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> todo;
  auto id_of = [&](std::uint32_t s, std::uint32_t level) {
    const std::uint64_t key = (std::uint64_t{s} << 32) | level;
    auto [it, inserted] = ids.emplace(key, ba.num_states());
    if (inserted) {
      ba.add_state(acc_scc[comp[s]] && level == k);
      todo.push_back({s, level});
      clock.check("the Büchi automaton", ba.num_states());
    }
    return it->second;
  };
  auto advance = [&](std::uint32_t from, const Marks& m) {
    std::uint32_t l = from == k ? 0 : from;
    while (l < k && m.test(l)) ++l;
    return l;
  };
  // Initial states start at the accepting level (as LTL2BA does): for G(p -> F q) this
  // gives the 2-state automaton instead of 3.
  for (std::uint32_t s : g.initial) {
    ba.initial.push_back(id_of(s, acc_scc[comp[s]] ? static_cast<std::uint32_t>(k) : 0));
  }
  while (!todo.empty()) {
    const auto [s, level] = todo.back();
    todo.pop_back();
    const std::uint32_t src = ids.at((std::uint64_t{s} << 32) | level);
    for (const auto& e : g.out[s]) {
      std::uint32_t l = 0;
      if (acc_scc[comp[e.dst]]) {
        // Inside an accepting SCC the level advances; entering one starts from level 0.
        l = comp[e.dst] == comp[s] ? advance(level, e.marks) : advance(0, e.marks);
      }
      ba.add_edge(src, id_of(e.dst, l), e.guard);
    }
  }
  return ba;
}

template <class A>
void simplify_ba(Automaton<A>& ba) {
  using Edge = typename Automaton<A>::Edge;
  struct G {
    std::vector<std::vector<Edge>> out;
    std::vector<std::uint32_t> initial;
  };
  auto dst_of = [](const Edge& e) { return e.dst; };
  // 1. Remove states that cannot reach an accepting cycle (or are unreachable).
  G g{std::move(ba.out), std::move(ba.initial)};
  const std::vector<bool> acc = ba.accepting;
  const auto renum = prune(
      g, dst_of, [](Edge& e, std::uint32_t d) { e.dst = d; },
      [&](const std::vector<std::uint32_t>& members, const std::vector<std::uint32_t>& comp) {
        bool has_acc = false, cyclic = false;
        for (std::uint32_t s : members) {
          has_acc = has_acc || acc[s];
          for (const Edge& e : g.out[s]) cyclic = cyclic || comp[e.dst] == comp[s];
        }
        return has_acc && cyclic;
      });
  const std::uint32_t n = static_cast<std::uint32_t>(g.out.size());
  std::vector<std::uint32_t> cls(n, 0);
  for (std::size_t s = 0; s < renum.size(); ++s) {
    if (renum[s] != ~0u) cls[renum[s]] = acc[s] ? 1 : 0;
  }
  // 2. Merge bisimilar states (same acceptance, same guards into each class).
  std::uint32_t k = 0;
  const auto merged = n == 0 ? cls
                             : bisimulation(
                                   ba.alphabet, n, cls,
                                   [&](std::uint32_t s, auto&& emit) {
                                     for (const Edge& e : g.out[s]) emit(e.dst, e.guard, 0);
                                   },
                                   k);
  Automaton<A> out;
  out.alphabet = ba.alphabet;
  for (std::uint32_t c = 0; c < k; ++c) out.add_state(false);
  std::vector<bool> done(k, false);
  for (std::uint32_t s = 0; s < n; ++s) {
    const std::uint32_t c = merged[s];
    if (done[c]) continue;
    done[c] = true;
    out.accepting[c] = cls[s] == 1;
    for (const Edge& e : g.out[s]) out.add_edge(c, merged[e.dst], e.guard);
  }
  for (std::uint32_t s : g.initial) out.initial.push_back(merged[s]);
  std::sort(out.initial.begin(), out.initial.end());
  out.initial.erase(std::unique(out.initial.begin(), out.initial.end()), out.initial.end());
  ba = std::move(out);
}

// The guard of a propositional NNF formula (tt, ff, p, !p, &, |).
template <class A>
typename A::Guard guard_of(const A& alpha, const Formula& f) {
  switch (f.op()) {
    case Op::True:
      return alpha.top();
    case Op::False:
      return alpha.bottom();
    case Op::Ap:
    case Op::Not: {
      const bool positive = f.op() == Op::Ap;
      const int i = alpha.find_ap(positive ? f.name() : f.child(0).name());
      REARM_DEMAND(i >= 0, "proposition missing from the alphabet");
      return alpha.ap(static_cast<std::uint32_t>(i), positive);
    }
    case Op::And:
    case Op::Or: {
      typename A::Guard g = f.op() == Op::And ? alpha.top() : alpha.bottom();
      for (const Formula& c : f.children()) {
        g = f.op() == Op::And ? alpha.conj(g, guard_of(alpha, c))
                              : alpha.disj(g, guard_of(alpha, c));
      }
      return g;
    }
    default:
      REARM_DEMAND(false, "guard_of: not a propositional NNF formula");
  }
  return alpha.bottom();
}

// φ_1, ..., φ_n when f (rewritten, NNF) is G F φ_1 & ... & G F φ_n with n >= 2 and every φ_i
// propositional: the form the rewriting GF(a & F b) == GF a & GF b gives a sequenced patrol
// GF(p1 & F(p2 & ... F pn)). Empty otherwise.
std::vector<Formula> recurrence_conjuncts(const Formula& f) {
  if (f.op() != Op::And) return {};
  std::vector<Formula> phis;
  for (const Formula& c : f.children()) {
    if (c.op() != Op::Always || c.child(0).op() != Op::Eventually ||
        !c.child(0).child(0).is_boolean()) {
      return {};
    }
    phis.push_back(c.child(0).child(0));
  }
  return phis;
}

// The Büchi automaton of G F φ_1 & ... & G F φ_n built directly: the degeneralized counter of
// the one-state generalized automaton whose i-th acceptance set is the letters of φ_i (what
// build_tgba and degeneralize give, without the 2^n transitions of the product of the n
// conjuncts' transition sets). Level j < n waits for φ_{j+1}; a letter advances the level as
// far as consecutive φ's hold in it; level n (all seen) is accepting and initial, and moves like
// level 0. n + 1 states, O(n^2) edges.
template <class A>
Automaton<A> recurrence_automaton(const A& alpha, const std::vector<Formula>& phis, Clock& clock) {
  Automaton<A> ba;
  ba.alphabet = alpha;
  const std::size_t n = phis.size();
  std::vector<typename A::Guard> holds, fails;
  for (const Formula& phi : phis) {
    holds.push_back(guard_of(alpha, phi));
    fails.push_back(guard_of(alpha, to_nnf(Formula::lnot(phi))));
  }
  for (std::size_t level = 0; level <= n; ++level) {
    ba.add_state(level == n);
    clock.check("the Büchi automaton", ba.num_states());
  }
  ba.initial.push_back(static_cast<std::uint32_t>(n));
  for (std::size_t level = 0; level <= n; ++level) {
    const std::size_t start = level == n ? 0 : level;
    typename A::Guard prefix = alpha.top();  // φ_{start+1} & ... & φ_j
    for (std::size_t j = start; j < n; ++j) {
      clock.poll("the Büchi automaton");
      ba.add_edge(static_cast<std::uint32_t>(level), static_cast<std::uint32_t>(j),
                  alpha.conj(prefix, fails[j]));
      prefix = alpha.conj(prefix, holds[j]);
      if (alpha.is_false(prefix)) break;
    }
    ba.add_edge(static_cast<std::uint32_t>(level), static_cast<std::uint32_t>(n), prefix);
  }
  return ba;
}

template <class A>
Automaton<A> translate_with(A alpha, const Formula& input, const TranslateOptions& options,
                            TranslationStats* stats) {
  Clock clock(options);
  const Formula f = options.rewrite ? rewrite(input) : to_nnf(input);
  if (const std::vector<Formula> phis = recurrence_conjuncts(f); !phis.empty()) {
    Automaton<A> ba = recurrence_automaton(alpha, phis, clock);
    if (options.simplify) simplify_ba(ba);
    if (stats) {
      TranslationStats st;
      st.rewritten = f.to_string(Syntax::Spot);
      st.acceptance_sets = phis.size();
      st.gba_states = 1;
      st.ba_states = ba.num_states();
      st.ba_edges = ba.num_edges();
      st.milliseconds = clock.ms();
      *stats = std::move(st);
    }
    return ba;
  }
  Vwaa<A> vwaa(alpha, clock);
  Tgba<A> g = build_tgba(alpha, vwaa, f, clock);
  TranslationStats st;
  st.rewritten = f.to_string(Syntax::Spot);
  st.vwaa_states = vwaa.num_states();
  st.acceptance_sets = g.num_acc;
  if (options.simplify) {
    prune(
        g, [](const auto& e) { return e.dst; }, [](auto& e, std::uint32_t d) { e.dst = d; },
        [&](const std::vector<std::uint32_t>& members, const std::vector<std::uint32_t>& c) {
          return accepting_scc(g, members, c);
        });
    merge_tgba_states(alpha, g);
  }
  st.gba_states = g.out.size();
  st.gba_edges = g.num_edges();
  Automaton<A> ba = degeneralize(alpha, g, clock);
  if (options.simplify) simplify_ba(ba);
  st.ba_states = ba.num_states();
  st.ba_edges = ba.num_edges();
  st.milliseconds = clock.ms();
  if (stats) *stats = std::move(st);
  return ba;
}

std::vector<std::string> alphabet_of(const Formula& f, const std::vector<std::string>& extra) {
  std::vector<std::string> aps = f.atomic_propositions();
  for (const std::string& x : extra) {
    if (std::find(aps.begin(), aps.end(), x) == aps.end()) aps.push_back(x);
  }
  return aps;
}

}  // namespace

GeneralNba translate_general(const Formula& f, const TranslateOptions& options,
                             TranslationStats* stats, const std::vector<std::string>& extra_aps) {
  return translate_with(GeneralAlphabet(alphabet_of(f, extra_aps)), f, options, stats);
}

ActionNba translate_actions(const Formula& f, const TranslateOptions& options,
                            TranslationStats* stats, const std::vector<std::string>& extra_aps) {
  return translate_with(ActionAlphabet(alphabet_of(f, extra_aps)), f, options, stats);
}

}  // namespace rearm::ltl
