"""Fold census of a triangle surface mesh (MSH read with meshio): the edges shared by two
triangles of one model face (same gmsh:geometrical tag) whose normals are more than 84
degrees apart — the volume mesher's fold criterion (mesher/volume/UnfoldSurface.h,
kFoldCosine). Neighbours on a face meshed within the curvature ratio differ by a few
degrees; a fold is a triangle turned over or standing across its face. A triangle with
mean ratio below DEGENERATE (e.g. in a CAD strip 1e-6 wide at a fillet tip, where no
triangle can be better) has no meaningful normal and is left out; the referee's
tri_eta_min reports such triangles."""
import numpy as np, meshio

FOLD_COSINE = np.cos(np.radians(84))
DEGENERATE = 1e-3


def folded_edges(path):
    """Returns (number of folded edges, sorted list of the face tags that have one)."""
    m = meshio.read(path)
    tris, tags = [], []
    for i, c in enumerate(m.cells):
        if c.type == "triangle":
            tris.append(c.data)
            tags.append(np.asarray(m.cell_data["gmsh:geometrical"][i]))
    if not tris: return 0, []
    T, G, P = np.vstack(tris), np.concatenate(tags), m.points
    N = np.cross(P[T[:, 1]] - P[T[:, 0]], P[T[:, 2]] - P[T[:, 0]])
    area2 = np.linalg.norm(N, axis=1)
    squares = sum(np.einsum("ij,ij->i", d, d) for d in (P[T[:, 1]] - P[T[:, 0]], P[T[:, 2]] - P[T[:, 1]], P[T[:, 0]] - P[T[:, 2]]))
    eta = 2 * np.sqrt(3) * area2 / np.maximum(squares, 1e-300)
    N /= np.maximum(area2[:, None], 1e-300)
    # Undirected edges with their triangle; pairs of one face sharing an edge.
    e = np.sort(np.stack([T[:, [0, 1]], T[:, [1, 2]], T[:, [2, 0]]], axis=1).reshape(-1, 2), axis=1)
    owner = np.repeat(np.arange(len(T)), 3)
    order = np.lexsort((e[:, 1], e[:, 0]))
    e, owner = e[order], owner[order]
    same = np.all(e[1:] == e[:-1], axis=1)
    a, b = owner[:-1][same], owner[1:][same]
    fold = (G[a] == G[b]) & (np.einsum("ij,ij->i", N[a], N[b]) < FOLD_COSINE) & (eta[a] >= DEGENERATE) & (eta[b] >= DEGENERATE)
    return int(fold.sum()), sorted(set(int(g) for g in G[a][fold]))
