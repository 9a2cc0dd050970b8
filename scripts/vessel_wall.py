# SPDX-License-Identifier: BSD-2-Clause
"""The wall of scripts/stl-to-mesh: layers of prisms laid outward on the lumen's surface mesh
along its vertex normals, each prism cut into three tetrahedra, and the second-order nodes of
the lumen and the wall."""
import math

from vessel_surface import Refusal, cross, dot, fmt, norm, sub


def vertex_normals(points, tris, rims):
    """Unit normals at the surface's points, the triangles' outward normals weighted by their
    angles there (Thuermer and Wuethrich); on an opening's rim turned into its plane, so that the
    wall's ring at the opening is planar. rims: {point: the opening's unit normal}."""
    acc = {}
    for tri in tris:
        n = cross(sub(points[tri[1]], points[tri[0]]), sub(points[tri[2]], points[tri[0]]))
        n = tuple(x / norm(n) for x in n)
        for k in range(3):
            p, q, r = (points[tri[(k + j) % 3]] for j in range(3))
            u, v = sub(q, p), sub(r, p)
            w = math.acos(max(-1.0, min(1.0, dot(u, v) / (norm(u) * norm(v)))))
            a = acc.setdefault(tri[k], [0.0, 0.0, 0.0])
            for c in range(3):
                a[c] += w * n[c]
    normals = {}
    for p, a in acc.items():
        if p in rims:
            d = dot(a, rims[p])
            a = [x - d * y for x, y in zip(a, rims[p])]
        normals[p] = tuple(x / norm(a) for x in a)
    return normals


def signed_volume(P, t):
    return dot(sub(P[t[1]], P[t[0]]), cross(sub(P[t[2]], P[t[0]]), sub(P[t[3]], P[t[0]]))) / 6


class Wall:
    """Layers of thickness thickness / layers on the surface triangles `tris` (oriented out of
    the lumen), appended to `points`: node(p, k) is surface point p moved k layers out.
    tets, outer (the last layer's triangles) and rings[o] (the sides over opening o's rim
    edges) index `points`.

    Each prism (a triangle between layers k and k + 1) is cut into three tetrahedra by the
    diagonals of its three sides; a side shared by two prisms is cut alike for both. A side's
    diagonal runs from one of its bottom corners (`diagonal`) to the other's top: first the
    corner of smaller index (Dompierre et al.'s rule, which never leaves a prism uncuttable),
    then, where a cell came out flat or inverted (sides bent by the surface's curvature), the
    sides of that prism are turned one at a time while that makes it and its neighbour better."""

    def __init__(self, points, tris, rim_edges, openings, thickness, layers):
        rims = {p: o.normal for o, edges in zip(openings, rim_edges) for e in edges for p in e}
        self.normals = vertex_normals(points, tris, rims)
        self.base = sorted(self.normals)
        self.slot = {p: s for s, p in enumerate(self.base)}
        self.start, self.step = len(points), thickness / layers
        for k in range(1, layers + 1):
            for p in self.base:
                points.append(tuple(x + k * self.step * n for x, n in zip(points[p], self.normals[p])))
        self.P, self.tris = points, tris
        self.diagonal, sides = {}, {}
        for t, tri in enumerate(tris):
            for a, b in ((tri[0], tri[1]), (tri[1], tri[2]), (tri[2], tri[0])):
                sides.setdefault(frozenset((a, b)), []).append(t)
                for k in range(layers):
                    self.diagonal[frozenset((a, b)), k] = min(a, b)
        for k in range(layers):
            self._repair(sides, k)
        self.tets = []
        for t, tri in enumerate(tris):
            for k in range(layers):
                if self.quality(t, k) < 0.05:
                    raise Refusal(f"the wall folds at {fmt(points[tri[0]])}: offset by {thickness:g} along the normals, the lumen's surface there is curved more tightly "
                                  f"than the wall is thick (a cell at {self.quality(t, k):.2g} of its prism's share of the volume); give a thinner --wall, or smooth the surface")
                self.tets += self.prism_tets(t, k)
        self.outer = [tuple(self.node(p, layers) for p in tri) for tri in tris]
        self.rings = [[tri for a, b in edges for k in range(layers) for tri in self.side_tris(a, b, k)] for edges in rim_edges]

    def node(self, p, k):
        return p if k == 0 else self.start + (k - 1) * len(self.base) + self.slot[p]

    def prism_tets(self, t, k):
        """The three tetrahedra of prism (t, k) as its sides' diagonals cut it (positively
        oriented for an unfolded prism), or [] if they go round it (no cut exists)."""
        tri = self.tris[t]
        for h in range(3):  # the hub: the corner both of whose sides' diagonals start at it
            v = [tri[(h + i) % 3] for i in range(3)]
            if self.diagonal[frozenset(v[:2]), k] == v[0] and self.diagonal[frozenset((v[0], v[2])), k] == v[0]:
                b, u = [self.node(p, k) for p in v], [self.node(p, k + 1) for p in v]
                if self.diagonal[frozenset(v[1:]), k] == v[1]:
                    return [(b[0], b[1], b[2], u[2]), (b[0], b[1], u[2], u[1]), (b[0], u[1], u[2], u[0])]
                return [(b[0], b[1], b[2], u[1]), (b[0], u[1], b[2], u[2]), (b[0], u[1], u[2], u[0])]
        return []

    def quality(self, t, k):
        """The smallest of prism (t, k)'s cells over a third of the prism's volume (-1 if it
        cannot be cut)."""
        tets = self.prism_tets(t, k)
        if not tets:
            return -1.0
        tri = self.tris[t]
        n = cross(sub(self.P[tri[1]], self.P[tri[0]]), sub(self.P[tri[2]], self.P[tri[0]]))
        return min(signed_volume(self.P, c) for c in tets) / (norm(n) / 2 * self.step / 3)

    def _repair(self, sides, k):
        for _ in range(3):
            changed = False
            for t, tri in enumerate(self.tris):
                if self.quality(t, k) >= 0.2:
                    continue
                for a, b in ((tri[0], tri[1]), (tri[1], tri[2]), (tri[2], tri[0])):
                    side, prisms = (frozenset((a, b)), k), sides[frozenset((a, b))]
                    before = min(self.quality(s, k) for s in prisms)
                    self.diagonal[side] = a + b - self.diagonal[side]
                    if min(self.quality(s, k) for s in prisms) > before:
                        changed = True
                    else:
                        self.diagonal[side] = a + b - self.diagonal[side]
            if not changed:
                return

    def side_tris(self, a, b, k):
        """The side over surface edge (a, b) between layers k and k + 1, cut by its diagonal."""
        d = self.diagonal[frozenset((a, b)), k]
        e = a + b - d
        return [(self.node(d, k), self.node(e, k), self.node(e, k + 1)), (self.node(d, k), self.node(e, k + 1), self.node(d, k + 1))]

    def layer_of(self, i):
        """(surface point, layer) of node i."""
        if i < self.start:
            return i, 0
        k, s = divmod(i - self.start, len(self.base))
        return self.base[s], k + 1

    def edge_node(self, points, i, j, curved):
        """The second-order node of the wall's edge (i, j), from curved(p, q): that of the
        surface edge (p, q). An edge within layer k is its surface edge's, moved k layers out
        along the mean of its ends' normals (a circle's edges stay on concentric circles); an
        edge across a layer's side is the middle of the ruled side between the curved edges
        below and above it; an edge along a normal is straight."""
        (p, k), (q, l) = self.layer_of(i), self.layer_of(j)
        if p == q:
            return tuple((x + y) / 2 for x, y in zip(points[i], points[j]))
        n = [x + y for x, y in zip(self.normals[p], self.normals[q])]
        n = [x / norm(n) for x in n]
        m = curved(p, q)
        at = lambda layer: tuple(x + layer * self.step * y for x, y in zip(m, n))
        if k == l:
            return at(k)
        return tuple((x + y) / 2 for x, y in zip(at(k), at(l)))
