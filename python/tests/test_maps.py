"""disklab.ellipse_map: the CLI's directions bit for bit, every pdf integrating to what it must
(in numpy, from directions uniform in a cone around the disk), inverses, bad input."""
import os
import subprocess

import numpy as np
import pytest

import disklab

MAPS = disklab.map_names()
rng = np.random.default_rng(7)

# (disk, shading point, receiver normal): near and off-axis, far, and seen at a grazing angle.
SCENES = {
    "near": (disklab.Disk((0, 0, 1), (0, 0, -1), 1.0), (0.3, 0.2, 0), (0.36, -0.48, 0.8)),
    "far": (disklab.Disk((1, 0.5, 20), (0.1, 0, -1), 0.7), (0, 0, 0), (0, 0, 1)),
    "grazing": (disklab.Disk((3, 0, 0.4), (-0.05, 0, -1), 1.0), (0, 0, 0), (0, 0, 1)),
}


def make(kind, scene):
    disk, o, n = SCENES[scene]
    return disklab.ellipse_map(kind, disk, o, n if kind == "projected" else None)


def cli_scene(kind, scene):
    disk, o, n = SCENES[scene]
    args = ["--map", kind, "--center", ",".join(map(repr, disk.center.tolist())),
            "--normal", ",".join(map(repr, disk.normal.tolist())), "--radius", repr(disk.radius),
            "--point", ",".join(map(repr, map(float, o)))]
    if kind == "projected":
        args += ["--receiver-normal", ",".join(map(repr, map(float, n)))]
    return args


def test_names():
    assert MAPS == ["area", "gamito", "parallel", "radial", "ld-radial", "radial4", "tabulated",
                    "radial-fast", "projected"]


@pytest.mark.parametrize("kind", MAPS)
@pytest.mark.parametrize("scene", ["near", "grazing"])
def test_samples_equal_the_cli_bit_for_bit(cli, kind, scene):
    n = 512
    rows = cli("points", *cli_scene(kind, scene), "--sequence", "pmj02", "--seed", 3,
               "--count", n)
    m = make(kind, scene)
    # `points --map` sizes a tabulated sequence's table for --count (make_sequence(.., count)).
    u = disklab.sequence("pmj02", seed=3, capacity=n).points(-(-n // m.copies))
    s = m.sample_copies(u)
    np.testing.assert_array_equal(rows[:, 1:3], np.repeat(u, m.copies, axis=0)[:n])
    ok = s.valid[:n]
    assert ok.mean() > 0.5
    np.testing.assert_array_equal(rows[ok, 3:6], s.direction[:n][ok])
    np.testing.assert_array_equal(rows[ok, 6], s.pdf[:n][ok])
    # The CLI writes pdf 0 for "no sample" (a rejected gamito or tabulated candidate).
    np.testing.assert_array_equal(rows[~ok, 6], 0.0)
    assert (s.pdf[:n][~ok] == 0).all() and (s.direction[:n][~ok] == 0).all()


def cone_directions(disk, o, count):
    """Directions uniform in a cone around o's view of the disk, and the cone's solid angle."""
    c, nrm = disk.center - o, disk.normal / np.linalg.norm(disk.normal)
    axis = c / np.linalg.norm(c)
    e1 = np.cross(nrm, [1, 0, 0] if abs(nrm[0]) < 0.9 else [0, 1, 0])
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(nrm, e1)
    t = np.linspace(0, 2 * np.pi, 4096, endpoint=False)[:, None]
    rim = c + disk.radius * (np.cos(t) * e1 + np.sin(t) * e2)
    cos_rim = (rim @ axis) / np.linalg.norm(rim, axis=1)
    # 2% more angle than the widest rim point: the rim between grid points bulges by far less.
    theta = min(1.02 * np.arccos(cos_rim.min()), np.pi)
    cmin = np.cos(theta)
    z = 1 - rng.random(count) * (1 - cmin)
    phi = 2 * np.pi * rng.random(count)
    rr = np.sqrt(np.maximum(0, 1 - z * z))
    a1 = np.cross(axis, e1)
    a1 /= np.linalg.norm(a1)
    a2 = np.cross(axis, a1)
    w = z[:, None] * axis + rr[:, None] * (np.cos(phi)[:, None] * a1 + np.sin(phi)[:, None] * a2)
    return w, 2 * np.pi * (1 - cmin)


@pytest.mark.parametrize("kind", MAPS)
@pytest.mark.parametrize("scene", list(SCENES))
def test_pdf_integrates_to_one_or_the_acceptance_rate(kind, scene):
    m = make(kind, scene)
    disk, o, _ = SCENES[scene]
    w, cone = cone_directions(disk, np.asarray(o, float), 200_000)
    f = m.pdf_of(w) * cone
    integral, se = f.mean(), f.std() / np.sqrt(f.size)
    target, target_se = 1.0, 0.0
    if kind in ("gamito", "tabulated"):
        # Proposal densities integrate to the acceptance rate (any_map.h).
        acc = m.sample(rng.random((200_000, 2))).valid
        target, target_se = acc.mean(), acc.std() / np.sqrt(acc.size)
    # 5 standard errors of the two estimates: fails by chance once in ~10^6 runs.
    assert abs(integral - target) < 5 * np.hypot(se, target_se) + 1e-12
    assert se < 0.02  # the test has power: the cone is not mostly empty


@pytest.mark.parametrize("kind", MAPS)
def test_directions_are_unit_inside_the_disk_and_pdf_of_agrees(kind):
    m = make(kind, "near")
    s = m.sample(rng.random((5000, 2)))
    d = s.direction[s.valid]
    # 1e-15: unit up to the last rounding of the normalization.
    np.testing.assert_allclose(np.linalg.norm(d, axis=1), 1, rtol=0, atol=1e-15)
    assert m.contains(d).all()
    if m.is_uniform:
        np.testing.assert_array_equal(s.pdf[s.valid], 1 / m.solid_angle)
    # The density recomputed from the direction (another ray-disk intersection) rounds apart
    # from the sample's own; 1e-9 checks the binding, the C++ tests bound the difference.
    np.testing.assert_allclose(m.pdf_of(d), s.pdf[s.valid], rtol=1e-9)


@pytest.mark.parametrize("kind", [k for k in MAPS if k != "gamito"])
def test_invert_round_trips(kind):
    m = make(kind, "near")
    u = rng.random((2000, 2))
    s = m.sample_copies(u)
    back, copy = m.invert_copy(s.direction[s.valid])
    assert (copy == np.tile(np.arange(m.copies), u.shape[0])[s.valid]).all()
    again = m.sample_copies(back)
    k = np.arange(back.shape[0]) * m.copies + copy
    # 1e-9 rad: a binding check; the C++ inverse tests bound the round trip far tighter.
    np.testing.assert_allclose(again.direction[k], s.direction[s.valid], rtol=0, atol=1e-9)
    assert np.isnan(m.invert([[0.0, 0.0, -1.0]])).all()  # a direction that misses the disk


def test_gamito_has_no_inverse():
    m = make("gamito", "near")
    assert not m.has_inverse and np.isnan(m.invert([[0.3, 0.2, 1.0]])).all()


def test_nan_or_out_of_range_u_gives_invalid_rows_never_a_nan_direction():
    m = make("radial", "near")
    u = np.array([[np.nan, 0.5], [0.5, np.inf], [-1e-300, 0.5], [0.5, 1 + 1e-16 * 3], [0, 1],
                  [1, 0]])
    s = m.sample(u)
    np.testing.assert_array_equal(s.valid, [False, False, False, False, True, True])
    assert np.isfinite(s.direction).all() and np.isfinite(s.pdf).all()
    assert (s.pdf[~s.valid] == 0).all()


def test_invalid_geometry_gives_an_invalid_map():
    behind = disklab.ellipse_map("radial", disklab.Disk((0, 0, 1), (0, 0, 1), 1), (0, 0, 0))
    assert not behind.valid and behind.solid_angle == 0
    s = behind.sample(rng.random((10, 2)))
    assert not s.valid.any() and (s.pdf == 0).all()
    two = disklab.ellipse_map("radial", disklab.Disk((0, 0, 1), (0, 0, 1), 1, two_sided=True),
                              (0, 0, 0))
    assert two.valid and two.solid_angle > 0


def test_normals_of_any_finite_non_zero_length():
    a = disklab.ellipse_map("radial", disklab.Disk((0, 0, 1), (0, 0, -1e-200), 1), (0.3, 0, 0))
    b = disklab.ellipse_map("radial", disklab.Disk((0, 0, 1), (0, 0, -1), 1), (0.3, 0, 0))
    assert a.valid and a.solid_angle == b.solid_angle


def test_solid_angle_on_the_axis_and_against_the_cli(cli):
    disk = disklab.Disk((0, 0, 0), (0, 0, 1), 2.0)
    h = np.geomspace(1e-6, 1e8, 60)
    pts = np.stack([np.zeros_like(h), np.zeros_like(h), h], axis=1)
    # On the axis: 2 pi r^2 / (s (s + h)), s = sqrt(h^2 + r^2) (no cancellation). 3e-15: this
    # formula's own few roundings (~1e-15) plus the library's documented ~1e-15.
    s = np.sqrt(h * h + 4.0)
    np.testing.assert_allclose(disklab.solid_angle(disk, pts), 2 * np.pi * 4 / (s * (s + h)),
                               rtol=3e-15, atol=0)
    p = rng.normal(size=(5, 3)) * 3
    got = disklab.solid_angle(disk, p)
    for i in range(5):
        want = cli("solid-angle", "--center", "0,0,0", "--normal", "0,0,1", "--radius", 2,
                   "--point", ",".join(map(repr, p[i].tolist())), header=False)
        assert want[0, 0] == got[i]  # both print and parse %.17g: the same double


@pytest.mark.parametrize("call, arg", [
    (lambda: disklab.Disk((0, np.nan, 0), (0, 0, 1), 1), "center"),
    (lambda: disklab.Disk((0, 0), (0, 0, 1), 1), "center"),
    (lambda: disklab.Disk((0, 0, 0), (0, 0, 0), 1), "normal"),
    (lambda: disklab.Disk((0, 0, 0), (0, np.inf, 1), 1), "normal"),
    (lambda: disklab.Disk((0, 0, 0), (0, 0, 1), 0), "radius"),
    (lambda: disklab.Disk((0, 0, 0), (0, 0, 1), -1), "radius"),
    (lambda: disklab.Disk((0, 0, 0), (0, 0, 1), np.nan), "radius"),
    (lambda: disklab.ellipse_map("spiral", SCENES["near"][0], (0, 0, 0)), "kind"),
    (lambda: disklab.ellipse_map("radial", "disk", (0, 0, 0)), "disk"),
    (lambda: disklab.ellipse_map("radial", SCENES["near"][0], (0, np.nan, 0)), "o"),
    (lambda: disklab.ellipse_map("projected", SCENES["near"][0], (0, 0, 0), (0, 0, 0)),
     "receiver_normal"),
    (lambda: make("radial", "near").sample(np.zeros((4, 3))), "u"),
    (lambda: make("radial", "near").sample(np.zeros((4, 2), dtype=bool)), "u"),
    (lambda: make("radial", "near").pdf_of(np.zeros((4, 2))), "directions"),
    (lambda: make("radial", "near").invert(np.zeros(3)), "directions"),
    (lambda: disklab.solid_angle(SCENES["near"][0], [[0, 0, np.nan]]), "points"),
    (lambda: disklab.solid_angle(SCENES["near"][0], [[0, 0]]), "points"),
])
def test_bad_input_raises_value_error_naming_the_argument(call, arg):
    with pytest.raises(ValueError, match=f"^{arg}:"):
        call()


def test_cli_takes_normals_and_directions_of_any_non_zero_length(cli):
    # Issue 46, finding 7: the CLI refused --normal 0,0,-1e-200 ("has zero length") because its
    # squared norm underflows; the library and this package take it.
    scene = ["--map", "radial", "--center", "0,0,1", "--radius", "1", "--point", "0.3,0,0"]
    unit = cli("points", *scene, "--normal", "0,0,-1", "--count", 64)
    tiny = cli("points", *scene, "--normal", "0,0,-1e-200", "--count", 64)
    np.testing.assert_array_equal(tiny, unit)
    exe = os.environ["DISKLAB_CLI"]
    inv = [subprocess.run([exe, "map", *scene, "--normal", "0,0,-1", "--inverse", "--dir", d],
                          check=True, capture_output=True, text=True).stdout
           for d in ("0.1,0.2,1", "1e-201,2e-201,1e-200")]
    a, b = (np.array(t.split(), dtype=float) for t in inv)
    # The two decimal texts are the same direction up to a rounding of each coordinate (1e-201
    # is not exactly 0.1 * 1e-200): u moves by as little, far below 1e-14.
    assert a.shape == (2,) and np.abs(a - b).max() < 1e-14
