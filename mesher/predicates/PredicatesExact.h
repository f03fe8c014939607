#pragma once
// Exact evaluations behind the filters of Predicates.cpp (internal to mesher/predicates).
//
// Every function takes the points' coordinates packed contiguously (point i at p + i·dim)
// and returns a double with the exact sign of the predicate in the conventions of
// Predicates.h and an approximate magnitude.
//
//  • ...Expansion: floating-point expansion arithmetic (Expansion.h). Exact only when every
//    nonzero coordinate magnitude lies in [2^−T, 2^T] with T = kExpansionRange[degree]
//    (then no product error term underflows and nothing overflows); the caller checks.
//  • ...Big: integer arithmetic on the coordinates written as integers times a common power
//    of two (ExactInteger.h). Exact for all finite inputs; slow.
// The dispatch between the two (range check, rescaling by a power of two) is in
// Predicates.cpp.
namespace aniso::predicates::detail {

/// Predicate degree → T: nonzero magnitudes in [2^−T, 2^T] keep expansions (and the
/// floating-point filters) free of underflow and overflow. Derivation: for degree k, every
/// intermediate value is an integer multiple of 2^(−k(T+52)) ≥ 2^−1074 (so products round
/// with relative error ≤ 2^−53 or exactly, and two-product error terms are representable),
/// and bounded by 2^(k(T+1)+10) < 2^1023.
inline constexpr int kExpansionRange[6] = {0, 0, 480, 300, 210, 160};

double orient2dExpansion(const double* p);
double incircleExpansion(const double* p);
double orient3dExpansion(const double* p);
double insphereExpansion(const double* p);

double orient2dBig(const double* p);
double incircleBig(const double* p);
double orient3dBig(const double* p);
double insphereBig(const double* p);

}  // namespace aniso::predicates::detail
