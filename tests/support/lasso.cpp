#include "support/lasso.h"

#include <algorithm>
#include <set>
#include <stdexcept>
#include <unordered_map>

namespace rearm::test_support {
namespace {

using ltl::Formula;
using ltl::Op;
using Values = std::vector<bool>;

std::string letter_string(const Lasso& w, std::size_t pos) {
  std::string s = "{";
  bool first = true;
  for (const std::string& name : w.true_aps(pos)) {
    if (!first) s += ',';
    s += name;
    first = false;
  }
  return s + "}";
}

// Evaluates every subformula once (memoized on the shared node) at all positions.
class Evaluator {
 public:
  explicit Evaluator(const Lasso& w) : w_(w), n_(w.size()) {}

  const Values& eval(const Formula& f) {
    auto it = memo_.find(f.node_id());
    if (it != memo_.end()) return it->second;
    Values v = compute(f);
    return memo_.emplace(f.node_id(), std::move(v)).first->second;
  }

 private:
  // Fixpoint of X[i] = step(i, X[succ(i)]) starting from all `init` (false: least fixpoint,
  // true: greatest). `step` must be monotone in its second argument, so the iteration
  // converges in at most n+1 rounds.
  template <class Step>
  Values fixpoint(bool init, Step step) const {
    Values x(n_, init);
    bool changed = true;
    while (changed) {
      changed = false;
      for (std::size_t k = n_; k-- > 0;) {
        const bool nv = step(k, x[w_.successor(k)]);
        if (nv != x[k]) {
          x[k] = nv;
          changed = true;
        }
      }
    }
    return x;
  }

  Values compute(const Formula& f) {
    switch (f.op()) {
      case Op::True:
        return Values(n_, true);
      case Op::False:
        return Values(n_, false);
      case Op::Ap: {
        Values v(n_);
        for (std::size_t k = 0; k < n_; ++k) v[k] = w_.holds(k, f.name());
        return v;
      }
      case Op::Not: {
        Values v = eval(f.child(0));
        for (std::size_t k = 0; k < n_; ++k) v[k] = !v[k];
        return v;
      }
      case Op::And: {
        Values v(n_, true);
        for (const Formula& c : f.children()) {
          const Values& cv = eval(c);
          for (std::size_t k = 0; k < n_; ++k) v[k] = v[k] && cv[k];
        }
        return v;
      }
      case Op::Or: {
        Values v(n_, false);
        for (const Formula& c : f.children()) {
          const Values& cv = eval(c);
          for (std::size_t k = 0; k < n_; ++k) v[k] = v[k] || cv[k];
        }
        return v;
      }
      case Op::Implies:
      case Op::Equiv:
      case Op::Xor: {
        const Values a = eval(f.child(0));
        const Values& b = eval(f.child(1));
        Values v(n_);
        for (std::size_t k = 0; k < n_; ++k) {
          if (f.op() == Op::Implies) v[k] = !a[k] || b[k];
          if (f.op() == Op::Equiv) v[k] = a[k] == b[k];
          if (f.op() == Op::Xor) v[k] = a[k] != b[k];
        }
        return v;
      }
      case Op::Next: {
        const Values& a = eval(f.child(0));
        Values v(n_);
        for (std::size_t k = 0; k < n_; ++k) v[k] = a[w_.successor(k)];
        return v;
      }
      case Op::Eventually: {  // F a = mu X. a | X X
        const Values a = eval(f.child(0));
        return fixpoint(false, [&](std::size_t k, bool next) { return a[k] || next; });
      }
      case Op::Always: {  // G a = nu X. a & X X
        const Values a = eval(f.child(0));
        return fixpoint(true, [&](std::size_t k, bool next) { return a[k] && next; });
      }
      case Op::Until:        // a U b = mu X. b | (a & X X)
      case Op::WeakUntil: {  // a W b = nu X. b | (a & X X)
        const Values a = eval(f.child(0));
        const Values b = eval(f.child(1));
        return fixpoint(f.op() == Op::WeakUntil,
                        [&](std::size_t k, bool next) { return b[k] || (a[k] && next); });
      }
      case Op::Release:          // a R b = nu X. b & (a | X X)
      case Op::StrongRelease: {  // a M b = mu X. b & (a | X X)
        const Values a = eval(f.child(0));
        const Values b = eval(f.child(1));
        return fixpoint(f.op() == Op::Release,
                        [&](std::size_t k, bool next) { return b[k] && (a[k] || next); });
      }
    }
    throw std::logic_error("evaluate: unknown operator");
  }

  const Lasso& w_;
  std::size_t n_;
  std::unordered_map<const void*, Values> memo_;
};

}  // namespace

Lasso Lasso::from_names(const std::vector<std::vector<std::string>>& prefix,
                        const std::vector<std::vector<std::string>>& loop,
                        const std::vector<std::string>& extra_aps) {
  std::set<std::string> names(extra_aps.begin(), extra_aps.end());
  for (const auto& l : prefix) names.insert(l.begin(), l.end());
  for (const auto& l : loop) names.insert(l.begin(), l.end());
  Lasso w;
  w.aps.assign(names.begin(), names.end());
  auto convert = [&](const std::vector<std::string>& names_true) {
    Letter letter(w.aps.size(), false);
    for (const std::string& n : names_true) letter[static_cast<std::size_t>(w.find_ap(n))] = true;
    return letter;
  };
  for (const auto& l : prefix) w.prefix.push_back(convert(l));
  for (const auto& l : loop) w.loop.push_back(convert(l));
  return w;
}

int Lasso::find_ap(const std::string& name) const {
  const auto it = std::find(aps.begin(), aps.end(), name);
  return it == aps.end() ? -1 : static_cast<int>(it - aps.begin());
}

bool Lasso::holds(std::size_t pos, const std::string& name) const {
  const int i = find_ap(name);
  return i >= 0 && letter(pos)[static_cast<std::size_t>(i)];
}

std::vector<std::string> Lasso::true_aps(std::size_t pos) const {
  std::vector<std::string> out;
  const Letter& l = letter(pos);
  for (std::size_t i = 0; i < aps.size(); ++i) {
    if (l[i]) out.push_back(aps[i]);
  }
  return out;
}

std::string Lasso::to_string() const {
  std::string s = "u=(";
  for (std::size_t k = 0; k < prefix.size(); ++k) s += letter_string(*this, k);
  s += ") v=(";
  for (std::size_t k = prefix.size(); k < size(); ++k) s += letter_string(*this, k);
  return s + ")";
}

Lasso random_lasso(Rng& rng, const std::vector<std::string>& aps, const LassoOptions& o) {
  if (o.min_loop < 1 || o.min_loop > o.max_loop || o.min_prefix > o.max_prefix) {
    throw std::invalid_argument("random_lasso: bad length ranges");
  }
  Lasso w;
  w.aps = aps;
  auto letter = [&] {
    Lasso::Letter l(aps.size(), false);
    if (o.one_hot) {
      const std::uint64_t c = rng.index(aps.size() + 1);
      if (c > 0) l[c - 1] = true;
    } else {
      for (std::size_t i = 0; i < aps.size(); ++i) l[i] = rng.bernoulli(o.p_true);
    }
    return l;
  };
  const auto len = [&](std::size_t lo, std::size_t hi) {
    return static_cast<std::size_t>(
        rng.uniform_int(static_cast<std::int64_t>(lo), static_cast<std::int64_t>(hi)));
  };
  const std::size_t nu = len(o.min_prefix, o.max_prefix);
  const std::size_t nv = len(o.min_loop, o.max_loop);
  for (std::size_t k = 0; k < nu; ++k) w.prefix.push_back(letter());
  for (std::size_t k = 0; k < nv; ++k) w.loop.push_back(letter());
  return w;
}

bool for_each_lasso(const std::vector<std::string>& aps, std::size_t max_prefix,
                    std::size_t max_loop, bool one_hot,
                    const std::function<bool(const Lasso&)>& visit) {
  // All letters of the alphabet.
  std::vector<Lasso::Letter> letters;
  if (one_hot) {
    letters.emplace_back(aps.size(), false);
    for (std::size_t i = 0; i < aps.size(); ++i) {
      letters.emplace_back(aps.size(), false);
      letters.back()[i] = true;
    }
  } else {
    if (aps.size() >= 20) throw std::invalid_argument("for_each_lasso: alphabet too large");
    for (std::size_t m = 0; m < (std::size_t{1} << aps.size()); ++m) {
      Lasso::Letter l(aps.size());
      for (std::size_t i = 0; i < aps.size(); ++i) l[i] = (m >> i) & 1;
      letters.push_back(std::move(l));
    }
  }
  Lasso w;
  w.aps = aps;
  for (std::size_t nu = 0; nu <= max_prefix; ++nu) {
    for (std::size_t nv = 1; nv <= max_loop; ++nv) {
      // Odometer over the nu + nv letter indices.
      std::vector<std::size_t> digit(nu + nv, 0);
      while (true) {
        w.prefix.clear();
        w.loop.clear();
        for (std::size_t k = 0; k < nu; ++k) w.prefix.push_back(letters[digit[k]]);
        for (std::size_t k = nu; k < nu + nv; ++k) w.loop.push_back(letters[digit[k]]);
        if (!visit(w)) return false;
        std::size_t k = 0;
        while (k < digit.size() && ++digit[k] == letters.size()) digit[k++] = 0;
        if (k == digit.size()) break;
      }
    }
  }
  return true;
}

std::vector<bool> evaluate_all(const ltl::Formula& f, const Lasso& w) {
  if (w.loop.empty()) throw std::invalid_argument("evaluate: lasso with an empty loop");
  Evaluator e(w);
  return e.eval(f);
}

bool evaluate(const ltl::Formula& f, const Lasso& w) { return evaluate_all(f, w)[0]; }

}  // namespace rearm::test_support
