#include "mesher/predicates/ExactInteger.h"

#include <cmath>

namespace aniso::predicates::detail {

BigInt::BigInt(std::int64_t v) {
  neg_ = v < 0;
  std::uint64_t m = neg_ ? (~static_cast<std::uint64_t>(v) + 1) : static_cast<std::uint64_t>(v);
  while (m != 0) {
    mag_.push_back(static_cast<std::uint32_t>(m & 0xffffffffu));
    m >>= 32;
  }
}

int lowExponent(double x) {
  int e = 0;
  const double f = std::frexp(std::fabs(x), &e);  // |x| = f · 2^e, f ∈ [0.5, 1)
  auto m = static_cast<std::uint64_t>(std::ldexp(f, 53));  // exact: 53-bit integer
  int low = e - 53;
  while ((m & 1u) == 0) {
    m >>= 1;
    ++low;
  }
  return low;
}

BigInt BigInt::fromDouble(double x, int e0) {
  BigInt r;
  if (x == 0.0) return r;
  int e = 0;
  const double f = std::frexp(std::fabs(x), &e);
  const auto m = static_cast<std::uint64_t>(std::ldexp(f, 53));  // |x| = m · 2^(e−53)
  const int shift = e - 53 - e0;  // may be negative only by trailing zero bits of m
  std::uint64_t mm = m;
  int s = shift;
  while (s < 0) {  // drop trailing zeros (guaranteed zero by the precondition)
    mm >>= 1;
    ++s;
  }
  const int limbShift = s / 32, bitShift = s % 32;
  r.mag_.assign(static_cast<std::size_t>(limbShift), 0u);
  // mm · 2^bitShift spans at most 53 + 31 bits: three limbs.
  const std::uint64_t lo = mm << bitShift;
  const std::uint64_t hi = bitShift == 0 ? 0 : (mm >> (64 - bitShift));
  r.mag_.push_back(static_cast<std::uint32_t>(lo & 0xffffffffu));
  r.mag_.push_back(static_cast<std::uint32_t>(lo >> 32));
  r.mag_.push_back(static_cast<std::uint32_t>(hi));
  r.neg_ = x < 0;
  r.trim();
  return r;
}

void BigInt::trim() {
  while (!mag_.empty() && mag_.back() == 0) mag_.pop_back();
  if (mag_.empty()) neg_ = false;
}

int BigInt::compareMag(const std::vector<std::uint32_t>& a, const std::vector<std::uint32_t>& b) {
  if (a.size() != b.size()) return a.size() < b.size() ? -1 : 1;
  for (std::size_t i = a.size(); i-- > 0;)
    if (a[i] != b[i]) return a[i] < b[i] ? -1 : 1;
  return 0;
}

std::vector<std::uint32_t> BigInt::addMag(const std::vector<std::uint32_t>& a,
                                          const std::vector<std::uint32_t>& b) {
  const std::vector<std::uint32_t>& lo = a.size() < b.size() ? a : b;
  const std::vector<std::uint32_t>& hi = a.size() < b.size() ? b : a;
  std::vector<std::uint32_t> r(hi.size() + 1, 0u);
  std::uint64_t carry = 0;
  for (std::size_t i = 0; i < hi.size(); ++i) {
    const std::uint64_t s = carry + hi[i] + (i < lo.size() ? lo[i] : 0u);
    r[i] = static_cast<std::uint32_t>(s);
    carry = s >> 32;
  }
  r[hi.size()] = static_cast<std::uint32_t>(carry);
  return r;
}

std::vector<std::uint32_t> BigInt::subMag(const std::vector<std::uint32_t>& a,
                                          const std::vector<std::uint32_t>& b) {
  std::vector<std::uint32_t> r(a.size(), 0u);
  std::int64_t borrow = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    std::int64_t d = static_cast<std::int64_t>(a[i]) - borrow - (i < b.size() ? b[i] : 0u);
    borrow = d < 0 ? 1 : 0;
    if (d < 0) d += (std::int64_t{1} << 32);
    r[i] = static_cast<std::uint32_t>(d);
  }
  return r;
}

BigInt BigInt::operator-() const {
  BigInt r = *this;
  if (!r.mag_.empty()) r.neg_ = !r.neg_;
  return r;
}

BigInt operator+(const BigInt& a, const BigInt& b) {
  BigInt r;
  if (a.neg_ == b.neg_) {
    r.mag_ = BigInt::addMag(a.mag_, b.mag_);
    r.neg_ = a.neg_;
  } else {
    const int c = BigInt::compareMag(a.mag_, b.mag_);
    if (c == 0) return r;
    if (c > 0) {
      r.mag_ = BigInt::subMag(a.mag_, b.mag_);
      r.neg_ = a.neg_;
    } else {
      r.mag_ = BigInt::subMag(b.mag_, a.mag_);
      r.neg_ = b.neg_;
    }
  }
  r.trim();
  return r;
}

BigInt operator-(const BigInt& a, const BigInt& b) { return a + (-b); }

BigInt operator*(const BigInt& a, const BigInt& b) {
  BigInt r;
  if (a.mag_.empty() || b.mag_.empty()) return r;
  r.mag_.assign(a.mag_.size() + b.mag_.size(), 0u);
  for (std::size_t i = 0; i < a.mag_.size(); ++i) {
    std::uint64_t carry = 0;
    for (std::size_t j = 0; j < b.mag_.size(); ++j) {
      const std::uint64_t t =
          static_cast<std::uint64_t>(a.mag_[i]) * b.mag_[j] + r.mag_[i + j] + carry;
      r.mag_[i + j] = static_cast<std::uint32_t>(t);
      carry = t >> 32;
    }
    std::size_t k = i + b.mag_.size();
    while (carry != 0) {
      const std::uint64_t t = static_cast<std::uint64_t>(r.mag_[k]) + carry;
      r.mag_[k++] = static_cast<std::uint32_t>(t);
      carry = t >> 32;
    }
  }
  r.neg_ = a.neg_ != b.neg_;
  r.trim();
  return r;
}

double BigInt::approx(int& exp2) const {
  exp2 = 0;
  if (mag_.empty()) return 0.0;
  // Top three limbs (at least 65 significant bits) scaled into (0.5, 1].
  double m = 0.0;
  const std::size_t n = mag_.size();
  for (std::size_t k = 0; k < 3 && k < n; ++k)
    m += std::ldexp(static_cast<double>(mag_[n - 1 - k]), -32 * static_cast<int>(k + 1));
  exp2 = 32 * static_cast<int>(n);
  return neg_ ? -m : m;
}

}  // namespace aniso::predicates::detail
