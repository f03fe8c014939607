#pragma once
// Step 4 of INTERIOR-CAVITY recovery (CavityRecovery.h): the apex of a star that fills one
// side of a cavity. The side is given by its boundary faces, each oriented towards the
// inside; a star is valid when every tet (face, apex) is positively oriented (exact
// orient3d). Candidates: the side's own vertices (no new point), then new points near
// the patch — offsets along its normal, the mean of the side's vertices, the centroids of
// the cavity's tets, and points of the side's kernel found by cyclic relaxation.
#include <array>
#include <cstdint>
#include <set>
#include <vector>

#include "mesher/core/Types.h"
#include "mesher/delaunay3d/TetMesh.h"

namespace aniso::volume {

using CavityFace = std::array<del3d::VertexId, 3>;

/// Where new points near a patch go: its unit outward normal (area-weighted), its
/// area-weighted centroid and its mean edge length.
struct PatchFrame {
  Vec3 normal{0, 0, 0}, centroid{0, 0, 0};
  double h = 0;
};

/// The frame of the boundary triangles `patch` (indices into `tris`); false for a patch of
/// no area.
bool patchFrame(const del3d::TetMesh& m, const std::vector<CavityFace>& tris, const std::vector<int>& patch,
                PatchFrame& out);

/// A point at `margin` or more on the inner side of every face (the kernel), by cyclic
/// relaxation (Agmon–Motzkin) from `start`. False when it does not settle; `out` is then
/// the last point reached (a best effort, used to grow the side towards a star).
bool relaxIntoKernel(const del3d::TetMesh& m, const std::vector<CavityFace>& faces, Vec3 start, double margin,
                     Vec3& out);

/// The same for several relaxations over one set of faces: their unit inward normals and
/// offsets, computed once (build: false when a face has no area).
struct KernelFaces {
  std::vector<double> nx, ny, nz, offset;
  bool build(const del3d::TetMesh& m, const std::vector<CavityFace>& faces);
  bool relax(Vec3 start, double margin, Vec3& out) const;
};

struct Apex {
  bool found = false;
  bool isNew = false;
  del3d::VertexId vertex;
  Vec3 p{0, 0, 0};
};

/// Candidate new points for one side (direction +1 outer, -1 inner of the patch).
std::vector<Vec3> apexCandidates(const del3d::TetMesh& m, const std::vector<CavityFace>& side,
                                 const std::vector<del3d::TetId>& cavity, const PatchFrame& frame, double direction);

/// The apex of the best star over `faces`: an existing vertex of them (not in
/// `forbidden`) when its star is good enough, else the best new point among `candidates`,
/// else the best vertex; `found` is false when nothing gives a valid star.
Apex chooseApex(const del3d::TetMesh& m, const std::vector<CavityFace>& faces, const std::vector<Vec3>& candidates,
                const std::set<std::uint32_t>& forbidden);

}  // namespace aniso::volume
