"""The static equilibrium of the SPH cable's discrete chain (moorings.chain_equilibrium):
every node in balance, the seabed's nodes laid flat, and the continuous elastic catenary
recovered as the chain is refined."""

import numpy as np
import pytest

from moorings.catenary import solve
from moorings.chain_equilibrium import discrete_equilibrium

L, W_LEN, EA = 150.0, 918.75, 1e9


def _chain(n):
    ds = np.full(n - 1, L / (n - 1))
    half = np.zeros(n)
    half[:-1] += 0.5 * ds
    half[1:] += 0.5 * ds
    return ds, W_LEN * half


def _balance(pos, ds, W, seabed_z=0.0):
    """Each interior node's net force [N] from its two segments and its weight; the seabed
    carries the vertical part of the nodes that rest on it."""
    seg = np.diff(pos, axis=0)
    ln = np.linalg.norm(seg, axis=1)
    T = (EA * (ln / ds - 1.0))[:, None] * seg / ln[:, None]
    net = T[1:] - T[:-1]
    net[:, -1] -= W[1:-1]
    on_bed = np.isclose(pos[1:-1, -1], seabed_z, atol=1e-9)
    assert np.all(net[on_bed, -1] <= 1e-6 * W.max())  # the bed pushes up, never pulls down
    net[on_bed, -1] = 0.0
    return net, on_bed


@pytest.mark.parametrize("X, h", [(130.0, 50.0), (101.0, 50.0), (140.0, 50.0), (105.0, 100.0)])
def test_every_node_is_in_balance_and_the_chain_ends_on_its_supports(X, h):
    ds, W = _chain(40)
    law = solve(X, h, L, W_LEN, EA)
    pos, H, V = discrete_equilibrium([0.0, 0.0], [X, h], ds, W, EA, (law.H, law.V))
    net, on_bed = _balance(pos, ds, W)
    assert np.abs(net).max() < 1e-6 * W.max()
    assert pos[0] == pytest.approx([0.0, 0.0]) and pos[-1] == pytest.approx([X, h])
    assert on_bed.any() == (law.touchdown > 0)  # the law's regime: partly on the bed or fully lifted
    assert np.all(pos[:, 1] >= -1e-9)


def test_it_tends_to_the_continuous_catenary_at_second_order():
    """Fully lifted (X = 105 m, h = 100 m): H and V (with the fairlead node's own weight,
    which its support carries) fall by 4.00 per halving of ds (measured -0.62 / -0.15 /
    -0.038 % of H at 10 / 20 / 40 segments). Partly on the bed (X = 130 m, h = 50 m) the
    touchdown jumps from node to node: no clean order, -1.5 / -0.35 / -0.07 / +0.002 %."""
    for (X, h), ns, bound in (((105.0, 100.0), (11, 21, 41), None), ((130.0, 50.0), (11, 41, 81), (0.02, 1e-3, 1e-4))):
        law = solve(X, h, L, W_LEN, EA)
        errs = []
        for n in ns:
            ds, W = _chain(n)
            _, H, V = discrete_equilibrium([0.0, 0.0], [X, h], ds, W, EA, (law.H, law.V))
            errs.append((abs(H / law.H - 1.0), abs((V + W[-1]) / law.V - 1.0)))
        errs = np.array(errs)
        if bound is None:
            assert errs[0] / errs[1] == pytest.approx([4.0, 4.0], rel=0.03)
            assert errs[1] / errs[2] == pytest.approx([4.0, 4.0], rel=0.03)
        else:
            assert np.all(errs.max(axis=1) < bound)


def test_3d_line_lies_in_the_vertical_plane_through_its_ends():
    ds, W = _chain(30)
    a, f = np.array([10.0, -5.0, -50.0]), np.array([10.0 + 0.6 * 130, -5.0 + 0.8 * 130, 0.0])
    law = solve(130.0, 50.0, L, W_LEN, EA)
    pos, H, V = discrete_equilibrium(a, f, ds, W, EA, (law.H, law.V))
    plane = np.cross(f - a, [0.0, 0.0, 1.0])
    assert np.abs((pos - a) @ plane).max() < 1e-9 * L * np.linalg.norm(plane)
    _, H2, V2 = discrete_equilibrium([0.0, -50.0], [130.0, 0.0], ds, W, EA, (law.H, law.V))
    assert (H, V) == pytest.approx((H2, V2), rel=1e-9)
