"""disklab.disk_strategy: the CLI's walk bit for bit, sample/invert/pdf, bad input."""
import numpy as np
import pytest

import disklab

NAMES = disklab.strategy_names()
rng = np.random.default_rng(20261207)


def test_names_are_the_memos_strategies():
    assert NAMES == ["pad-zero", "rejection", "polar", "concentric", "polar4", "concentric4"]


@pytest.mark.parametrize("name", NAMES)
@pytest.mark.parametrize("seq", ["sobol-owen", "pmj02"])
def test_walk_equals_the_cli_bit_for_bit(cli, name, seq):
    rows = cli("points", "--strategy", name, "--sequence", seq, "--seed", 11, "--count", 256)
    w = disklab.disk_strategy(name).walk(disklab.sequence(seq, seed=11), 256)
    np.testing.assert_array_equal(rows[:, 0], np.arange(256))
    np.testing.assert_array_equal(rows[:, 1:3], w.uv)
    np.testing.assert_array_equal(rows[:, 3:5], w.point)
    np.testing.assert_array_equal(rows[:, 5], w.weight)


@pytest.mark.parametrize("name", NAMES)
def test_sample_agrees_with_the_walk(name):
    s = disklab.disk_strategy(name)
    seq = disklab.sequence("halton-rotated", seed=2)
    w = s.walk(seq, 400)
    u = seq.points(w.index.max() + 1)
    p, wt = s.sample(u), s.weights(u)
    assert p.shape == (u.shape[0] * s.copies, 2)
    if name == "rejection":
        # The walk skips rejected candidates: it is sample() with weight 0 rows removed.
        np.testing.assert_array_equal(p[wt > 0][:400], w.point)
    else:
        np.testing.assert_array_equal(p[:400], w.point)
        np.testing.assert_array_equal(wt[:400], w.weight)


@pytest.mark.parametrize("name", ["polar", "concentric", "polar4", "concentric4"])
def test_maps_are_area_preserving_onto_the_disk_and_invert(name):
    s = disklab.disk_strategy(name)
    u = rng.random((20000, 2))
    p = s.sample(u)
    r2 = (p**2).sum(axis=1)
    # 1e-15: the rim r = 1 can be passed by the roundings of r cos, r sin.
    assert (r2 <= 1 + 1e-15).all()
    # Area preserving: the fraction inside radius 1/2 is 1/4 (binomial 5-sigma, n = 20000 * copies).
    n = p.shape[0]
    assert abs((r2 < 0.25).mean() - 0.25) < 5 * np.sqrt(0.25 * 0.75 / n)
    uv, k = s.invert_copy(p)
    np.testing.assert_array_equal(k, np.tile(np.arange(s.copies), u.shape[0]))
    # 1e-14 absolute: u = r^2 and the angle each come back through a few roundings (sqrt,
    # cos/sin, then x^2 + y^2 and atan2 or atan), each within an ulp of 1 (1.1e-16).
    np.testing.assert_allclose(uv, np.repeat(u, s.copies, axis=0), rtol=0, atol=1e-14)
    np.testing.assert_array_equal(s.pdf(p), np.full(n, 1 / np.pi))


def test_pad_zero_and_rejection_candidates_and_weights():
    u = np.array([[0.5, 0.5], [0.0, 0.0], [0.99, 0.5]])
    for name, inside in (("pad-zero", 4 / np.pi), ("rejection", 1.0)):
        s = disklab.disk_strategy(name)
        np.testing.assert_array_equal(s.sample(u), 2 * u - 1)
        np.testing.assert_array_equal(s.weights(u), [inside, 0.0, inside])
        back = s.invert(s.sample(u))
        np.testing.assert_array_equal(back[[0, 2]], u[[0, 2]])
    # No inverse: rejection outside the disk, pad-zero outside [-1, 1]^2.
    assert np.isnan(disklab.disk_strategy("rejection").invert([[-1.0, -1.0]])).all()
    assert np.isnan(disklab.disk_strategy("pad-zero").invert([[1.5, 0.0]])).all()
    np.testing.assert_array_equal(disklab.disk_strategy("pad-zero").pdf([[0.9, 0.9], [1.1, 0]]),
                                  [0.25, 0.0])


@pytest.mark.parametrize("call, arg", [
    (lambda: disklab.disk_strategy("square"), "name"),
    (lambda: disklab.disk_strategy("polar").sample(np.zeros((3, 3))), "u"),
    (lambda: disklab.disk_strategy("polar").sample(np.zeros(2)), "u"),
    (lambda: disklab.disk_strategy("polar").sample(np.array([["a", "b"]])), "u"),
    (lambda: disklab.disk_strategy("polar").sample(np.zeros((2, 2), dtype=complex)), "u"),
    (lambda: disklab.disk_strategy("polar").invert(np.zeros((2, 1))), "p"),
    (lambda: disklab.disk_strategy("polar").walk("sobol-owen", 4), "seq"),
    (lambda: disklab.disk_strategy("polar").walk(disklab.sequence("random"), -4), "n"),
])
def test_bad_input_raises_value_error_naming_the_argument(call, arg):
    with pytest.raises(ValueError, match=f"^{arg}:"):
        call()
