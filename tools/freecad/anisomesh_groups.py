# Names the groups of a mesh read back from anisomesh's UNV after the FreeCAD objects it was
# made from (README, "FreeCAD"):
#   <Obj>               the volume elements of object Obj (its face elements in a surface
#                       mesh or when Obj has no solid)
#   <Obj>_Solid<k>      the volume elements of Obj's k-th solid, only when Obj has several
#   <Obj>_Face<n>       the nodes on Face<n> of Obj, numbered as FreeCAD numbers Obj's shape
#   <Obj>_Face<n>_Faces the boundary (or shell) elements on that face
# Obj is the object's Name (unique in the document, a valid identifier), not its Label.
#
# The CLI numbers the faces of the model it prepared (FACE<n>): several objects touching or
# overlapping are fragmented, so a face of an object may come back in pieces, and the face
# between two touching objects is one mesh face lying on a face of each. So faces are mapped
# by geometry, not by export order: each FACE<n> gets a probe point (its interior mesh node
# farthest from its boundary nodes; without interior node, the centroid of its largest
# element) and lies on every object face within a small distance of that probe (the nearest
# one plus a margin of a tenth of the probe's distance to the face's boundary). Solids keep
# their order through the CLI (README, "Command line"): the k-th volume group is the k-th
# solid of the exported compound, objects in selection order.
import math
import re

# FreeCAD's UNV import splits a group holding nodes and elements into NAME_Nodes and
# NAME_Faces (NAME_Volumes, ...): face FACE<n> comes back as FACE<n>_Nodes and FACE<n>_Faces.
FACE_GROUP = re.compile(r"^FACE(\d+)_(Nodes|Faces)$")
# At most this many interior nodes are tried as probe, against at most this many boundary nodes.
PROBE_CANDIDATES = 32
PROBE_BOUNDARY_SAMPLE = 400


def _stride_sample(ids, n):
    """At most n of the sorted ids, evenly spread (deterministic)."""
    ids = sorted(ids)
    if len(ids) <= n:
        return ids
    step = len(ids) / n
    return [ids[int(i * step)] for i in range(n)]


def _face_groups(mesh):
    """{n: {"Nodes": gid, "Faces": gid}} for the FACE<n> groups."""
    out = {}
    for gid in mesh.Groups:
        m = FACE_GROUP.match(mesh.getGroupName(gid))
        if m:
            out.setdefault(int(m.group(1)), {})[m.group(2)] = gid
    return out


def _probe(mesh, nodes, shared, elements):
    """(point, margin) for one mesh face: the probe point and its distance to the face's
    boundary nodes (the scale below which other faces cannot come)."""
    def xyz(nid):
        v = mesh.getNodeById(nid)
        return (v.x, v.y, v.z)

    interior = [n for n in nodes if n not in shared]
    boundary = [xyz(n) for n in _stride_sample([n for n in nodes if n in shared], PROBE_BOUNDARY_SAMPLE)]
    if interior:
        best, best_d = None, -1.0
        for nid in _stride_sample(interior, PROBE_CANDIDATES):
            p = xyz(nid)
            d = min((math.dist(p, q) for q in boundary), default=math.inf)
            if d > best_d:
                best, best_d = p, d
        return best, best_d
    best, best_area, best_size = None, -1.0, 0.0
    for eid in sorted(elements):
        pts = [xyz(n) for n in mesh.getElementNodes(eid)[:3]]
        a = [pts[1][i] - pts[0][i] for i in range(3)]
        b = [pts[2][i] - pts[0][i] for i in range(3)]
        cross = (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
        area = 0.5 * math.sqrt(sum(c * c for c in cross))
        if area > best_area:
            per = math.dist(pts[0], pts[1]) + math.dist(pts[1], pts[2]) + math.dist(pts[2], pts[0])
            best, best_area, best_size = tuple(sum(p[i] for p in pts) / 3 for i in range(3)), area, 2 * area / per
    return best, best_size


def map_faces(mesh, objects_faces, tolerance):
    """{n: [(object index, local face index 1-based), ...]} for the mesh's FACE<n> groups;
    objects_faces[i] is the list of Part.Face of object i (FreeCAD's order). A face that lies
    on no object face maps to []. `tolerance` (model units) is the smallest distance margin."""
    import FreeCAD
    import Part

    groups = _face_groups(mesh)
    count = {}
    for g in groups.values():
        for nid in mesh.getGroupElements(g["Nodes"]) if "Nodes" in g else ():
            count[nid] = count.get(nid, 0) + 1
    shared = {nid for nid, c in count.items() if c > 1}
    out = {}
    for n in sorted(groups):
        g = groups[n]
        nodes = mesh.getGroupElements(g["Nodes"]) if "Nodes" in g else ()
        elements = mesh.getGroupElements(g["Faces"]) if "Faces" in g else ()
        point, margin = _probe(mesh, nodes, shared, elements)
        if point is None:
            out[n] = []
            continue
        p = FreeCAD.Vector(*point)
        vertex = Part.Vertex(p)
        slack = max(tolerance, 0.1 * margin) if math.isfinite(margin) else tolerance
        near = []
        for i, faces in enumerate(objects_faces):
            for k, face in enumerate(faces, start=1):
                box = FreeCAD.BoundBox(face.BoundBox)
                box.enlarge(slack)
                if box.isInside(p):
                    near.append((face.distToShape(vertex)[0], i, k))
        if not near:
            out[n] = []
            continue
        dmin = min(d for d, _, _ in near)
        # a probe farther from every face than its own margin allows is not on the shapes
        out[n] = [] if dmin > max(tolerance, 0.25 * margin) else [(i, k) for d, i, k in near if d <= dmin + slack]
    return out


def _volume_groups(mesh):
    return [gid for gid in mesh.Groups if mesh.getGroupElementType(gid) == "Volume"]


def _add(mesh, name, kind, ids):
    if ids:
        gid = mesh.addGroup(name, kind)
        mesh.addGroupElements(gid, sorted(ids))


def name_groups(mesh, names, objects_faces, solid_counts, tolerance):
    """Replaces the CLI's groups (FACE<n>_Nodes/_Faces, one volume group per solid) by groups
    named after the objects (scheme at the top of this file). names[i], objects_faces[i],
    solid_counts[i]: object i's Name, faces and number of solids, in export order.
    Returns the list of warnings (faces or solids that could not be named; their CLI groups
    are then kept)."""
    warnings = []
    groups = _face_groups(mesh)
    placed = map_faces(mesh, objects_faces, tolerance)
    face_nodes, face_elems, object_elems = {}, {}, {}
    for n in sorted(groups):
        g = groups[n]
        if not placed.get(n):
            warnings.append(f"mesh face FACE{n} lies on no face of {', '.join(names)}: kept as FACE{n}")
            continue
        nodes = mesh.getGroupElements(g["Nodes"]) if "Nodes" in g else ()
        elems = mesh.getGroupElements(g["Faces"]) if "Faces" in g else ()
        for i, k in placed[n]:
            face_nodes.setdefault((i, k), set()).update(nodes)
            face_elems.setdefault((i, k), set()).update(elems)
            object_elems.setdefault(i, set()).update(elems)
        for gid in g.values():
            mesh.removeGroup(gid)
    for i, faces in enumerate(objects_faces):
        for k in range(1, len(faces) + 1):
            if (i, k) not in face_nodes:
                warnings.append(f"{names[i]} Face{k} has no mesh face (no group {names[i]}_Face{k})")
    volumes = _volume_groups(mesh)
    has_volumes = bool(volumes)
    if volumes and len(volumes) != sum(solid_counts):
        warnings.append(f"the mesh has {len(volumes)} solids, the objects {sum(solid_counts)}: "
                        "solid groups keep the CLI's names")
        volumes = []
    solid_elems, next_solid = {}, 0
    for i, count in enumerate(solid_counts):
        for _ in range(count):
            solid_elems.setdefault(i, []).append(set(mesh.getGroupElements(volumes[next_solid])) if volumes else set())
            next_solid += 1
    for gid in volumes:
        mesh.removeGroup(gid)
    for i, name in enumerate(names):
        solids = solid_elems.get(i, [])
        if not has_volumes or not solids:  # a surface mesh, or an object without solid (a sheet)
            _add(mesh, name, "Face", object_elems.get(i, set()))
        elif volumes and solids:
            _add(mesh, name, "Volume", set().union(*solids))
            if len(solids) > 1:
                for k, elems in enumerate(solids, start=1):
                    _add(mesh, f"{name}_Solid{k}", "Volume", elems)
        for k in range(1, len(objects_faces[i]) + 1):
            _add(mesh, f"{name}_Face{k}", "Node", face_nodes.get((i, k), set()))
            _add(mesh, f"{name}_Face{k}_Faces", "Face", face_elems.get((i, k), set()))
    return warnings
