#include "ltl/bdd.h"

#include <algorithm>
#include <limits>
#include <utility>

#include "core/error.h"

// Representation (contracts the rest of the file relies on):
//  - nodes_[0] and nodes_[1] are the terminals false and true; their stored var is kTermVar
//    (larger than every variable), so "the top variable of a pair" is a plain min(). The
//    public top_var() reports num_vars() for terminals, as the header documents.
//  - Every other node is reduced (low != high) and unique: unique_ is an open-addressing
//    (linear probing) table of Refs, 0 marking an empty slot (node 0 is a terminal, never
//    stored). Its size is a power of two and it is kept at most half full.
//  - No complement edges: f and !f are distinct nodes, and kFalse/kTrue are the only
//    terminals. Negation has its own cache entries.
//  - cache_ is a lossy direct-mapped computed table shared by all operations, keyed by
//    (op, a, b). Entries are never invalid because nodes are never freed.
//  - Nodes are appended to nodes_, so a child always has a smaller Ref than its parent,
//    and recursion depth is bounded by the number of variables.
// Any recursion may throw BudgetExceeded from make(); the manager stays consistent (nodes
// already created are valid, the cache holds only finished results).

namespace rearm::ltl {
namespace {

constexpr std::uint32_t kTermVar = std::numeric_limits<std::uint32_t>::max();

// Operation codes of the computed table (0 = empty entry).
enum Op : std::uint32_t {
  kOpAnd = 1,
  kOpNot = 2,
  kOpOr = 3,
  kOpImplies = 4,
  kOpIntersects = 5,
};

constexpr std::size_t kInitialUniqueSize = 1u << 10;
constexpr std::size_t kInitialCacheSize = 1u << 10;
// The computed table grows with the unique table up to this many entries (16 bytes each).
constexpr std::size_t kMaxCacheSize = std::size_t{1} << 22;

inline std::uint64_t mix(std::uint64_t x) {
  x ^= x >> 32;
  x *= 0xd6e8feb86659fd93ULL;
  x ^= x >> 32;
  return x;
}

inline std::size_t node_hash(std::uint32_t var, std::uint32_t low, std::uint32_t high) {
  return static_cast<std::size_t>(
      mix(((std::uint64_t{low} << 32) | high) * 0x9e3779b97f4a7c15ULL + var));
}

inline std::size_t op_hash(std::uint32_t op, std::uint32_t a, std::uint32_t b) {
  return static_cast<std::size_t>(
      mix(((std::uint64_t{a} << 32) | b) * 0x9e3779b97f4a7c15ULL + op * 0xc2b2ae3d27d4eb4fULL));
}

}  // namespace

BddManager::BddManager(std::uint32_t num_vars, std::size_t max_nodes)
    : num_vars_(num_vars), max_nodes_(max_nodes) {
  REARM_DEMAND(num_vars < kTermVar, "too many BDD variables");
  REARM_DEMAND(max_nodes >= 2, "a BDD node budget must allow the two terminals");
  // Refs are 32-bit; cap the budget so a Ref never wraps.
  max_nodes_ = std::min<std::size_t>(max_nodes_, std::numeric_limits<Ref>::max());
  nodes_.reserve(64);
  nodes_.push_back(Node{kTermVar, kFalse, kFalse});
  nodes_.push_back(Node{kTermVar, kTrue, kTrue});
  unique_.assign(kInitialUniqueSize, 0);
  cache_.assign(kInitialCacheSize, CacheEntry{});
}

std::uint32_t BddManager::num_vars() const { return num_vars_; }

std::uint32_t BddManager::add_var() {
  REARM_DEMAND(num_vars_ + 1 < kTermVar, "too many BDD variables");
  return num_vars_++;
}

BddManager::Ref BddManager::var(std::uint32_t v) {
  REARM_DEMAND(v < num_vars_, "BDD variable out of range");
  return make(v, kFalse, kTrue);
}

BddManager::Ref BddManager::nvar(std::uint32_t v) {
  REARM_DEMAND(v < num_vars_, "BDD variable out of range");
  return make(v, kTrue, kFalse);
}

BddManager::Ref BddManager::cube(const Cube& c) {
  Cube sorted = c;
  std::sort(sorted.begin(), sorted.end(),
            [](const Literal& x, const Literal& y) { return x.var < y.var; });
  // Built bottom-up (largest variable first), so each make() gets reduced children.
  Ref r = kTrue;
  for (std::size_t i = sorted.size(); i-- > 0;) {
    const Literal l = sorted[i];
    REARM_DEMAND(l.var < num_vars_, "BDD variable out of range");
    if (i + 1 < sorted.size() && sorted[i + 1].var == l.var) {
      if (sorted[i + 1].positive != l.positive) return kFalse;  // x & !x
      continue;                                                 // repeated literal
    }
    r = l.positive ? make(l.var, kFalse, r) : make(l.var, r, kFalse);
  }
  return r;
}

BddManager::Ref BddManager::conj(Ref a, Ref b) {
  REARM_DEMAND(a < nodes_.size() && b < nodes_.size(), "invalid BDD Ref");
  return apply_and(a, b);
}

BddManager::Ref BddManager::disj(Ref a, Ref b) {
  REARM_DEMAND(a < nodes_.size() && b < nodes_.size(), "invalid BDD Ref");
  // Shannon expansion, like apply_and with the roles of the terminals swapped.
  auto rec = [this](auto& self, Ref x, Ref y) -> Ref {
    if (x == y || y == kFalse) return x;
    if (x == kFalse) return y;
    if (x == kTrue || y == kTrue) return kTrue;
    if (x > y) std::swap(x, y);
    CacheEntry& e = cache_[op_hash(kOpOr, x, y) & (cache_.size() - 1)];
    if (e.op == kOpOr && e.a == x && e.b == y) return e.r;
    const Node nx = nodes_[x];
    const Node ny = nodes_[y];
    const std::uint32_t v = std::min(nx.var, ny.var);
    const Ref lo = self(self, nx.var == v ? nx.low : x, ny.var == v ? ny.low : y);
    const Ref hi = self(self, nx.var == v ? nx.high : x, ny.var == v ? ny.high : y);
    const Ref r = make(v, lo, hi);
    // make() may have grown (and moved) the cache: index it afresh.
    cache_[op_hash(kOpOr, x, y) & (cache_.size() - 1)] = CacheEntry{x, y, r, kOpOr};
    return r;
  };
  return rec(rec, a, b);
}

BddManager::Ref BddManager::neg(Ref a) {
  REARM_DEMAND(a < nodes_.size(), "invalid BDD Ref");
  return apply_not(a);
}

bool BddManager::implies(Ref a, Ref b) {
  REARM_DEMAND(a < nodes_.size() && b < nodes_.size(), "invalid BDD Ref");
  // Allocation-free: a -> b iff every pair of cofactors implies, terminals decide directly
  // (a non-terminal node of a reduced BDD is neither constant false nor constant true).
  auto rec = [this](auto& self, Ref x, Ref y) -> bool {
    if (x == kFalse || y == kTrue || x == y) return true;
    if (x == kTrue || y == kFalse) return false;
    CacheEntry& e = cache_[op_hash(kOpImplies, x, y) & (cache_.size() - 1)];
    if (e.op == kOpImplies && e.a == x && e.b == y) return e.r != 0;
    const Node nx = nodes_[x];
    const Node ny = nodes_[y];
    const std::uint32_t v = std::min(nx.var, ny.var);
    const bool r = self(self, nx.var == v ? nx.low : x, ny.var == v ? ny.low : y) &&
                   self(self, nx.var == v ? nx.high : x, ny.var == v ? ny.high : y);
    // No node is created here, so `e` still points into the live cache.
    e = CacheEntry{x, y, r ? 1u : 0u, kOpImplies};
    return r;
  };
  return rec(rec, a, b);
}

bool BddManager::intersects(Ref a, Ref b) {
  REARM_DEMAND(a < nodes_.size() && b < nodes_.size(), "invalid BDD Ref");
  auto rec = [this](auto& self, Ref x, Ref y) -> bool {
    if (x == kFalse || y == kFalse) return false;
    // A non-false node is satisfiable, and so is its conjunction with true or itself.
    if (x == kTrue || y == kTrue || x == y) return true;
    if (x > y) std::swap(x, y);
    CacheEntry& e = cache_[op_hash(kOpIntersects, x, y) & (cache_.size() - 1)];
    if (e.op == kOpIntersects && e.a == x && e.b == y) return e.r != 0;
    const Node nx = nodes_[x];
    const Node ny = nodes_[y];
    const std::uint32_t v = std::min(nx.var, ny.var);
    const bool r = self(self, nx.var == v ? nx.low : x, ny.var == v ? ny.low : y) ||
                   self(self, nx.var == v ? nx.high : x, ny.var == v ? ny.high : y);
    e = CacheEntry{x, y, r ? 1u : 0u, kOpIntersects};
    return r;
  };
  return rec(rec, a, b);
}

bool BddManager::eval(Ref f, const std::vector<bool>& assignment) const {
  REARM_DEMAND(f < nodes_.size(), "invalid BDD Ref");
  while (f > kTrue) {
    const Node& n = nodes_[f];
    REARM_DEMAND(n.var < assignment.size(), "BDD assignment shorter than the variables used");
    f = assignment[n.var] ? n.high : n.low;
  }
  return f == kTrue;
}

std::vector<Cube> BddManager::cubes(Ref f) const {
  REARM_DEMAND(f < nodes_.size(), "invalid BDD Ref");
  std::vector<Cube> out;
  Cube path;
  // Depth-first over paths; each path to true is one cube, paths are pairwise disjoint
  // because two paths differ in the value of the variable where they branch apart.
  auto rec = [&](auto& self, Ref g) -> void {
    if (g == kFalse) return;
    if (g == kTrue) {
      out.push_back(path);
      return;
    }
    const Node n = nodes_[g];
    path.push_back(Literal{n.var, false});
    self(self, n.low);
    path.back().positive = true;
    self(self, n.high);
    path.pop_back();
  };
  rec(rec, f);
  return out;
}

std::uint32_t BddManager::top_var(Ref f) const {
  REARM_DEMAND(f < nodes_.size(), "invalid BDD Ref");
  return is_terminal(f) ? num_vars_ : nodes_[f].var;
}

BddManager::Ref BddManager::low(Ref f) const {
  REARM_DEMAND(f < nodes_.size() && !is_terminal(f), "low() of a terminal or invalid Ref");
  return nodes_[f].low;
}

BddManager::Ref BddManager::high(Ref f) const {
  REARM_DEMAND(f < nodes_.size() && !is_terminal(f), "high() of a terminal or invalid Ref");
  return nodes_[f].high;
}

std::size_t BddManager::node_count() const { return nodes_.size(); }

BddManager::Ref BddManager::make(std::uint32_t var, Ref low, Ref high) {
  if (low == high) return low;
  const std::size_t mask = unique_.size() - 1;
  std::size_t i = node_hash(var, low, high) & mask;
  while (true) {
    const Ref r = unique_[i];
    if (r == 0) break;
    const Node& n = nodes_[r];
    if (n.var == var && n.low == low && n.high == high) return r;
    i = (i + 1) & mask;
  }
  if (nodes_.size() >= max_nodes_) {
    throw BudgetExceeded("BDD node budget exceeded: " + std::to_string(max_nodes_) + " nodes (" +
                         std::to_string(num_vars_) + " variables)");
  }
  const Ref r = static_cast<Ref>(nodes_.size());
  nodes_.push_back(Node{var, low, high});
  unique_[i] = r;
  // Keep the table at most half full (nodes_ holds two terminals not in the table).
  if (2 * (nodes_.size() - 2) > unique_.size()) grow_unique();
  return r;
}

BddManager::Ref BddManager::apply_and(Ref a, Ref b) {
  if (a == b || b == kTrue) return a;
  if (a == kTrue) return b;
  if (a == kFalse || b == kFalse) return kFalse;
  if (a > b) std::swap(a, b);  // commutative: one cache entry per unordered pair
  {
    const CacheEntry& e = cache_[op_hash(kOpAnd, a, b) & (cache_.size() - 1)];
    if (e.op == kOpAnd && e.a == a && e.b == b) return e.r;
  }
  const Node na = nodes_[a];
  const Node nb = nodes_[b];
  const std::uint32_t v = std::min(na.var, nb.var);
  const Ref lo = apply_and(na.var == v ? na.low : a, nb.var == v ? nb.low : b);
  const Ref hi = apply_and(na.var == v ? na.high : a, nb.var == v ? nb.high : b);
  const Ref r = make(v, lo, hi);
  cache_[op_hash(kOpAnd, a, b) & (cache_.size() - 1)] = CacheEntry{a, b, r, kOpAnd};
  return r;
}

BddManager::Ref BddManager::apply_not(Ref a) {
  if (a <= kTrue) return a ^ 1u;
  {
    const CacheEntry& e = cache_[op_hash(kOpNot, a, 0) & (cache_.size() - 1)];
    if (e.op == kOpNot && e.a == a) return e.r;
  }
  const Node n = nodes_[a];
  const Ref lo = apply_not(n.low);
  const Ref hi = apply_not(n.high);
  const Ref r = make(n.var, lo, hi);
  cache_[op_hash(kOpNot, a, 0) & (cache_.size() - 1)] = CacheEntry{a, 0, r, kOpNot};
  // Negation is an involution: remember the way back too.
  cache_[op_hash(kOpNot, r, 0) & (cache_.size() - 1)] = CacheEntry{r, 0, a, kOpNot};
  return r;
}

void BddManager::grow_unique() {
  const std::size_t size = unique_.size() * 2;
  std::vector<Ref> table(size, 0);
  const std::size_t mask = size - 1;
  for (std::size_t r = 2; r < nodes_.size(); ++r) {
    const Node& n = nodes_[r];
    std::size_t i = node_hash(n.var, n.low, n.high) & mask;
    while (table[i] != 0) i = (i + 1) & mask;
    table[i] = static_cast<Ref>(r);
  }
  unique_.swap(table);

  // Grow the computed table alongside (bounded), keeping the results it already holds.
  const std::size_t cache_size = std::min(size, kMaxCacheSize);
  if (cache_size > cache_.size()) {
    std::vector<CacheEntry> cache(cache_size);
    for (const CacheEntry& e : cache_) {
      if (e.op != 0) cache[op_hash(e.op, e.a, e.b) & (cache_size - 1)] = e;
    }
    cache_.swap(cache);
  }
}

}  // namespace rearm::ltl
