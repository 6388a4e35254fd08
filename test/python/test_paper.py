"""Wilkie & Weidlich 2011, statement by statement (docs/paper.md): each test renders the
repository's scene of a figure (scripts/paper_figures.py, seed 1) and asserts what the paper
says the figure shows.

Samples: 1 per pixel, but 4 for Fig. 10. Every quantity was measured at 1, 4 and 64 spp
(docs/paper.md lists the 64-spp values). The sums run over thousands of pixels: of the tested
values that page lists, none moves by more than 9 % between 1 and 64 spp (silver's degree of polarisation under ambient
light, 0.0228 against 0.021, bounded at 0.038), and every bound is further from its value than
that. The closest is black quartz's B/C > 1, 4.5 % below its 1.045 at 1 spp (1.044 at 64).
Fig. 10's effect is small, and its test a paired z-score of the per-pixel differences, which
does not grow as the square root of the samples (the effect varies from pixel to pixel): 5.9
at 1 spp, 4.8 at 2, 7.7 at 4 and 11.7 at 64, against a bound of 5; hence 4 spp there."""

import os
import sys

import numpy as np
import pytest

import kiln

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "scripts"))
import paper_figures as paper  # noqa: E402

SPP = 1
FIG10_SPP = 4


@pytest.fixture(scope="module")
def fig7():
    return paper.measure_fig7(SPP)


def test_fig1_gold_glows_yellow_orange_and_nickel_red():
    m = paper.measure_fig1(SPP)
    (xg, yg), (xn, yn) = m["gold xy"], m["nickel xy"]
    assert xn > xg + 0.05 and yg > yn + 0.01  # nickel redder, gold towards yellow


def test_fig5_additive_emission_barely_changes_black_quartz_but_silver_greatly():
    m = paper.measure_fig5(SPP)
    assert 1.0 < m["black-quartz B/C"] < 1.15      # black quartz emits 1 - F, F about 4 %
    assert m["silver B/C"] > 10                    # "good reflectors are bad emitters"
    # "errors at the edges of the spheres": the additive error grows towards the limb
    assert m["black-quartz error limb"] > 1.5 * m["black-quartz error centre"]


def test_fig6_glow_follows_albedo_and_selenium_glows_almost_as_black_quartz():
    m = paper.measure_fig6(SPP)
    assert 0.8 < m["selenium/black-quartz"] < 1.2
    assert m["silver/black-quartz"] < 0.1 < m["platinum/black-quartz"] < 0.8


def test_fig7_gold_and_copper_glow_off_the_blackbody_hue_and_ambient_only_partly_masks_it(fig7):
    for metal in ("gold", "copper"):
        # Every sphere: less red (smaller x) and greener (larger y) than the blackbody glow
        assert np.all(fig7[f"{metal} dx"] < -0.05) and np.all(fig7[f"{metal} dy"] > 0.01)
        # With ambient light the hue is still displaced, less so on the cooler spheres
        assert np.all(fig7[f"{metal}-ambient dx"] < -0.01)
        cool = slice(0, 6)
        assert np.all(np.abs(fig7[f"{metal}-ambient dx"][cool]) < np.abs(fig7[f"{metal} dx"][cool]))
    # The additive render's hue is the blackbody's: at 1300 K the sphere of pbrt-v4 blackbody
    # lights and kiln's gold differ by the displacement above
    assert fig7["gold xy 1300K"][0] < fig7["blackbody xy 1300K"][0] - 0.05


def test_fig8_a_glowing_gold_disc_is_brighter_through_a_vertical_polariser():
    assert paper.measure_fig8(SPP)["vertical/horizontal"] > 1.5


def test_fig9_emission_polarisation_metals_over_dielectrics_radial_and_cancelled_by_ambient():
    m = paper.measure_fig9(SPP)
    assert m["silver DoP"] > 3 * m["black-quartz DoP"]
    # Emission is polarised along the radius (p), 90 degrees from reflection (s)
    assert m["silver radial"] > 0.8 * m["silver DoP"] and m["black-quartz radial"] > 0
    # Reflected ambient light cancels it: silver's almost wholly, black quartz's is overturned
    # (its weak emission polarisation is outweighed by the reflection's, along the circumference)
    assert m["silver-ambient DoP"] < 0.1 * m["silver DoP"]
    assert m["black-quartz-ambient radial"] < 0


def test_fig10_polarisation_changes_reflections_in_black_glass_not_the_spheres():
    m = paper.measure_fig10(FIG10_SPP)
    assert m["reflection pixels"] > 2000
    assert abs(m["reflections difference z"]) > 5
    assert abs(m["spheres polarised/unpolarised"] - 1) < 0.005


# The spread between published n,k data sets for the same metal (../shared/data: Johnson &
# Christy 1972, a 298 K ellipsometry set, and Palik-handbook tables), against the effects the
# figures show: each effect must stand clear of what the choice of data set alone moves.

SHARED = os.path.join(os.path.dirname(__file__), "..", "..", "..", "shared", "data")
DATA_SETS = {
    "Au": ["nk_Au.csv", "nk_Au_298K.csv", "palik/nk_Au_luxpop.csv"],
    "Cu": ["nk_Cu.csv", "palik/nk_Cu_Palik1985.csv", "palik/nk_Cu_luxpop.csv"],
    "Ag": ["nk_Ag.csv", "nk_Ag_298K.csv", "palik/nk_Ag_luxpop.csv"],
}


def conductor_from(path):
    rows = np.loadtxt(os.path.join(SHARED, path), delimiter=",", skiprows=1)
    rows = rows[(rows[:, 0] >= 300) & (rows[:, 0] <= 900)]
    return {"spectrum eta": list(rows[:, [0, 1]].ravel()),
            "spectrum k": list(rows[:, [0, 2]].ravel())}


needs_data = pytest.mark.skipif(not os.path.isdir(SHARED), reason="no ../shared/data beside the checkout")


@needs_data
def test_fig7_hue_shift_stands_clear_of_the_spread_between_nk_data_sets(fig7):
    for metal, name in (("Au", "gold"), ("Cu", "copper")):
        x = [kiln.glow_color(1300, "conductor", conductor_from(f)).xy[0] for f in DATA_SETS[metal]]
        spread = max(x) - min(x)
        # The 1300 K sphere's displacement from the blackbody hue, against that spread
        assert abs(fig7[f"{name} dx"][5]) > 2 * spread, (metal, x)


@needs_data
def test_fig5_silver_bound_holds_for_every_nk_data_set():
    lam = np.arange(400.0, 701.0, 10.0)
    for f in DATA_SETS["Ag"]:
        # Visible emissivity at normal incidence, weighted by ybar: B/C of a sphere is about
        # its inverse (more at the limb, where silver emits relatively more)
        e = kiln.emissivity("conductor", conductor_from(f), 0.0, lam)
        ybar = kiln._kiln._cie_xyz(lam)[:, 1]
        ratio = ybar.sum() / (e * ybar).sum()
        assert ratio > 10, (f, ratio)  # test_fig5's bound holds whichever data set is used


def test_the_masks_follow_the_scenes_cameras():
    """Sphere pixels are found with one camera for every scene of the ring: they must share it."""
    import glob
    root = os.path.join(paper.ROOT, "scenes")
    ring = glob.glob(os.path.join(root, "wilkie2011", "*.pbrt")) + \
        glob.glob(os.path.join(root, "polarization", "fig9-*.pbrt")) + \
        glob.glob(os.path.join(root, "polarization", "fig10-*.pbrt"))
    assert len(ring) == 30
    for path in ring:
        assert paper.camera_of(os.path.relpath(path, root)) == paper.RING_CAMERA, path
