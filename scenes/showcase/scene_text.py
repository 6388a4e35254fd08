"""Scene text for the showcase generators (generate_*.py): SceneText collects pbrt-v4 lines and
writes trianglemesh shapes (boxes, surfaces of revolution, tubes along paths, discs); add,
sub, mul, cross and norm work on 3-tuples. Numbers are written with a given number of
significant digits (positions, normals and temperatures may differ).
"""
import math


def add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def mul(a, s):
    return (a[0] * s, a[1] * s, a[2] * s)


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def norm(a):
    length = math.sqrt(a[0] ** 2 + a[1] ** 2 + a[2] ** 2)
    return mul(a, 1 / length)


def fmt(values, digits=5):
    return " ".join("%.*g" % (digits, v) for v in values)


class SceneText:
    def __init__(self, normal_digits=5, temperature_digits=5):
        self.lines = []
        self.normal_digits = normal_digits
        self.temperature_digits = temperature_digits

    def emit(self, s=""):
        self.lines.append(s)

    def text(self):
        return "\n".join(self.lines) + "\n"

    def mesh(self, points, tris, normals=None, temperatures=None, extra=""):
        """A trianglemesh shape: points [(x, y, z)], tris [(i, j, k)], optional per-vertex
        normals and temperatures (kelvin), and extra parameter text."""
        self.emit('Shape "trianglemesh" "point3 P" [%s]' % fmt([c for p in points for c in p]))
        self.emit('    "integer indices" [%s]' % " ".join(str(i) for t in tris for i in t))
        if normals:
            self.emit('    "normal N" [%s]'
                      % fmt([c for n in normals for c in n], self.normal_digits))
        if temperatures:
            self.emit('    "float temperature" [%s]' % fmt(temperatures, self.temperature_digits))
        if extra:
            self.emit("    " + extra)

    def box(self, x0, x1, y0, y1, z0, z1):
        """Six quads of an axis-aligned box, outward facing."""
        p = [(x, y, z) for z in (z0, z1) for y in (y0, y1) for x in (x0, x1)]
        # vertex index: x + 2 y + 4 z
        quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2),
                 (1, 3, 7, 5)]
        tris = []
        for a, b, c, d in quads:
            tris += [(a, b, c), (a, c, d)]
        self.mesh(p, tris)

    def lathe(self, profile, segments=48, flip=False):
        """A surface of revolution about the local y axis: profile [(radius, y)], smooth
        normals facing away from the axis (towards it with flip)."""
        pts, nrm, tris = [], [], []
        m = len(profile)
        for j, (r, y) in enumerate(profile):
            r0, y0 = profile[max(j - 1, 0)]
            r1, y1 = profile[min(j + 1, m - 1)]
            # the profile's tangent (dr, dy) turned outwards
            nr, ny = (y1 - y0), -(r1 - r0)
            length = math.hypot(nr, ny) or 1
            nr, ny = nr / length, ny / length
            if flip:
                nr, ny = -nr, -ny
            for k in range(segments):
                a = 2 * math.pi * k / segments
                pts.append((r * math.cos(a), y, r * math.sin(a)))
                nrm.append((nr * math.cos(a), ny, nr * math.sin(a)))
        for j in range(m - 1):
            for k in range(segments):
                a, b = j * segments + k, j * segments + (k + 1) % segments
                c, d = a + segments, b + segments
                # no triangle with two corners on the axis (a profile point of radius 0)
                quad = [(a, b, c), (b, d, c)] if not flip else [(a, c, b), (b, c, d)]
                if profile[j][0] == 0:
                    quad = quad[1:]
                if profile[j + 1][0] == 0:
                    quad = quad[:1]
                tris += quad
        self.mesh(pts, tris, nrm)

    def tube(self, path, radii, sides=12, temperatures=None, ripple=None, normals=True,
             twist_free=True):
        """A tube along a polyline path, one radius (and temperature) per path point;
        ripple(i, k) scales the radius of ring i at side k. Its cross sections follow the path
        by parallel transport (twist_free), or each is placed independently. Without normals
        the tube is flat-shaded (for wires too thin to show facets)."""
        pts, nrm, tris, temps = [], [], [], []
        n = len(path)
        prev_u = None
        for i, p in enumerate(path):
            d = norm(sub(path[min(i + 1, n - 1)], path[max(i - 1, 0)]))
            if twist_free:
                helper = prev_u if prev_u else ((0, 0, 1) if abs(d[2]) < 0.9 else (1, 0, 0))
                u = norm(cross(cross(d, helper), d))
                prev_u = u
            else:
                helper = (0, 1, 0) if abs(d[1]) < 0.9 else (1, 0, 0)
                u = norm(cross(d, helper))
            v = cross(d, u)
            for k in range(sides):
                a = 2 * math.pi * k / sides
                nn = add(mul(u, math.cos(a)), mul(v, math.sin(a)))
                r = radii[i] * (ripple(i, k) if ripple else 1)
                pts.append(add(p, mul(nn, r)))
                nrm.append(nn)
                if temperatures:
                    temps.append(temperatures[i])
        for i in range(n - 1):
            for k in range(sides):
                a, b = i * sides + k, i * sides + (k + 1) % sides
                c, d = a + sides, b + sides
                tris += [(a, c, b), (b, c, d)]
        self.mesh(pts, tris, nrm if normals else None, temps or None)

    def disc(self, cx, y, cz, r, segments=32, temperature=None, wobble=None):
        """A horizontal disc facing up; wobble(k) scales the radius at rim point k."""
        pts = [(cx, y, cz)]
        for k in range(segments):
            a = 2 * math.pi * k / segments
            rr = r * (wobble(k) if wobble else 1)
            pts.append((cx + rr * math.cos(a), y, cz + rr * math.sin(a)))
        tris = [(0, 1 + (k + 1) % segments, 1 + k) for k in range(segments)]
        self.mesh(pts, tris, [(0, 1, 0)] * len(pts),
                  [temperature] * len(pts) if temperature else None)
