#pragma once
// Exact crossing tests between a segment and a triangle or another segment, the geometry
// of the recovery pipes (thesis sec. 5.4.1: "all geometrical calculations for building the
// pipe are based on the orient3d and orient2d tests"). Every decision is a sign of
// predicates::orient3d or, for coplanar points, of predicates::orient2d on the two
// coordinates that keep the plane non-degenerate (dropping one coordinate keeps the exact
// sign up to one common factor per query). Endpoints are compared by their coordinates:
// two distinct mesh vertices never coincide.
//
// Results: None (no crossing of the relative interiors), Interior (the relative interiors
// cross), Degenerate (a configuration no valid pair of mesh entities can have: a vertex in
// the interior of the other entity, collinear overlap) — the caller reports it.
namespace aniso::volume {

enum class Cross { None, Interior, Degenerate };

/// Segment pq against triangle abc, transversally: p and q strictly on opposite sides of
/// the plane and the crossing point in the open triangle. Coplanar p, q: None. An endpoint
/// on the plane strictly inside the triangle (and not one of its vertices): Degenerate.
Cross segmentPiercesTriangle(const double* p, const double* q, const double* a, const double* b, const double* c);

/// Segment pq against triangle abc when all five points are coplanar: Interior when pq
/// enters the open triangle (crossing an edge properly, or leaving a shared vertex into the
/// angle there); Degenerate when an endpoint lies strictly inside; else None.
Cross segmentCrossesTriangleInPlane(const double* p, const double* q, const double* a, const double* b,
                                    const double* c);

/// Either of the two: the relative interiors of segment pq and triangle abc meet.
Cross segmentCrossesTriangle(const double* p, const double* q, const double* a, const double* b, const double* c);

/// Segments ab and xy (no shared endpoint counts as crossing): Interior when they are
/// coplanar and cross at one point interior to both; Degenerate for a collinear overlap
/// or an endpoint of one strictly inside the other.
Cross segmentsCross(const double* a, const double* b, const double* x, const double* y);

}  // namespace aniso::volume
