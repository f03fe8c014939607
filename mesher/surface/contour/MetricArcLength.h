#pragma once
// Metric arc length along a curve (thesis sec. 4.3, alg. 4.1 steps 2–3): the function
//   s(t) = ∫_{t0}^{t} ρ(τ) dτ,   ρ(t) = |M(c_p(t)) c_p'(t)|  (M = M_s M_p, eq. 2.9)
// sampled adaptively, and its inverse, which places the nodes of a contour at equal metric
// arc length (the clean form of the thesis' iterative unit steps with the last segment's
// remainder redistributed).
//
// ρ is modelled as piecewise linear between samples. A piece is bisected until the
// trapezoid rule on it agrees with the trapezoid rule on its two halves within tolerance
// AND its metric length is at most `maxPieceLength` (so the metric field is sampled at
// least a few times per mesh segment: features smaller than the mesh size cannot be
// resolved by the mesh anyway). Deterministic: the samples depend only on ρ, t0, t1 and
// the options.
#include <functional>
#include <vector>

namespace aniso::contour {

struct ArcLengthOptions {
  int initialPieces = 8;        ///< uniform first subdivision of [t0, t1]
  int maxDepth = 18;            ///< bisections of an initial piece at most
  double relTol = 1e-3;         ///< trapezoid disagreement relative to the piece's length
  double absTol = 1e-3;         ///< metric units over the whole curve, shared by parameter length
  double maxPieceLength = 0.25; ///< metric length of an accepted piece at most
};

class MetricArcLength {
 public:
  /// Samples ρ on [t0, t1] (t0 < t1, both finite). Throws MeshingError when ρ is negative
  /// or not finite at a sample (the message gives t; callers add the entity's name).
  MetricArcLength(const std::function<double(double)>& density, double t0, double t1,
                  const ArcLengthOptions& options = {});

  /// s(t1): the metric length of the whole curve.
  double total() const { return s_.back(); }
  /// t with s(t) = s, s clamped to [0, total()]; t0 when total() is 0.
  double parameterAt(double s) const;
  /// n + 1 parameters t0 = τ_0 < τ_1 < ... < τ_n = t1 splitting the curve into n pieces of
  /// equal metric length (n ≥ 1); equal parameter length when total() is 0.
  std::vector<double> equalSpacing(int n) const;
  /// Number of samples of ρ taken (for tests and statistics).
  int samples() const { return static_cast<int>(t_.size()); }

 private:
  void refine(const std::function<double(double)>& density, double a, double ra, double b,
              double rb, int depth);
  double eval(const std::function<double(double)>& density, double t) const;

  ArcLengthOptions opt_;
  double t0_ = 0, t1_ = 1;
  std::vector<double> t_, rho_, s_;  ///< samples in increasing t, s_ the cumulative length
};

}  // namespace aniso::contour
