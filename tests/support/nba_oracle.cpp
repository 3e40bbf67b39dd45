#include "support/nba_oracle.h"

#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <stdexcept>
#include <unordered_map>

namespace rearm::test_support {
namespace {

using ltl::ActionNba;
using ltl::BddManager;
using ltl::GeneralNba;
using Graph = std::vector<std::vector<std::uint32_t>>;

// Whether a cycle reachable from `roots` passes through a vertex with accepting[v].
bool has_accepting_cycle(const Graph& adj, const std::vector<std::uint32_t>& roots,
                         const std::vector<bool>& accepting) {
  const std::vector<int> comp = strongly_connected_components(adj, roots);
  // A component has a cycle iff it has an internal edge (covers self-loops).
  std::vector<bool> cyclic;
  for (std::uint32_t v = 0; v < adj.size(); ++v) {
    if (comp[v] < 0) continue;
    const auto c = static_cast<std::size_t>(comp[v]);
    if (cyclic.size() <= c) cyclic.resize(c + 1, false);
    for (std::uint32_t d : adj[v]) {
      if (comp[d] == comp[v]) cyclic[c] = true;
    }
  }
  for (std::uint32_t v = 0; v < adj.size(); ++v) {
    if (comp[v] >= 0 && accepting[v] && cyclic[static_cast<std::size_t>(comp[v])]) return true;
  }
  return false;
}

// Product of automaton states × lasso positions; node id = q * |w| + k. `enabled(e, k)`
// says whether edge guard e.guard admits the letter at position k.
template <class Nba, class Enabled>
bool accepts_product(const Nba& a, const Lasso& w, Enabled enabled) {
  if (w.loop.empty()) throw std::invalid_argument("accepts: lasso with an empty loop");
  const std::size_t n = w.size();
  const std::size_t num = static_cast<std::size_t>(a.num_states()) * n;
  Graph adj(num);
  std::vector<bool> acc(num, false);
  for (std::uint32_t q = 0; q < a.num_states(); ++q) {
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t id = q * n + k;
      acc[id] = a.accepting[q];
      for (const auto& e : a.out[q]) {
        if (enabled(e.guard, k)) {
          adj[id].push_back(static_cast<std::uint32_t>(e.dst * n + w.successor(k)));
        }
      }
    }
  }
  std::vector<std::uint32_t> roots;
  for (std::uint32_t q0 : a.initial) roots.push_back(static_cast<std::uint32_t>(q0 * n));
  return has_accepting_cycle(adj, roots, acc);
}

// For each BDD variable used by an alphabet's propositions, its name; checks that the two
// alphabets agree (same name <=> same variable).
std::map<std::uint32_t, std::string> shared_variables(const ltl::GeneralAlphabet& x,
                                                      const ltl::GeneralAlphabet& y) {
  if (x.bdd_ptr() != y.bdd_ptr() || !x.bdd_ptr()) {
    throw std::invalid_argument("find_common_word: the automata do not share a BddManager");
  }
  BddManager& bdd = x.bdd();
  std::map<std::uint32_t, std::string> var_name;
  std::map<std::string, std::uint32_t> name_var;
  for (const ltl::GeneralAlphabet* al : {&x, &y}) {
    for (std::uint32_t i = 0; i < al->aps().size(); ++i) {
      const std::string& name = al->aps()[i];
      const BddManager::Ref r = al->ap(i, true);
      if (bdd.is_terminal(r) || bdd.low(r) != BddManager::kFalse ||
          bdd.high(r) != BddManager::kTrue) {
        throw std::invalid_argument("find_common_word: proposition " + name +
                                    " is not a single BDD variable");
      }
      const std::uint32_t v = bdd.top_var(r);
      const auto [it1, new_var] = var_name.emplace(v, name);
      const auto [it2, new_name] = name_var.emplace(name, v);
      if (it1->second != name || it2->second != v) {
        throw std::invalid_argument("find_common_word: proposition " + name +
                                    " denotes different BDD variables in the two alphabets");
      }
    }
  }
  return var_name;
}

// Shortest path inside the vertex set `allowed` from `from` to a vertex satisfying
// `target`, as the list of vertices after `from` (empty when `from` itself is a target and
// !must_move). Returns nullopt when none.
template <class Target>
std::optional<std::vector<std::uint32_t>> bfs_path(const Graph& adj, std::uint32_t from,
                                                   const std::vector<bool>& allowed, Target target,
                                                   bool must_move) {
  if (!must_move && target(from)) return std::vector<std::uint32_t>{};
  constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> parent(adj.size(), kNone);
  std::vector<bool> seen(adj.size(), false);
  std::vector<std::uint32_t> queue;
  // With must_move, `from` is not marked seen, so a cycle back to it is found.
  auto discover = [&](std::uint32_t u) {
    for (std::uint32_t d : adj[u]) {
      if (!allowed[d] || seen[d]) continue;
      seen[d] = true;
      parent[d] = u;
      queue.push_back(d);
    }
  };
  if (!must_move) seen[from] = true;
  discover(from);
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const std::uint32_t u = queue[head];
    if (target(u)) {
      std::vector<std::uint32_t> path{u};
      for (std::uint32_t v = parent[u]; v != from; v = parent[v]) path.push_back(v);
      std::reverse(path.begin(), path.end());
      return path;
    }
    discover(u);
  }
  return std::nullopt;
}

std::string letter_of(const Lasso& w, std::size_t pos) {
  std::string s = "{";
  const auto names = w.true_aps(pos);
  for (std::size_t i = 0; i < names.size(); ++i) s += (i ? "," : "") + names[i];
  return s + "}";
}

}  // namespace

std::vector<int> strongly_connected_components(const Graph& adj,
                                               const std::vector<std::uint32_t>& roots) {
  const std::size_t n = adj.size();
  constexpr std::uint32_t kUnvisited = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> index(n, kUnvisited), low(n, 0);
  std::vector<bool> on_stack(n, false);
  std::vector<int> comp(n, -1);
  std::vector<std::uint32_t> stack;
  // Call stack of (vertex, next successor position).
  std::vector<std::pair<std::uint32_t, std::size_t>> calls;
  std::uint32_t counter = 0;
  int num_comps = 0;
  for (std::uint32_t root : roots) {
    if (root >= n) throw std::invalid_argument("strongly_connected_components: bad root");
    if (index[root] != kUnvisited) continue;
    index[root] = low[root] = counter++;
    stack.push_back(root);
    on_stack[root] = true;
    calls.emplace_back(root, 0);
    while (!calls.empty()) {
      auto& [v, pos] = calls.back();
      if (pos < adj[v].size()) {
        const std::uint32_t d = adj[v][pos++];
        if (index[d] == kUnvisited) {
          index[d] = low[d] = counter++;
          stack.push_back(d);
          on_stack[d] = true;
          calls.emplace_back(d, 0);  // invalidates v, pos: loop re-reads calls.back()
        } else if (on_stack[d]) {
          low[v] = std::min(low[v], index[d]);
        }
        continue;
      }
      const std::uint32_t done = v;
      calls.pop_back();
      if (low[done] == index[done]) {
        std::uint32_t x;
        do {
          x = stack.back();
          stack.pop_back();
          on_stack[x] = false;
          comp[x] = num_comps;
        } while (x != done);
        ++num_comps;
      }
      if (!calls.empty()) {
        const std::uint32_t parent = calls.back().first;
        low[parent] = std::min(low[parent], low[done]);
      }
    }
  }
  return comp;
}

bool accepts(const GeneralNba& a, const Lasso& w) {
  // Symbol at each position over the automaton's propositions.
  std::vector<std::vector<bool>> sym(w.size(), std::vector<bool>(a.alphabet.aps().size()));
  for (std::size_t j = 0; j < a.alphabet.aps().size(); ++j) {
    const int i = w.find_ap(a.alphabet.aps()[j]);
    if (i < 0) continue;
    for (std::size_t k = 0; k < w.size(); ++k) sym[k][j] = w.letter(k)[static_cast<std::size_t>(i)];
  }
  return accepts_product(a, w, [&](const GeneralNba::Guard& g, std::size_t k) {
    return a.alphabet.contains(g, sym[k]);
  });
}

bool accepts(const ActionNba& a, const Lasso& w) {
  std::vector<std::size_t> letter(w.size(), 0);
  for (std::size_t j = 0; j < a.alphabet.aps().size(); ++j) {
    const int i = w.find_ap(a.alphabet.aps()[j]);
    if (i < 0) continue;
    for (std::size_t k = 0; k < w.size(); ++k) {
      if (!w.letter(k)[static_cast<std::size_t>(i)]) continue;
      if (letter[k] != 0) {
        throw std::invalid_argument("accepts(ActionNba): two propositions hold at position " +
                                    std::to_string(k) + " of " + w.to_string());
      }
      letter[k] = j + 1;
    }
  }
  return accepts_product(a, w, [&](const ActionNba::Guard& g, std::size_t k) {
    return a.alphabet.contains(g, letter[k]);
  });
}

std::string ProductWitness::to_string() const {
  auto state = [](const ProductState& s) {
    std::string out = "(";
    out += std::to_string(s.first);
    out += ',';
    out += std::to_string(s.second);
    return out + ")";
  };
  std::string out = "prefix:";
  for (std::size_t i = 0; i < prefix_states.size(); ++i) {
    out += ' ';
    out += state(prefix_states[i]);
    out += " -";
    out += letter_of(word, i);
    out += "->";
  }
  out += " cycle:";
  for (std::size_t i = 0; i < cycle_states.size(); ++i) {
    out += ' ';
    out += state(cycle_states[i]);
    out += " -";
    out += letter_of(word, word.prefix.size() + i);
    out += "->";
  }
  return out + " word: " + word.to_string();
}

std::vector<Lasso> sample_accepted_lassos(const GeneralNba& a, Rng& rng, std::size_t count,
                                          std::size_t max_length) {
  BddManager& bdd = a.alphabet.bdd();
  const std::uint32_t n = a.num_states();
  // Live states: those that reach a cycle through an accepting state.
  Graph adj(n), radj(n);
  std::vector<std::uint32_t> all(n);
  for (std::uint32_t q = 0; q < n; ++q) {
    all[q] = q;
    for (const auto& e : a.out[q]) {
      if (e.guard == BddManager::kFalse) continue;
      adj[q].push_back(e.dst);
      radj[e.dst].push_back(q);
    }
  }
  const std::vector<int> comp = strongly_connected_components(adj, all);
  std::vector<bool> live(n, false);
  std::vector<std::uint32_t> work;
  for (std::uint32_t q = 0; q < n; ++q) {
    if (!a.accepting[q]) continue;
    for (std::uint32_t d : adj[q]) {
      if (comp[d] == comp[q] && !live[q]) {
        live[q] = true;
        work.push_back(q);
      }
    }
  }
  while (!work.empty()) {
    const std::uint32_t q = work.back();
    work.pop_back();
    for (std::uint32_t p : radj[q]) {
      if (!live[p]) {
        live[p] = true;
        work.push_back(p);
      }
    }
  }
  std::vector<std::uint32_t> starts;
  for (std::uint32_t q0 : a.initial) {
    if (live[q0]) starts.push_back(q0);
  }
  std::vector<Lasso> out;
  if (starts.empty() || max_length == 0) return out;
  const std::size_t num_aps = a.alphabet.aps().size();
  std::vector<std::uint32_t> var_of(num_aps);
  for (std::uint32_t i = 0; i < num_aps; ++i) var_of[i] = bdd.top_var(a.alphabet.ap(i, true));
  auto random_symbol = [&](BddManager::Ref g) {
    const std::vector<ltl::Cube> cubes = bdd.cubes(g);
    const ltl::Cube& c = cubes[rng.index(cubes.size())];
    Lasso::Letter l(num_aps);
    for (std::size_t i = 0; i < num_aps; ++i) {
      const auto it = std::find_if(c.begin(), c.end(),
                                   [&](const ltl::Literal& x) { return x.var == var_of[i]; });
      l[i] = it != c.end() ? it->positive : rng.bernoulli(0.5);
    }
    return l;
  };
  for (std::size_t attempt = 0; attempt < 20 * count && out.size() < count; ++attempt) {
    std::vector<std::uint32_t> states{starts[rng.index(starts.size())]};
    std::vector<Lasso::Letter> letters;
    while (letters.size() < max_length) {
      const std::uint32_t q = states.back();
      std::vector<const GeneralNba::Edge*> next;
      for (const auto& e : a.out[q]) {
        if (e.guard != BddManager::kFalse && live[e.dst]) next.push_back(&e);
      }
      if (next.empty()) break;
      const GeneralNba::Edge& e = *next[rng.index(next.size())];
      letters.push_back(random_symbol(e.guard));
      states.push_back(e.dst);
      // Close a cycle at an earlier visit of e.dst whose cycle has an accepting state.
      std::optional<std::size_t> loop_start;
      bool acc = false;
      for (std::size_t j = states.size() - 1; j-- > 0;) {
        acc = acc || a.accepting[states[j]];
        if (states[j] == e.dst && acc) {
          loop_start = j;
          break;
        }
      }
      if (loop_start && (letters.size() == max_length || rng.bernoulli(0.5))) {
        Lasso w;
        w.aps = a.alphabet.aps();
        w.prefix.assign(letters.begin(),
                        letters.begin() + static_cast<std::ptrdiff_t>(*loop_start));
        w.loop.assign(letters.begin() + static_cast<std::ptrdiff_t>(*loop_start), letters.end());
        out.push_back(std::move(w));
        break;
      }
    }
  }
  return out;
}

std::optional<ProductWitness> find_common_word(const GeneralNba& a, const GeneralNba& b) {
  const std::map<std::uint32_t, std::string> var_name = shared_variables(a.alphabet, b.alphabet);
  BddManager& bdd = a.alphabet.bdd();
  const std::size_t nb = b.num_states();
  auto id = [&](std::uint32_t qa, std::uint32_t qb) {
    return static_cast<std::uint32_t>(qa * nb + qb);
  };
  // Explore the reachable product; vertices are dense ids qa * |b| + qb.
  const std::size_t num = static_cast<std::size_t>(a.num_states()) * nb;
  Graph adj(num);
  std::vector<bool> reached(num, false);
  std::vector<std::uint32_t> roots, work;
  for (std::uint32_t qa : a.initial) {
    for (std::uint32_t qb : b.initial) {
      const std::uint32_t v = id(qa, qb);
      roots.push_back(v);
      if (!reached[v]) {
        reached[v] = true;
        work.push_back(v);
      }
    }
  }
  while (!work.empty()) {
    const std::uint32_t v = work.back();
    work.pop_back();
    const std::uint32_t qa = static_cast<std::uint32_t>(v / nb);
    const std::uint32_t qb = static_cast<std::uint32_t>(v % nb);
    for (const auto& ea : a.out[qa]) {
      for (const auto& eb : b.out[qb]) {
        if (!bdd.intersects(ea.guard, eb.guard)) continue;
        const std::uint32_t d = id(ea.dst, eb.dst);
        adj[v].push_back(d);
        if (!reached[d]) {
          reached[d] = true;
          work.push_back(d);
        }
      }
    }
  }
  const std::vector<int> comp = strongly_connected_components(adj, roots);
  // Per component: has an internal edge, an accepting state of a, one of b.
  std::unordered_map<int, std::array<bool, 3>> info;
  for (std::uint32_t v = 0; v < num; ++v) {
    if (comp[v] < 0) continue;
    auto& f = info[comp[v]];
    for (std::uint32_t d : adj[v]) f[0] = f[0] || comp[d] == comp[v];
    f[1] = f[1] || a.accepting[v / nb];
    f[2] = f[2] || b.accepting[v % nb];
  }
  int good = -1;
  for (const auto& [c, f] : info) {
    if (f[0] && f[1] && f[2] && (good < 0 || c < good)) good = c;
  }
  if (good < 0) return std::nullopt;

  // Witness: shortest path from a root into the component, then a cycle inside it through an
  // accepting state of a and one of b.
  std::vector<bool> inside(num, false);
  for (std::uint32_t v = 0; v < num; ++v) inside[v] = comp[v] == good;
  std::vector<std::uint32_t> prefix;
  std::uint32_t s = 0;
  {
    bool found = false;
    for (std::uint32_t r : roots) {
      if (comp[r] == good) {
        s = r;
        found = true;
        break;
      }
    }
    if (!found) {
      // BFS from all roots together.
      constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
      std::vector<std::uint32_t> parent(num, kNone);
      std::vector<bool> seen(num, false);
      std::vector<std::uint32_t> queue;
      for (std::uint32_t r : roots) {
        if (!seen[r]) {
          seen[r] = true;
          queue.push_back(r);
        }
      }
      for (std::size_t head = 0; head < queue.size() && !found; ++head) {
        for (std::uint32_t d : adj[queue[head]]) {
          if (seen[d]) continue;
          seen[d] = true;
          parent[d] = queue[head];
          queue.push_back(d);
          if (inside[d]) {
            s = d;
            found = true;
            break;
          }
        }
      }
      for (std::uint32_t v = parent[s]; v != kNone; v = parent[v]) prefix.push_back(v);
      std::reverse(prefix.begin(), prefix.end());
    }
  }
  std::vector<std::uint32_t> cycle{s};
  std::uint32_t cur = s;
  auto extend = [&](auto target, bool must_move) {
    auto seg = bfs_path(adj, cur, inside, target, must_move);
    if (!seg) throw std::logic_error("find_common_word: SCC path search failed");
    for (std::uint32_t v : *seg) cycle.push_back(v);
    if (!seg->empty()) cur = seg->back();
  };
  extend([&](std::uint32_t v) { return static_cast<bool>(a.accepting[v / nb]); }, false);
  extend([&](std::uint32_t v) { return static_cast<bool>(b.accepting[v % nb]); }, false);
  extend([&](std::uint32_t v) { return v == s; }, cycle.size() == 1);
  cycle.pop_back();  // the final s closes the cycle

  ProductWitness wit;
  for (const auto& [v, name] : var_name) wit.word.aps.push_back(name);
  std::sort(wit.word.aps.begin(), wit.word.aps.end());
  auto to_pair = [&](std::uint32_t v) {
    return ProductWitness::ProductState{static_cast<std::uint32_t>(v / nb),
                                        static_cast<std::uint32_t>(v % nb)};
  };
  // The letter on product edge u -> d: a satisfying assignment of the conjunction of the
  // guards, unconstrained propositions false.
  auto letter = [&](std::uint32_t u, std::uint32_t d) {
    BddManager::Ref ga = BddManager::kFalse, gb = BddManager::kFalse;
    for (const auto& e : a.out[u / nb]) {
      if (e.dst == d / nb) ga = bdd.disj(ga, e.guard);
    }
    for (const auto& e : b.out[u % nb]) {
      if (e.dst == d % nb) gb = bdd.disj(gb, e.guard);
    }
    const std::vector<ltl::Cube> cubes = bdd.cubes(bdd.conj(ga, gb));
    if (cubes.empty()) throw std::logic_error("find_common_word: empty product edge");
    Lasso::Letter l(wit.word.aps.size(), false);
    for (const ltl::Literal& lit : cubes.front()) {
      const auto it = var_name.find(lit.var);
      if (it == var_name.end() || !lit.positive) continue;
      l[static_cast<std::size_t>(wit.word.find_ap(it->second))] = true;
    }
    return l;
  };
  for (std::size_t i = 0; i < prefix.size(); ++i) {
    wit.prefix_states.push_back(to_pair(prefix[i]));
    wit.word.prefix.push_back(letter(prefix[i], i + 1 < prefix.size() ? prefix[i + 1] : s));
  }
  for (std::size_t i = 0; i < cycle.size(); ++i) {
    wit.cycle_states.push_back(to_pair(cycle[i]));
    wit.word.loop.push_back(letter(cycle[i], cycle[(i + 1) % cycle.size()]));
  }
  return wit;
}

}  // namespace rearm::test_support
