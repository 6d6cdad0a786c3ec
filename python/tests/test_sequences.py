"""disklab.sequence: the CLI's points bit for bit, at() == points(), capacities, bad input."""
import numpy as np
import pytest

import disklab

NAMES = disklab.sequence_names()


def test_names_are_the_memos_sequences():
    assert NAMES[0] == "random" and "sobol-owen" in NAMES and "pmj02" in NAMES
    assert len(NAMES) == len(set(NAMES)) == 10


@pytest.mark.parametrize("name", NAMES)
def test_points_equal_the_cli_bit_for_bit(cli, name):
    rows = cli("points", "--sequence", name, "--seed", 7, "--count", 300)
    p = disklab.sequence(name, seed=7).points(300)
    assert p.shape == (300, 2) and p.dtype == np.float64
    np.testing.assert_array_equal(rows[:, 0], np.arange(300))
    # Exact: %.17g reads back the same double, so any difference is a different point.
    np.testing.assert_array_equal(rows[:, 1:3], p)


@pytest.mark.parametrize("name", NAMES)
def test_at_equals_points_and_stays_in_the_half_open_square(name):
    s = disklab.sequence(name, seed=3)
    p = s.points(500)
    assert ((p >= 0) & (p < 1)).all()
    idx = np.array([[499, 0], [17, 256]])
    np.testing.assert_array_equal(s.at(idx), p[idx])
    np.testing.assert_array_equal(s.points(100, first=400), p[400:])
    # Seeds randomize: another seed moves the points.
    assert not np.array_equal(disklab.sequence(name, seed=4).points(500), p)


def test_tabulated_capacity_keeps_prefixes_and_blocks_past_it():
    small = disklab.sequence("pmj02", seed=5, capacity=64)
    large = disklab.sequence("pmj02", seed=5, capacity=1024)
    a, b = small.points(128), large.points(128)
    # The table's points do not depend on its size; past it the table is reused per block.
    np.testing.assert_array_equal(a[:64], b[:64])
    assert not np.array_equal(a[64:], b[64:])
    # Default capacity is the library's 2^16, which the CLI's `points --sequence` uses.
    np.testing.assert_array_equal(disklab.sequence("pmj02", seed=5).points(128), b)


def test_repr_and_properties():
    s = disklab.sequence("halton-scrambled", seed=2**64 - 1)
    assert s.name == "halton-scrambled" and s.seed == 2**64 - 1
    assert "halton-scrambled" in repr(s)


@pytest.mark.parametrize("call, arg", [
    (lambda: disklab.sequence("sobol"), "name"),
    (lambda: disklab.sequence(3), "name"),
    (lambda: disklab.sequence("random", seed=-1), "seed"),
    (lambda: disklab.sequence("random", seed=2**64), "seed"),
    (lambda: disklab.sequence("random", seed=1.5), "seed"),
    (lambda: disklab.sequence("pmj02", capacity=0), "capacity"),
    (lambda: disklab.sequence("pmj02", capacity=2**25), "capacity"),
    (lambda: disklab.sequence("random").points(-1), "n"),
    (lambda: disklab.sequence("random").points(2.0), "n"),
    (lambda: disklab.sequence("random").points(2, first=2**32 - 1), "n"),
    (lambda: disklab.sequence("random").at([0.5]), "indices"),
    (lambda: disklab.sequence("random").at([-1]), "indices"),
    (lambda: disklab.sequence("random").at([2**32]), "indices"),
])
def test_bad_input_raises_value_error_naming_the_argument(call, arg):
    with pytest.raises(ValueError, match=f"^{arg}:"):
        call()
