#include "ltl/letter_set.h"

#include <bit>

#include "core/error.h"

// Invariant: words_ has ceil(n_ / 64) words and every bit at position >= n_ is zero, so the
// defaulted operator== and hash() see only the set itself.

namespace rearm::ltl {
namespace {

constexpr std::size_t kWordBits = 64;

std::size_t num_words(std::size_t n) { return (n + kWordBits - 1) / kWordBits; }

// Mask of the valid bits of the last word of a universe of n letters (all ones if n is a
// multiple of 64).
std::uint64_t last_word_mask(std::size_t n) {
  const std::size_t rem = n % kWordBits;
  return rem == 0 ? ~std::uint64_t{0} : (std::uint64_t{1} << rem) - 1;
}

}  // namespace

LetterSet::LetterSet(std::size_t num_letters, bool full)
    : n_(num_letters), words_(num_words(num_letters), full ? ~std::uint64_t{0} : 0) {
  if (full && !words_.empty()) words_.back() &= last_word_mask(n_);
}

LetterSet LetterSet::single(std::size_t num_letters, std::size_t letter) {
  LetterSet s(num_letters);
  s.set(letter);
  return s;
}

bool LetterSet::test(std::size_t letter) const {
  REARM_DEMAND(letter < n_, "letter outside the universe");
  return (words_[letter / kWordBits] >> (letter % kWordBits)) & 1u;
}

void LetterSet::set(std::size_t letter) {
  REARM_DEMAND(letter < n_, "letter outside the universe");
  words_[letter / kWordBits] |= std::uint64_t{1} << (letter % kWordBits);
}

void LetterSet::reset(std::size_t letter) {
  REARM_DEMAND(letter < n_, "letter outside the universe");
  words_[letter / kWordBits] &= ~(std::uint64_t{1} << (letter % kWordBits));
}

bool LetterSet::empty() const {
  for (std::uint64_t w : words_) {
    if (w != 0) return false;
  }
  return true;
}

bool LetterSet::full() const {
  if (words_.empty()) return true;
  for (std::size_t i = 0; i + 1 < words_.size(); ++i) {
    if (words_[i] != ~std::uint64_t{0}) return false;
  }
  return words_.back() == last_word_mask(n_);
}

std::size_t LetterSet::count() const {
  std::size_t c = 0;
  for (std::uint64_t w : words_) c += static_cast<std::size_t>(std::popcount(w));
  return c;
}

bool LetterSet::subset_of(const LetterSet& o) const {
  REARM_DEMAND(n_ == o.n_, "letter sets over different universes");
  for (std::size_t i = 0; i < words_.size(); ++i) {
    if (words_[i] & ~o.words_[i]) return false;
  }
  return true;
}

bool LetterSet::intersects(const LetterSet& o) const {
  REARM_DEMAND(n_ == o.n_, "letter sets over different universes");
  for (std::size_t i = 0; i < words_.size(); ++i) {
    if (words_[i] & o.words_[i]) return true;
  }
  return false;
}

std::size_t LetterSet::next(std::size_t from) const {
  if (from >= n_) return n_;
  std::size_t i = from / kWordBits;
  std::uint64_t w = words_[i] & (~std::uint64_t{0} << (from % kWordBits));
  while (true) {
    if (w != 0) return i * kWordBits + static_cast<std::size_t>(std::countr_zero(w));
    if (++i == words_.size()) return n_;
    w = words_[i];
  }
}

LetterSet LetterSet::operator&(const LetterSet& o) const {
  LetterSet r = *this;
  r &= o;
  return r;
}

LetterSet LetterSet::operator|(const LetterSet& o) const {
  LetterSet r = *this;
  r |= o;
  return r;
}

LetterSet LetterSet::operator~() const {
  LetterSet r = *this;
  for (std::uint64_t& w : r.words_) w = ~w;
  if (!r.words_.empty()) r.words_.back() &= last_word_mask(n_);
  return r;
}

LetterSet& LetterSet::operator&=(const LetterSet& o) {
  REARM_DEMAND(n_ == o.n_, "letter sets over different universes");
  for (std::size_t i = 0; i < words_.size(); ++i) words_[i] &= o.words_[i];
  return *this;
}

LetterSet& LetterSet::operator|=(const LetterSet& o) {
  REARM_DEMAND(n_ == o.n_, "letter sets over different universes");
  for (std::size_t i = 0; i < words_.size(); ++i) words_[i] |= o.words_[i];
  return *this;
}

std::size_t LetterSet::hash() const {
  std::uint64_t h = 0x9e3779b97f4a7c15ULL ^ n_;
  for (std::uint64_t w : words_) {
    h ^= w + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    h *= 0xd6e8feb86659fd93ULL;
  }
  return static_cast<std::size_t>(h ^ (h >> 32));
}

}  // namespace rearm::ltl
