#pragma once
// BigInt — a small signed arbitrary-precision integer (internal to mesher/predicates, also
// used by the tests as an independent exact reference).
//
// Purpose: the last-resort exact evaluation of the predicates when the input coordinates
// span a magnitude range so wide that floating-point expansions could underflow or overflow
// (see Predicates.cpp). Every finite double is an integer multiple of 2^e for some e, so a
// set of doubles can be written exactly as integers times one common power of two:
// fromDouble(x, e0) = x · 2^(−e0), which is an integer when e0 ≤ lowExponent(x).
//
// Schoolbook arithmetic on 32-bit limbs; values have at most a few thousand bits here, so
// nothing smarter is needed. Not tuned for speed.
#include <cstdint>
#include <vector>

namespace aniso::predicates::detail {

class BigInt {
 public:
  BigInt() = default;
  explicit BigInt(std::int64_t v);
  /// x · 2^(−e0) exactly. Requires x finite and x == 0 or e0 ≤ lowExponent(x).
  static BigInt fromDouble(double x, int e0);

  friend BigInt operator+(const BigInt& a, const BigInt& b);
  friend BigInt operator-(const BigInt& a, const BigInt& b);
  friend BigInt operator*(const BigInt& a, const BigInt& b);
  BigInt operator-() const;
  friend bool operator==(const BigInt& a, const BigInt& b) = default;

  /// −1, 0 or +1.
  int sign() const { return mag_.empty() ? 0 : (neg_ ? -1 : 1); }
  /// An approximation m · 2^exp2 of the value with m a double in (−1, 1) (0 for zero).
  double approx(int& exp2) const;

 private:
  static int compareMag(const std::vector<std::uint32_t>& a, const std::vector<std::uint32_t>& b);
  static std::vector<std::uint32_t> addMag(const std::vector<std::uint32_t>& a,
                                           const std::vector<std::uint32_t>& b);
  /// a − b for |a| ≥ |b|.
  static std::vector<std::uint32_t> subMag(const std::vector<std::uint32_t>& a,
                                           const std::vector<std::uint32_t>& b);
  void trim();

  bool neg_ = false;
  std::vector<std::uint32_t> mag_;  ///< little-endian limbs, no leading zero limb
};

/// The exponent of the least significant set bit of x: x = m · 2^e with m an odd integer.
/// Requires x finite and nonzero.
int lowExponent(double x);

}  // namespace aniso::predicates::detail
