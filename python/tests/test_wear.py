"""Wear, WearProfile, wear_profile_update and Accumulator against the
relations the header states for them (each quoted in the test), so a field
read into the wrong array or a total from the wrong slot fails."""

import numpy as np
import pytest

import creepwork

CONTACT = dict(a=7e-3, b=5e-3, N=100e3, xi_x=1e-3, xi_y=2e-3, phi=0.5)


@pytest.fixture(scope="module")
def worn():
    with creepwork.Solver() as s:
        r = s.solve(**CONTACT)
        w = s.wear(pass_length=2.5, density=7850.0)
        kth = s.wear(law="archard_kth", rolling_speed=20.0)
    return r, w, kth


def test_wear_totals_and_fields(worn):
    r, w, _ = worn
    rho, area = 7850.0, r.area
    # "mass_per_distance: sum of rate * area", "mass_per_pass: mass_per_distance
    # * pass_length", "volume_per_distance: mass_per_distance / rho"
    assert w.mass_per_distance == pytest.approx((w.rate * area).sum(), rel=1e-12)
    assert w.mass_per_pass == pytest.approx(w.mass_per_distance * 2.5, rel=1e-15)
    assert w.volume_per_distance == pytest.approx(w.mass_per_distance / rho, rel=1e-15)
    # "depth per pass: rate * area / (rho dy_j)", strip j of width dy_j = 2b/ny here.
    dy = 2 * CONTACT["b"] / 20
    np.testing.assert_allclose(w.depth, w.rate * area / (rho * dy), rtol=1e-12, atol=0)
    np.testing.assert_allclose(w.mass, w.rate * area * 2.5, rtol=1e-12, atol=0)
    # The strips: depth per pass summed over the strip; max_depth the largest.
    np.testing.assert_allclose(w.strips.depth, w.depth.sum(axis=1), rtol=1e-12, atol=1e-30)
    assert w.max_depth == pytest.approx(w.strips.depth.max(), rel=1e-12)
    np.testing.assert_allclose(w.strips.width, dy, rtol=1e-12)
    # The energy-consistent work the USFD law is fed with sums to W_macro.
    assert w.work == pytest.approx(r.W_macro, rel=1e-9)
    assert w.law == creepwork.CW_WEAR_USFD and w.regime_area.shape == (4,)
    # Regime areas: the contact area in each regime 1..4.
    for k in range(4):
        assert w.regime_area[k] == pytest.approx(area[w.regimes == k + 1].sum(), rel=1e-12)
    assert w.rate.shape == w.regimes.shape == (20, 20)


def test_archard_law(worn):
    _, w, kth = worn
    assert kth.law == creepwork.CW_WEAR_ARCHARD_KTH
    assert kth.mass_per_distance > 0 and kth.mass_per_distance != w.mass_per_distance


def test_profile_accumulation_is_exact_and_conserves_volume(worn):
    s_nodes = np.linspace(-0.03, 0.03, 241)
    width = s_nodes[1] - s_nodes[0]
    with creepwork.Solver() as solver, creepwork.WearProfile(s_nodes) as all_at_once, \
            creepwork.WearProfile(s_nodes) as half, creepwork.WearProfile(s_nodes) as other:
        solver.solve(**CONTACT)
        w = solver.wear()
        all_at_once.add(solver, s0=2e-3, passes=1000)
        half.add(solver, s0=2e-3, passes=400)
        other.add(solver, s0=2e-3, passes=600)
        half.merge(other)
        # "Sums are exact: ... on how the same passes are split between calls, or on merging"
        assert half.depth().tobytes() == all_at_once.depth().tobytes()
        totals = all_at_once.totals()
        # "volume: worn cross-section added [m^2]" = passes * sum(depth_j * dy_j)
        volume = 1000 * (w.strips.depth * w.strips.width).sum()
        assert totals["volume"] == pytest.approx(volume, rel=1e-12)
        assert totals["volume_lost"] == 0.0 and totals["adds"] == 1 and totals["passes"] == 1000
        assert (all_at_once.depth() * width).sum() == pytest.approx(volume, rel=1e-12)
        # The state round trip of MPI workers.
        with creepwork.WearProfile(s_nodes) as copy:
            copy.add_state(all_at_once.state())
            assert copy.depth().tobytes() == all_at_once.depth().tobytes()
        # Caller's strips: the same strips give the same depths, bitwise.
        with creepwork.WearProfile(s_nodes) as strips:
            strips.add_strips(w.strips.y, w.strips.width, w.strips.depth, s0=2e-3, passes=1000)
            assert strips.depth().tobytes() == all_at_once.depth().tobytes()
        all_at_once.reset()
        assert np.all(all_at_once.depth() == 0)
        with pytest.raises(creepwork.UnknownOptionError):
            all_at_once.depth("sideways")


def test_profile_update_conserves_the_cross_section():
    """cw_wear_profile_update: sum (old - new) * width = sum depth * width."""
    s = np.linspace(0.0, 0.1, 101)
    old = np.full(101, 0.02)
    depth = 1e-4 * np.exp(-((s - 0.05) / 0.01) ** 2)
    new = creepwork.wear_profile_update(s, old, depth, smoothing=0.004)
    width = np.full(101, 1e-3)
    width[[0, -1]] = 1e-3  # end cells extend half a spacing beyond the end nodes
    assert ((old - new) * width).sum() == pytest.approx((depth * width).sum(), rel=1e-12)
    assert (old - new).max() < depth.max()  # smoothed
    with pytest.raises(creepwork.InvalidInputError, match="smoothing"):
        creepwork.wear_profile_update(s, old, depth, smoothing=-1.0)


def test_accumulator():
    with creepwork.Solver() as s, creepwork.Accumulator(s) as acc:
        r1 = s.solve(**CONTACT)
        acc.add(s, 0.5)
        r2 = s.solve(**dict(CONTACT, xi_x=2e-3))
        acc.add(s, 0.25)
        t = acc.totals()
        # paper eq. 35: sum of W_macro V dt
        assert t["W_macro"] == pytest.approx(0.5 * r1.W_macro + 0.25 * r2.W_macro, rel=1e-12)
        assert t["distance"] == 0.75 and t["steps"] == 2
        consistent = 0.5 * r1.W_consistent + 0.25 * r2.W_consistent
        assert acc.field("work_consistent").sum() == pytest.approx(consistent, rel=1e-12)
        assert acc.strip_work().sum() == pytest.approx(consistent, rel=1e-12)
        with pytest.raises(creepwork.InvalidInputError, match="distance"):
            acc.add(s, -1.0)
