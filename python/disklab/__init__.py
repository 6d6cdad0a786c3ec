"""disklab from numpy: the sample sequences, disk strategies and spherical-ellipse maps of the
C++ library, its solid angles and elliptic integrals, on float64 arrays.

    import numpy as np, disklab
    u = disklab.sequence("sobol-owen", seed=7).points(1024)          # (1024, 2) in [0, 1)^2
    xy = disklab.disk_strategy("concentric").sample(u)               # (1024, 2) on the unit disk
    light = disklab.Disk(center=(0, 0, 2), normal=(0, 0, -1), radius=1)
    m = disklab.ellipse_map("radial", light, o=(0.3, 0, 0))
    s = m.sample(u)                                                  # .direction .point .pdf .valid

Names are the C++ library's and the CLI's (`disklab points --sequence/--strategy/--map`), and the
values are the same bit for bit. Arrays come back as new float64 arrays; float64 C-ordered input
is read without a copy, and the loops run without the GIL. Bad input (a wrong shape or dtype, an
unknown name, non-finite or degenerate geometry) raises ValueError naming the argument; u outside
the closed unit square or NaN gives rows with valid == False, zero direction, point and pdf.
See docs/python.md.
"""

from collections import namedtuple
import numbers

import numpy as np

from . import _disklab as _core

__all__ = [
    "Disk", "DiskStrategy", "DiskWalk", "EllipseMap", "MapSamples", "Sequence", "carlson_rd",
    "carlson_rf", "carlson_rj", "disk_strategy", "ellint_f", "ellint_pi", "ellipse_map",
    "l2_star", "map_names", "sequence", "sequence_names", "solid_angle", "strategy_names",
]

# The columns of EllipseMap.sample(): direction (n, 3) unit vectors from o, point (n, 3) where
# they meet the disk, pdf (n,) in the solid-angle measure, valid (n,) bool.
MapSamples = namedtuple("MapSamples", "direction point pdf valid")
# DiskStrategy.walk(): the square point index and value each disk sample used, the disk point
# and its estimator weight, one row per sample.
DiskWalk = namedtuple("DiskWalk", "index uv point weight")


def sequence_names():
    """The sequence names, in Christensen's memo order."""
    return list(_core.sequence_names())


def strategy_names():
    """The disk strategy names: pad-zero rejection polar concentric polar4 concentric4."""
    return list(_core.strategy_names())


def map_names():
    """The spherical-ellipse map names (ellipse/any_map.h)."""
    return list(_core.map_names())


def _real_array(a, what):
    arr = np.asarray(a)
    if arr.dtype.kind not in "fiu":
        raise ValueError(f"{what}: expected real numbers, got dtype {arr.dtype}")
    return arr


def _rows(a, cols, what):
    """a as a C-ordered float64 (n, cols) array (no copy when it is one already)."""
    arr = _real_array(a, what)
    if arr.ndim != 2 or arr.shape[1] != cols:
        raise ValueError(f"{what}: expected an array of shape (n, {cols}), got shape {arr.shape}")
    return np.ascontiguousarray(arr, dtype=np.float64)


def _finite_rows(a, cols, what):
    arr = _rows(a, cols, what)
    bad = ~np.isfinite(arr).all(axis=1)
    if bad.any():
        raise ValueError(f"{what}: row {int(np.argmax(bad))} is not finite")
    return arr


def _vec3(v, what, nonzero=False):
    arr = _real_array(v, what)
    if arr.shape != (3,):
        raise ValueError(f"{what}: expected 3 numbers, got shape {arr.shape}")
    arr = np.ascontiguousarray(arr, dtype=np.float64)
    if not np.isfinite(arr).all():
        raise ValueError(f"{what}: {arr.tolist()} is not finite")
    if nonzero and not (np.abs(arr) > 0).any():
        raise ValueError(f"{what}: has zero length")
    return arr


def _count(n, what, limit=2**32):
    if isinstance(n, bool) or not isinstance(n, numbers.Integral):
        raise ValueError(f"{what}: expected an integer, got {n!r}")
    if not 0 <= n <= limit:
        raise ValueError(f"{what}: {n} is outside [0, {limit}]")
    return int(n)


def _name(name, valid, what):
    if not isinstance(name, str) or name not in valid:
        raise ValueError(f"{what}: unknown name {name!r} (valid: {' '.join(valid)})")
    return name


class Sequence:
    """A 2D sample sequence in [0, 1)^2 (Christensen 2018, Sec. 2), randomized by `seed`.

    capacity: the table size of the tabulated sequences (best-candidate, pmj02, pmj02bn), None
    for the library's default 2^16; indices past it reuse the table block by block, randomized
    per block (sequence/tabulated.h). `disklab points --sequence` uses the default.
    """

    def __init__(self, name, seed=1, capacity=None):
        _name(name, sequence_names(), "name")
        seed = _count(seed, "seed", 2**64 - 1)
        if capacity is not None:
            capacity = _count(capacity, "capacity", 2**24)
            if capacity < 1:
                raise ValueError("capacity: must be at least 1")
        self._seq = _core.Sequence(name, seed, capacity)

    @property
    def name(self):
        return self._seq.name

    @property
    def seed(self):
        return self._seq.seed

    def points(self, n, first=0):
        """Points first .. first + n - 1 as an (n, 2) array."""
        n = _count(n, "n")
        first = _count(first, "first")
        if first + n > 2**32:
            raise ValueError(f"n: first + n = {first + n} exceeds the 2^32 indices")
        return self._seq.points(first, n)

    def at(self, indices):
        """The points at integer `indices` (any shape) in [0, 2^32): shape indices.shape + (2,)."""
        idx = np.asarray(indices)
        if idx.dtype.kind not in "iu":
            raise ValueError(f"indices: expected integers, got dtype {idx.dtype}")
        if idx.size and (idx.min() < 0 or idx.max() >= 2**32):
            raise ValueError("indices: outside [0, 2^32)")
        return self._seq.at(idx.ravel().astype(np.uint32)).reshape(idx.shape + (2,))

    def __repr__(self):
        return f"disklab.sequence({self.name!r}, seed={self.seed})"


def sequence(name, seed=1, capacity=None):
    """The sequence called `name` (see sequence_names()), randomized by `seed`."""
    return Sequence(name, seed, capacity)


class DiskStrategy:
    """A unit-disk sampling strategy of Christensen 2018, Sec. 3.

    sample(u) maps square points to disk points; the four-copy strategies (polar4, concentric4)
    give copies == 4 rows per square point, row 4 i + k being copy k of u[i]. pad-zero and
    rejection give the candidate 2 u - 1, with weights(u) saying how to count it.
    """

    def __init__(self, name):
        _name(name, strategy_names(), "name")
        self._s = _core.DiskStrategy(name)

    @property
    def name(self):
        return self._s.name

    @property
    def copies(self):
        return self._s.copies

    def sample(self, u):
        """(n, 2) square points -> (n * copies, 2) disk points."""
        return self._s.sample(_rows(u, 2, "u"))

    def weights(self, u):
        """Estimator weight of each row of sample(u): pad-zero 4/pi inside the disk and 0
        outside, rejection 1 accepted and 0 rejected, else 1."""
        return self._s.weights(_rows(u, 2, "u"))

    def invert(self, p):
        """(n, 2) disk points -> the square points they come from (NaN rows where none)."""
        return self._s.invert(_rows(p, 2, "p"))[0]

    def invert_copy(self, p):
        """(square points, copy index) of each disk point (copy 0 for one-copy strategies)."""
        return self._s.invert(_rows(p, 2, "p"))

    def pdf(self, p):
        """Area density of the strategy's points at p: 1/pi on the unit disk (pad-zero: 1/4 on
        [-1, 1]^2), 0 elsewhere."""
        return self._s.pdf(_rows(p, 2, "p"))

    def walk(self, seq, n, first=0):
        """The memo's renderer walk: n disk samples drawn from `seq` from square point `first`
        on (rejection skips the points outside the disk), as `disklab points --strategy`."""
        if not isinstance(seq, Sequence):
            raise ValueError("seq: expected a disklab.Sequence")
        n = _count(n, "n", 2**31)
        first = _count(first, "first", 2**31)
        return DiskWalk(*self._s.walk(seq._seq, n, first))

    def __repr__(self):
        return f"disklab.disk_strategy({self.name!r})"


def disk_strategy(name):
    """The strategy called `name` (see strategy_names())."""
    return DiskStrategy(name)


class Disk:
    """An oriented disk light: emits towards +normal (both sides if two_sided). normal may have
    any non-zero finite length; radius is finite and positive."""

    def __init__(self, center, normal, radius, two_sided=False):
        self.center = _vec3(center, "center")
        self.normal = _vec3(normal, "normal", nonzero=True)
        r = float(_real_array(radius, "radius"))
        if not (np.isfinite(r) and r > 0):
            raise ValueError(f"radius: {r} is not finite and positive")
        self.radius = r
        self.two_sided = bool(two_sided)

    def __repr__(self):
        return (f"disklab.Disk(center={self.center.tolist()}, normal={self.normal.tolist()}, "
                f"radius={self.radius!r}, two_sided={self.two_sided})")


def _disk(disk):
    if not isinstance(disk, Disk):
        raise ValueError("disk: expected a disklab.Disk")
    return disk


class EllipseMap:
    """A spherical-ellipse sampler of `disk` seen from the point `o` (Guillen et al. 2017 and
    the library's extensions; ellipse/any_map.h). `valid` is False when o sees no disk; every
    sample is then invalid."""

    def __init__(self, kind, disk, o, receiver_normal=None):
        _name(kind, map_names(), "kind")
        d = _disk(disk)
        o = _vec3(o, "o")
        if receiver_normal is not None:
            receiver_normal = _vec3(receiver_normal, "receiver_normal", nonzero=True)
        self.disk = d
        self.o = o
        self._m = _core.EllipseMap(kind, d.center, d.normal, d.radius, d.two_sided, o,
                                   receiver_normal)

    kind = property(lambda self: self._m.kind)
    valid = property(lambda self: self._m.valid)
    solid_angle = property(lambda self: self._m.solid_angle, doc="steradians (0 if not valid)")
    copies = property(lambda self: self._m.copies, doc="directions per u in sample_copies")
    has_inverse = property(lambda self: self._m.has_inverse)
    is_uniform = property(lambda self: self._m.is_uniform, doc="pdf == 1/solid_angle")

    def sample(self, u):
        """(n, 2) square points -> MapSamples of n rows (radial4: its full-ellipse sample)."""
        return MapSamples(*self._m.sample(_rows(u, 2, "u")))

    def sample_copies(self, u):
        """Every copy of each u: n * copies rows, row copies * i + k being copy k of u[i]
        (radial4's four reflections, as `disklab points --map radial4` prints them)."""
        return MapSamples(*self._m.sample_copies(_rows(u, 2, "u")))

    def pdf_of(self, directions):
        """Solid-angle density sample() reports for each direction (any non-zero length); 0
        where it misses the disk or is not finite."""
        return self._m.pdf_of(_rows(directions, 3, "directions"))

    def contains(self, directions):
        """Whether each ray from o along the direction meets the disk."""
        return self._m.contains(_rows(directions, 3, "directions"))

    def invert(self, directions):
        """u with sample_copies(u) along each direction, (n, 2), NaN rows where none."""
        return self._m.invert(_rows(directions, 3, "directions"))[0]

    def invert_copy(self, directions):
        """(u, copy): the copy index of each direction too (-1 where there is no inverse)."""
        return self._m.invert(_rows(directions, 3, "directions"))

    def __repr__(self):
        return f"disklab.ellipse_map({self.kind!r}, {self.disk!r}, o={self.o.tolist()})"


def ellipse_map(kind, disk, o, receiver_normal=None):
    """The map `kind` (see map_names()) of `disk` from the point o; projected samples the cosine
    to receiver_normal (default: the direction of the ellipse's centre), the others ignore it."""
    return EllipseMap(kind, disk, o, receiver_normal)


def solid_angle(disk, points):
    """Solid angle of `disk` from each of the (k, 3) points, (k,) (0 where it is not seen)."""
    d = _disk(disk)
    return _core.solid_angle(d.center, d.normal, d.radius, d.two_sided,
                             _finite_rows(points, 3, "points"))


def _elementwise(f, names, args):
    arrs = [_real_array(a, n) for a, n in zip(args, names)]
    try:
        b = np.broadcast_arrays(*arrs)
    except ValueError:
        raise ValueError(f"{', '.join(names)}: shapes {[a.shape for a in arrs]} do not broadcast")
    flat = [np.ascontiguousarray(a, dtype=np.float64).ravel() for a in b]
    out = f(*flat).reshape(b[0].shape)
    return float(out) if out.ndim == 0 else out


def ellint_f(phi, m):
    """F(phi|m) = int_0^phi dt / sqrt(1 - m sin^2 t), parameter m (scipy's ellipkinc(phi, m)),
    broadcasting like a ufunc. NaN outside the domain (m > 1)."""
    return _elementwise(_core.ellint_f, ("phi", "m"), (phi, m))


def ellint_pi(n, phi, m):
    """Pi(n; phi|m) = int_0^phi dt / ((1 - n sin^2 t) sqrt(1 - m sin^2 t)), broadcasting."""
    return _elementwise(_core.ellint_pi, ("n", "phi", "m"), (n, phi, m))


def carlson_rf(x, y, z):
    """Carlson's R_F(x, y, z) (DLMF 19.16.1; scipy's elliprf), broadcasting."""
    return _elementwise(_core.carlson_rf, ("x", "y", "z"), (x, y, z))


def carlson_rd(x, y, z):
    """Carlson's R_D(x, y, z) (DLMF 19.16.5; scipy's elliprd), broadcasting."""
    return _elementwise(_core.carlson_rd, ("x", "y", "z"), (x, y, z))


def carlson_rj(x, y, z, p):
    """Carlson's R_J(x, y, z, p) (DLMF 19.16.2; scipy's elliprj), broadcasting."""
    return _elementwise(_core.carlson_rj, ("x", "y", "z", "p"), (x, y, z, p))


def l2_star(points):
    """L2-star discrepancy of (n, 2) points in [0, 1]^2 (Warnock's closed form)."""
    p = _finite_rows(points, 2, "points")
    if ((p < 0) | (p > 1)).any():
        raise ValueError("points: outside [0, 1]^2")
    return _core.l2_star(p)
