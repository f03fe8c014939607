#pragma once
// Exact geometric predicates with a floating-point filter (STYLE.md §4): every Delaunay,
// cavity and recovery decision of the meshers goes through these. Each returns a value
// whose SIGN is exact for the given double coordinates (the magnitude is only an
// approximation): a fast floating-point evaluation with a forward error bound first, and
// an exact evaluation with expansion arithmetic when the bound cannot certify the sign.
// Inputs must be finite. Every finite input is handled exactly: coordinates far from 1 in
// magnitude are rescaled by a power of two (signs are invariant), and coordinates that
// span too many binades for floating-point expansions fall back to big-integer arithmetic
// (Predicates.cpp explains the ranges). The returned magnitude may then be that of the
// rescaled input, or clamped to stay a nonzero double.
//
// Conventions (all determinants of differences, so translation-invariant):
//   orient2d(a,b,c)     > 0  iff a, b, c are in counter-clockwise order
//                           = det[b−a, c−a]
//   incircle(a,b,c,d)   > 0  iff d lies strictly inside the circle through a, b, c, when
//                           a, b, c are counter-clockwise (the sign flips if they are not)
//   orient3d(a,b,c,d)   > 0  iff the tetrahedron abcd is positively oriented (right-handed)
//                           = det[b−a, c−a, d−a] = (b−a)·((c−a)×(d−a))
//   insphere(a,b,c,d,e) > 0  iff e lies strictly inside the sphere through a, b, c, d, when
//                           orient3d(a,b,c,d) > 0 (the sign flips if it is negative)
// Thread-safe, no global state.
namespace aniso::predicates {

double orient2d(const double* a, const double* b, const double* c);
double incircle(const double* a, const double* b, const double* c, const double* d);
double orient3d(const double* a, const double* b, const double* c, const double* d);
double insphere(const double* a, const double* b, const double* c, const double* d, const double* e);

}  // namespace aniso::predicates
