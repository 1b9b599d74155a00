#!/usr/bin/python3
"""Writes enet_grilli_slide.stl: the Enet & Grilli (2007) Gaussian slide as a closed, convex triangle mesh.

Its surface, from ../shared/validation/README.md (NHWAVE manual section 5.4; NTHMP landslide benchmark 2):
    zeta(x, y) = T / (1 - eps) [sech(kb x) sech(kw y) - eps]  where positive,
    kb = 2 C / b, kw = 2 C / w, C = acosh(1 / eps), b = 0.395 m, w = 0.680 m, T = 0.082 m, eps = 0.717.
Frame: x along the slide's length (down the slope once placed), y across, z out of its flat base; the origin at the
centre of the base, so that the scene places the slide by where that point goes and turns it by the slope's angle.
The dome is concave (sech is concave for |u| < asinh(1) = 0.881 > C = 0.862, and the product stays so over the
footprint), so the solid is convex and is its points' convex hull: points of the dome on a grid of spacing H inside
the footprint, and N points of the footprint's edge (zeta = 0) at z = 0, hulled by Qhull (scipy). Prints the volume
(the formula integrates to 7.726e-3 m^3; the slide measured 7.72e-3) and the largest gap between the hull's facets and
zeta at their centroids.

Run: /usr/bin/python3 cases/meshes/make_enet_grilli_slide.py   (needs python3-numpy and python3-scipy)
"""
import math
import os
import struct

import numpy as np
from scipy.spatial import ConvexHull

b, w, T, eps = 0.395, 0.680, 0.082, 0.717
C = math.acosh(1.0 / eps)
kb, kw = 2.0 * C / b, 2.0 * C / w
H = 0.01   # m, the dome's grid
N = 128    # points on the footprint's edge


def zeta(x, y):
    return T / (1.0 - eps) * (1.0 / (np.cosh(kb * x) * np.cosh(kw * y)) - eps)


def edge_point(phi):
    """Where the ray from the centre at angle phi leaves the footprint (zeta = 0), by bisection."""
    lo, hi = 0.0, 1.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if zeta(mid * math.cos(phi), mid * math.sin(phi)) > 0.0:
            lo = mid
        else:
            hi = mid
    r = 0.5 * (lo + hi)
    return r * math.cos(phi), r * math.sin(phi)


points = [(*edge_point(2.0 * math.pi * k / N), 0.0) for k in range(N)]
n = int(math.ceil(0.5 * b / H)) + 1
m = int(math.ceil(0.5 * w / H)) + 1
for i in range(-n, n + 1):
    for j in range(-m, m + 1):
        x, y = i * H, j * H
        z = zeta(x, y)
        if z > 1e-3 * T:   # the edge itself is the ring above
            points.append((x, y, z))
p = np.array(points)
hull = ConvexHull(p)
centre = p.mean(axis=0)
triangles = []
for s in hull.simplices:
    a, bb, c = p[s[0]], p[s[1]], p[s[2]]
    normal = np.cross(bb - a, c - a)
    if np.dot(normal, a - centre) < 0.0:   # Qhull does not orient its facets: outward from the centre
        s = [s[0], s[2], s[1]]
    triangles.append(s)
volume = sum(np.dot(p[t[0]], np.cross(p[t[1]], p[t[2]])) for t in triangles) / 6.0
gap = 0.0
for t in triangles:
    c = p[t].mean(axis=0)
    if c[2] > 1e-9:
        gap = max(gap, abs(zeta(c[0], c[1]) - c[2]))
out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "enet_grilli_slide.stl")
with open(out, "wb") as f:
    f.write(b"Enet & Grilli (2007) Gaussian slide, cases/meshes/make_enet_grilli_slide.py".ljust(80, b" "))
    f.write(struct.pack("<I", len(triangles)))
    for t in triangles:
        a, bb, c = p[t[0]], p[t[1]], p[t[2]]
        nrm = np.cross(bb - a, c - a)
        nrm /= np.linalg.norm(nrm)
        f.write(struct.pack("<12fH", *nrm, *a, *bb, *c, 0))
print(f"{out}: {len(p)} points, {len(triangles)} triangles, volume {volume:.6e} m^3, "
      f"largest gap to zeta {gap:.2e} m, length {p[:,0].max()-p[:,0].min():.4f} m, width {p[:,1].max()-p[:,1].min():.4f} m")
