// s^{1/p} for s in [1, 2]: the root of the R-conjunction (docs/reactive.md §3.5), whose
// scaled argument s = |a/m|^p + |b/m|^p always lies in [1, 2]. It is the hot spot of an
// evaluation of h (about 60% of its time with std::pow), and std::pow's latency sits on the
// fold's dependency chain. A table of the root at 2^8 + 1 knots s_i = 1 + i/2^8, each held as
// a double-double (hi + lo, from long double), and the binomial series of (1 + d)^{1/p} for
// the rest, d = (s − s_i)/s_i < 2^−8, six terms (the seventh is below 2^−62 for every p >= 2).
// The result is within one unit in the last place of the exact root (nearly always the
// correctly rounded one; tests/reactive/pth_root_test.cpp), at about half std::pow's latency
// (docs/reactive.md §7). s == 1 gives exactly 1.
#pragma once

#include <array>

namespace rearm::reactive {

class PthRoot {
 public:
  static constexpr int kKnotsLog2 = 8;
  static constexpr int kKnots = 1 << kKnotsLog2;
  static constexpr int kTerms = 6;  // binomial coefficients c_1..c_6

  // The table for an even p >= 2 (throws rearm::Error otherwise).
  explicit PthRoot(int p);

  // One shared immutable table per p, built on first use (thread-safe); the reference stays
  // valid for the program's lifetime.
  static const PthRoot& of(int p);

  int p() const { return p_; }

  // s^{1/p}; s outside [1, 2] (never from the R-conjunction) falls back to std::pow.
  double operator()(double s) const {
    const double e = s - 1;  // exact for s in [1, 2]
    if (e == 0) return 1;
    if (!(e > 0 && e <= 1)) return slow(s);
    const int i = static_cast<int>(e * kKnots);
    // e − i/2^8 is exact (Sterbenz), and d < 2^−8.
    const double d = (e - static_cast<double>(i) / kKnots) * inv_[i];
    // (1 + d)^{1/p} − 1 = d(c1 + c2 d + d²(c3 + c4 d + d²(c5 + c6 d))) (Estrin's scheme: half
    // the dependent operations of Horner's).
    static_assert(kTerms == 6);
    const double d2 = d * d;
    const double q =
        d * ((c_[0] + c_[1] * d) + d2 * ((c_[2] + c_[3] * d) + d2 * (c_[4] + c_[5] * d)));
    return hi_[i] + (lo_[i] + hi_[i] * q);
  }

 private:
  double slow(double s) const;

  int p_;
  std::array<double, kTerms> c_{};  // c_[k] = binom(1/p, k + 1)
  std::array<double, kKnots + 1> hi_{}, lo_{}, inv_{};
};

}  // namespace rearm::reactive
