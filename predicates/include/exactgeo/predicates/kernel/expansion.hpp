#pragma once

// Floating-point expansions: an exact real number stored as a sum of doubles
// (Shewchuk 1997, sections 2.4-2.8). Components are nonoverlapping, sorted by
// increasing magnitude and never zero; the number zero is the empty expansion. The sign
// of an expansion is the sign of its largest component.
//
// Expansion<N> holds at most N components on the stack: no heap on the exact path. The
// capacity of a result is part of its type (a sum of N and M components fits in N + M,
// a product in 2NM), so every operation below is exact and cannot overflow its storage.
// Where capacities would explode (products of long products), callers compress and then
// narrow<K>() at run time, which reports "does not fit" as std::nullopt.
//
// Exactness also needs the inputs to be in range: no overflow anywhere and no underflow
// in products; see exponent_range.hpp.

#include <cmath>
#include <cstddef>
#include <optional>

#include "exactgeo/predicates/kernel/error_free.hpp"
#include "exactgeo/predicates/sign.hpp"

namespace exactgeo::kernel {

namespace internal {

// h = e + f. Inputs nonoverlapping and increasing in magnitude, zero-free; so is h.
// Returns the length of h (Shewchuk's FAST-EXPANSION-SUM with zero elimination; the
// comparisons never read past the end of e or f).
inline int sum(const double* e, int e_len, const double* f, int f_len, double* h) noexcept {
  if (e_len == 0 || f_len == 0) {
    const double* src = e_len == 0 ? f : e;
    const int len = e_len == 0 ? f_len : e_len;
    for (int i = 0; i < len; ++i)
      h[i] = src[i];
    return len;
  }
  int i = 0;
  int j = 0;
  // Components in order of increasing magnitude, taken from e and f alternately.
  auto next = [&]() noexcept {
    if (j >= f_len || (i < e_len && std::fabs(e[i]) <= std::fabs(f[j]))) return e[i++];
    return f[j++];
  };
  int h_len = 0;
  double q = next();
  const int total = e_len + f_len;
  if (i + j < total) {
    const TwoTerm first = fast_two_sum(next(), q);
    q = first.head;
    if (first.tail != 0.0) h[h_len++] = first.tail;
    while (i + j < total) {
      const TwoTerm s = two_sum(q, next());
      q = s.head;
      if (s.tail != 0.0) h[h_len++] = s.tail;
    }
  }
  if (q != 0.0) h[h_len++] = q;
  return h_len;
}

// h = e * b (Shewchuk's SCALE-EXPANSION with zero elimination). h has room for 2 e_len.
inline int scale(const double* e, int e_len, double b, double* h) noexcept {
  if (e_len == 0 || b == 0.0) return 0;
  int h_len = 0;
  TwoTerm p = two_product(e[0], b);
  double q = p.head;
  if (p.tail != 0.0) h[h_len++] = p.tail;
  for (int i = 1; i < e_len; ++i) {
    p = two_product(e[i], b);
    const TwoTerm s = two_sum(q, p.tail);
    if (s.tail != 0.0) h[h_len++] = s.tail;
    const TwoTerm t = fast_two_sum(p.head, s.head);
    q = t.head;
    if (t.tail != 0.0) h[h_len++] = t.tail;
  }
  if (q != 0.0) h[h_len++] = q;
  return h_len;
}

// In-place COMPRESS (Shewchuk): same value, fewer components, largest component within
// one ulp of the value.
inline int compress(double* e, int e_len) noexcept {
  if (e_len <= 1) return e_len;
  int bottom = e_len - 1;
  double q = e[bottom];
  for (int i = e_len - 2; i >= 0; --i) {
    const TwoTerm s = fast_two_sum(q, e[i]);
    if (s.tail != 0.0) {
      e[bottom--] = s.head;
      q = s.tail;
    } else {
      q = s.head;
    }
  }
  int top = 0;
  for (int i = bottom + 1; i < e_len; ++i) {
    const TwoTerm s = fast_two_sum(e[i], q);
    if (s.tail != 0.0) e[top++] = s.tail;
    q = s.head;
  }
  if (q != 0.0) e[top++] = q;
  return top;
}

}  // namespace internal

template <int N>
class Expansion {
  static_assert(N >= 1);

 public:
  static constexpr int capacity = N;

  Expansion() noexcept = default;

  explicit Expansion(double x) noexcept requires(N >= 1) {
    if (x != 0.0) c_[size_++] = x;
  }

  /// The exact difference a - b.
  static Expansion difference(double a, double b) noexcept requires(N >= 2) {
    Expansion r;
    const TwoTerm d = two_diff(a, b);
    if (d.tail != 0.0) r.c_[r.size_++] = d.tail;
    if (d.head != 0.0) r.c_[r.size_++] = d.head;
    return r;
  }

  Expansion(const Expansion& other) noexcept : size_(other.size_) { copy_from(other.c_, size_); }
  Expansion& operator=(const Expansion& other) noexcept {
    size_ = other.size_;
    copy_from(other.c_, size_);
    return *this;
  }

  /// Widening copy.
  template <int M>
  requires(M < N) Expansion(const Expansion<M>& other)
  noexcept : size_(other.size()) {  // NOLINT
    copy_from(other.data(), size_);
  }

  int size() const noexcept { return size_; }
  const double* data() const noexcept { return c_; }
  bool is_zero() const noexcept { return size_ == 0; }
  Sign sign() const noexcept { return size_ == 0 ? Sign::zero : sign_of(c_[size_ - 1]); }

  /// The largest component: after compress() it is within one ulp of the value.
  double head() const noexcept { return size_ == 0 ? 0.0 : c_[size_ - 1]; }

  Expansion& compress() noexcept {
    size_ = internal::compress(c_, size_);
    return *this;
  }

  Expansion operator-() const noexcept {
    Expansion r;
    r.size_ = size_;
    for (int i = 0; i < size_; ++i)
      r.c_[i] = -c_[i];
    return r;
  }

  /// The same value with capacity K, or nullopt when it has more than K components.
  template <int K>
  std::optional<Expansion<K>> narrow() const noexcept {
    if (size_ > K) return std::nullopt;
    Expansion<K> r;
    r.assign(c_, size_);
    return r;
  }

  // Raw access for the arithmetic below.
  double* mutable_data() noexcept { return c_; }
  void set_size(int n) noexcept { size_ = n; }
  void assign(const double* src, int n) noexcept {
    size_ = n;
    copy_from(src, n);
  }

 private:
  void copy_from(const double* src, int n) noexcept {
    for (int i = 0; i < n; ++i)
      c_[i] = src[i];
  }

  // Storage beyond size_ is never read, so it is left uninitialized on purpose: these
  // objects are large and live on the hot exact path.
  double c_[N];
  int size_ = 0;
};

template <int N, int M>
Expansion<N + M> operator+(const Expansion<N>& a, const Expansion<M>& b) noexcept {
  Expansion<N + M> r;
  r.set_size(internal::sum(a.data(), a.size(), b.data(), b.size(), r.mutable_data()));
  return r;
}

template <int N, int M>
Expansion<N + M> operator-(const Expansion<N>& a, const Expansion<M>& b) noexcept {
  return a + (-b);
}

/// Equal values (the exact difference of equal values is the empty expansion).
template <int N, int M>
bool operator==(const Expansion<N>& a, const Expansion<M>& b) noexcept {
  return (a - b).is_zero();
}

/// Exact product of an expansion and a double.
template <int N>
Expansion<2 * N> scale(const Expansion<N>& a, double b) noexcept {
  Expansion<2 * N> r;
  r.set_size(internal::scale(a.data(), a.size(), b, r.mutable_data()));
  return r;
}

/// Exact product of two expansions: the sum of a scaled by each component of b.
template <int N, int M>
Expansion<2 * N * M> operator*(const Expansion<N>& a, const Expansion<M>& b) noexcept {
  if constexpr (M > N) {
    return b * a;
  } else {
    // Accumulate a * b_k into two buffers used alternately; the last one written is the
    // result.
    Expansion<2 * N * M> buffers[2];
    int current = 0;
    for (int k = 0; k < b.size(); ++k) {
      double partial[2 * N];
      const int len = internal::scale(a.data(), a.size(), b.data()[k], partial);
      const Expansion<2 * N* M>& acc = buffers[current];
      Expansion<2 * N* M>& next = buffers[1 - current];
      next.set_size(internal::sum(acc.data(), acc.size(), partial, len, next.mutable_data()));
      current = 1 - current;
    }
    return buffers[current];
  }
}

}  // namespace exactgeo::kernel
