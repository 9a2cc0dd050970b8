# SPDX-License-Identifier: BSD-2-Clause
"""A vessel's lumen surface read from an STL file and checked for scripts/stl-to-mesh: one
connected, orientable, manifold surface of triangles whose boundary loops are the vessel's
openings, each planar within a tolerance. What is refused raises Refusal with one sentence."""
import math
import os
import struct


class Refusal(Exception):
    """Why the input cannot be meshed, as one sentence."""


def fmt(p):
    return "(" + ", ".join(f"{x:.6g}" for x in p) + ")"


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def norm(a):
    return math.sqrt(dot(a, a))


def directed(tri, flipped):
    """The edges of a triangle as it traverses them (turned over if flipped)."""
    a, b, c = tri
    return ((a, c), (c, b), (b, a)) if flipped else ((a, b), (b, c), (c, a))


def read_stl(path):
    """The triangles of an ASCII or binary STL file, as triples of (x, y, z)."""
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError as e:
        raise Refusal(f"{path}: cannot read it ({e.strerror})")
    if len(data) >= 84 and len(data) == 84 + 50 * struct.unpack_from("<I", data, 80)[0]:
        n = struct.unpack_from("<I", data, 80)[0]
        values = [struct.unpack_from("<9f", data, 84 + 50 * k + 12) for k in range(n)]
        tris = [(v[0:3], v[3:6], v[6:9]) for v in values]
    elif data.lstrip().startswith(b"solid"):
        words = data.decode("ascii", "replace").split()
        coords = []
        for k, w in enumerate(words):
            if w == "vertex":
                try:
                    coords.append(tuple(float(x) for x in words[k + 1:k + 4]))
                except ValueError:
                    raise Refusal(f"{path}: a vertex that is not three numbers ('{' '.join(words[k:k + 4])}')")
        if len(coords) % 3:
            raise Refusal(f"{path}: {len(coords)} vertices, not three per facet: the file is cut short or damaged")
        tris = [tuple(coords[k:k + 3]) for k in range(0, len(coords), 3)]
    else:
        raise Refusal(f"{path}: not an STL file (neither 'solid ...' text nor a binary file of 84 + 50 n bytes)")
    if not tris:
        raise Refusal(f"{path}: the file holds no triangle")
    for t in tris:
        if not all(math.isfinite(x) for p in t for x in p):
            raise Refusal(f"{path}: a triangle has a coordinate that is not a finite number {t}")
    return tris


class Surface:
    """The welded surface: points, triangles (index triples, oriented so that their normals
    point out of the lumen) and its boundary loops (index lists, each traversed as its
    triangles traverse it)."""

    def __init__(self, path, tris, scale):
        self.path = path
        index, self.points, self.tris = {}, [], []
        for t in tris:  # the STL repeats each corner's coordinates exactly: weld equal ones
            self.tris.append(tuple(index.setdefault(p, len(index)) for p in t))
        self.points = [None] * len(index)
        for p, i in index.items():
            self.points[i] = (p[0] * scale, p[1] * scale, p[2] * scale)
        self._check_topology()
        self._loops()
        if self._enclosed_volume() < 0:  # the triangles face inwards: turn them all
            self.tris = [(a, c, b) for a, b, c in self.tris]
            self.loops = [loop[::-1] for loop in self.loops]

    def _refuse(self, what, where):
        raise Refusal(f"{self.path}: {what} at {fmt(where)}")

    def _check_topology(self):
        edges = {}
        for t, (a, b, c) in enumerate(self.tris):
            if a == b or b == c or a == c:
                self._refuse("a triangle has two corners at one point (it has no area)", self.points[a])
            for u, v in ((a, b), (b, c), (c, a)):
                edges.setdefault((min(u, v), max(u, v)), []).append(t)
        for (u, v), ts in edges.items():
            if len(ts) > 2:
                self._refuse(f"{len(ts)} triangles meet at one edge (the surface is not a manifold)", self.midpoint(u, v))
        self.edges = edges
        # orient every triangle as its first neighbour, breadth first: two triangles sharing an
        # edge must traverse it in opposite directions
        flip, pieces = [None] * len(self.tris), 0
        for seed in range(len(self.tris)):
            if flip[seed] is not None:
                continue
            pieces += 1
            flip[seed], queue = False, [seed]
            while queue:
                t = queue.pop()
                for u, v in directed(self.tris[t], flip[t]):
                    for s in edges[(min(u, v), max(u, v))]:
                        if s == t:
                            continue
                        want = (u, v) in directed(self.tris[s], False)  # turn s over if it runs along (u, v) too
                        if flip[s] is None:
                            flip[s] = want
                            queue.append(s)
                        elif flip[s] != want:
                            self._refuse("the triangles cannot be oriented consistently (a one-sided surface, or two sheets glued edge to edge)", self.midpoint(u, v))
        if pieces > 1:
            raise Refusal(f"{self.path}: the surface is in {pieces} separate pieces; give the lumen alone, in one piece")
        self.tris = [(a, c, b) if f else (a, b, c) for (a, b, c), f in zip(self.tris, flip)]
        # around each point one fan of triangles (a disc, or a half disc on the boundary): two
        # cones touching at their tips are not a surface the wall can be laid on
        around = [[] for _ in self.points]
        for t, tri in enumerate(self.tris):
            for p in tri:
                around[p].append(t)
        for p, ts in enumerate(around):
            if not ts:
                continue
            seen, queue = {ts[0]}, [ts[0]]
            while queue:
                t = queue.pop()
                for q in self.tris[t]:
                    if q != p:
                        for s in edges[(min(p, q), max(p, q))]:
                            if s not in seen:
                                seen.add(s)
                                queue.append(s)
            if len(seen) != len(ts):
                self._refuse("two fans of triangles touch at one point (the surface is pinched there)", self.points[p])

    def midpoint(self, u, v):
        return tuple((a + b) / 2 for a, b in zip(self.points[u], self.points[v]))

    def _loops(self):
        nxt = {}
        for a, b, c in self.tris:
            for u, v in ((a, b), (b, c), (c, a)):
                if len(self.edges[(min(u, v), max(u, v))]) == 1:
                    nxt[u] = v
        self.loops, done = [], set()
        for start in nxt:
            if start in done:
                continue
            loop, p = [], start
            while p not in done:
                done.add(p)
                loop.append(p)
                p = nxt[p]
            self.loops.append(loop)
        if not self.loops:
            raise Refusal(f"{self.path}: the surface is closed, so it has no openings; cut the vessel's ends off with planes (each opening a boundary loop of the surface)")

    def _enclosed_volume(self):
        """The volume the surface encloses with each loop closed by a fan from its centre
        (positive when the triangles face out of it)."""
        P, six = self.points, 0.0
        for a, b, c in self.tris:
            six += dot(P[a], cross(P[b], P[c]))
        for loop in self.loops:
            o = tuple(sum(P[p][k] for p in loop) / len(loop) for k in range(3))
            for u, v in zip(loop, loop[1:] + loop[:1]):
                six += dot(o, cross(P[v], P[u]))
        return six / 6


def closest_on_triangle(p, a, b, c):
    """The point of triangle a b c nearest to p (Ericson, Real-Time Collision Detection, 5.1.5)."""
    ab, ac, ap = sub(b, a), sub(c, a), sub(p, a)
    d1, d2 = dot(ab, ap), dot(ac, ap)
    if d1 <= 0 and d2 <= 0:
        return a
    bp = sub(p, b)
    d3, d4 = dot(ab, bp), dot(ac, bp)
    if d3 >= 0 and d4 <= d3:
        return b
    vc = d1 * d4 - d3 * d2
    if vc <= 0 and d1 >= 0 and d3 <= 0:
        return along(a, ab, d1 / (d1 - d3))
    cp = sub(p, c)
    d5, d6 = dot(ab, cp), dot(ac, cp)
    if d6 >= 0 and d5 <= d6:
        return c
    vb = d5 * d2 - d1 * d6
    if vb <= 0 and d2 >= 0 and d6 <= 0:
        return along(a, ac, d2 / (d2 - d6))
    va = d3 * d6 - d5 * d4
    if va <= 0 and d4 - d3 >= 0 and d5 - d6 >= 0:
        return along(b, sub(c, b), (d4 - d3) / ((d4 - d3) + (d5 - d6)))
    denom = 1 / (va + vb + vc)
    v, w = vb * denom, vc * denom
    return tuple(a[k] + ab[k] * v + ac[k] * w for k in range(3))


def closest_on_segment(p, a, b):
    ab = sub(b, a)
    t = dot(sub(p, a), ab) / dot(ab, ab)
    return along(a, ab, min(1.0, max(0.0, t)))


def along(a, d, t):
    return (a[0] + t * d[0], a[1] + t * d[1], a[2] + t * d[2])


class Nearest:
    """The point of the surface's triangles nearest to a point within a given distance, through
    a grid of cubes of side `cell` holding the triangles whose boxes meet them."""

    def __init__(self, surface, cell):
        self.P, self.tris, self.cell, self.grid = surface.points, surface.tris, cell, {}
        for t, tri in enumerate(self.tris):
            lo, hi = self._box([self.P[p] for p in tri], 0.0)
            for key in self._keys(lo, hi):
                self.grid.setdefault(key, []).append(t)

    def _box(self, pts, pad):
        return ([min(q[k] for q in pts) - pad for k in range(3)], [max(q[k] for q in pts) + pad for k in range(3)])

    def _keys(self, lo, hi):
        r = [range(math.floor(lo[k] / self.cell), math.floor(hi[k] / self.cell) + 1) for k in range(3)]
        return ((i, j, k) for i in r[0] for j in r[1] for k in r[2])

    def __call__(self, p, radius):
        best, found = radius * radius, None
        seen = set()
        for key in self._keys(*self._box([p], radius)):
            for t in self.grid.get(key, ()):
                if t in seen:
                    continue
                seen.add(t)
                q = closest_on_triangle(p, *(self.P[v] for v in self.tris[t]))
                d = sub(q, p)
                if dot(d, d) <= best:
                    best, found = dot(d, d), q
        return found


class Opening:
    """A boundary loop closed by a plane: its rim (point indices, as the surface's triangles
    traverse it), centre, outward unit normal (out of the lumen), area and radius (of the disc
    of that area)."""

    def __init__(self, surface, loop):
        P = surface.points
        self.rim = loop
        ring = [P[p] for p in loop]
        area = (0.0, 0.0, 0.0)
        for p, q in zip(ring, ring[1:] + ring[:1]):  # Newell: the cap runs against the loop
            area = tuple(x + y / 2 for x, y in zip(area, cross(q, p)))
        self.area = norm(area)
        self.normal = tuple(x / self.area for x in area)
        self.radius = math.sqrt(self.area / math.pi)
        total, centre = 0.0, (0.0, 0.0, 0.0)
        for p, q in zip(ring[1:], ring[2:]):  # the area centroid of the fan from the first point
            w = dot(cross(sub(q, ring[0]), sub(p, ring[0])), self.normal) / 2
            total += w
            centre = tuple(c + w * (x + y + z) / 3 for c, x, y, z in zip(centre, ring[0], p, q))
        self.centre = tuple(c / total for c in centre)
        self.offplane = max(abs(dot(sub(q, self.centre), self.normal)) for q in ring)

    def flatten(self, surface):
        """Move the rim onto the plane (by at most offplane): the cap and the wall's ring
        are then planar."""
        for p in self.rim:
            q = surface.points[p]
            d = dot(sub(q, self.centre), self.normal)
            surface.points[p] = tuple(x - d * n for x, n in zip(q, self.normal))


def openings(surface, planarity):
    """The openings, each planar within planarity x its radius (then made planar)."""
    found = [Opening(surface, loop) for loop in surface.loops]
    for o in found:
        if o.offplane > planarity * o.radius:
            raise Refusal(f"{surface.path}: the opening at {fmt(o.centre)} (radius {o.radius:.4g}) is not planar: its rim leaves its plane by "
                          f"{o.offplane:.3g}, {100 * o.offplane / o.radius:.3g} % of its radius (at most {100 * planarity:.3g} %, --planarity); cut the vessel there with a plane")
        o.flatten(surface)
    return found


def stl_surface(path, scale):
    if not os.path.isfile(path):
        raise Refusal(f"{path}: no such file" if not os.path.exists(path) else f"{path}: not a file")
    return Surface(path, read_stl(path), scale)
