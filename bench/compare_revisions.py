#!/usr/bin/env python3
"""Two kiln binaries on every scene of scenes/: same images within noise, and render time.

For a change that must not alter what kiln renders (a refactoring), or that may change only the
noise (a sampling change). Each scene is rendered by A and B alternately, one thread, SEEDS
times with independent seeds at SPP samples per pixel. For the whole image and each of its
quadrants, per channel, the mean over the seeds of the region's average pixel value is compared
with a z-score against the spread of the seeds (Welch): |z| above --sigmas flags the scene.
Render times are kiln's render-loop seconds ("s wall"); the table gives medians and B / A, and
the geometric mean of B / A over the scenes.

  bench/compare_revisions.py --a OLD/kiln --b build/kiln [--spp 4] [--seeds 6] [--sigmas 4.5]
"""
import argparse
import glob
import math
import os
import re
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
REGIONS = {"image": None, "q00": (0, 0), "q10": (1, 0), "q01": (0, 1), "q11": (1, 1)}


def render(binary, scene, spp, seed, out):
    """Renders; returns (render-loop seconds, resolution)"""
    r = subprocess.run([binary, scene, "--spp", str(spp), "--seed", str(seed), "--threads", "1",
                        "-o", out], capture_output=True, text=True)
    if r.returncode != 0:
        raise RuntimeError(f"{binary} {scene}: {r.stderr.strip()[-400:]}")
    m = re.search(r"([0-9.]+)s wall", r.stdout + r.stderr)
    return float(m.group(1)) if m else float("nan")


def averages(exr):
    """Per region, per channel average of the image (one oiiotool --printstats per region)"""
    info = subprocess.run(["oiiotool", "--info", exr], capture_output=True, text=True).stdout
    w, h = map(int, re.search(r"(\d+) x\s+(\d+)", info).groups())
    args = ["oiiotool"]
    for q in REGIONS.values():
        args += ["-i", exr]
        if q:
            qw, qh = w // 2, h // 2
            args += ["--cut", f"{qw}x{qh}+{q[0] * qw}+{q[1] * qh}"]
        args += ["--printstats"]
    out = subprocess.run(args, capture_output=True, text=True).stdout
    lines = re.findall(r"Stats Avg: ([-0-9.e ]+)", out)
    return {name: [float(v) for v in line.split()[:3]] for name, line in zip(REGIONS, lines)}


def z_score(a, b):
    ma, mb = statistics.fmean(a), statistics.fmean(b)
    va, vb = statistics.variance(a), statistics.variance(b)
    se = math.sqrt(va / len(a) + vb / len(b))
    if se == 0:
        return 0.0 if ma == mb else math.inf
    return (mb - ma) / se


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--a", required=True, help="the reference binary")
    p.add_argument("--b", required=True, help="the binary under test")
    p.add_argument("--spp", type=int, default=4)
    p.add_argument("--seeds", type=int, default=6)
    p.add_argument("--sigmas", type=float, default=4.5)
    p.add_argument("--scenes", nargs="*", help="scene files (default: every scene in scenes/)")
    args = p.parse_args()
    scenes = args.scenes or sorted(glob.glob(os.path.join(ROOT, "scenes", "**", "*.pbrt"),
                                             recursive=True))
    ratios, flagged = [], []
    print(f"{'scene':34} {'A s':>8} {'B s':>8} {'B/A':>6} {'max|z|':>7}")
    with tempfile.TemporaryDirectory() as tmp:
        for scene in scenes:
            stats = {"a": [], "b": []}
            times = {"a": [], "b": []}
            try:
                for seed in range(1, args.seeds + 1):
                    for key, binary in (("a", args.a), ("b", args.b)):
                        out = os.path.join(tmp, f"{key}.exr")
                        times[key].append(render(binary, scene, args.spp, seed, out))
                        stats[key].append(averages(out))
            except RuntimeError as e:
                print(f"{os.path.relpath(scene, ROOT):34} error: {e}")
                flagged.append(scene)
                continue
            zmax = 0.0
            for region in REGIONS:
                for c in range(len(stats["a"][0][region])):
                    z = z_score([s[region][c] for s in stats["a"]],
                                [s[region][c] for s in stats["b"]])
                    zmax = max(zmax, abs(z))
            ta, tb = statistics.median(times["a"]), statistics.median(times["b"])
            ratio = tb / ta if ta > 0 else float("nan")
            if math.isfinite(ratio):
                ratios.append(ratio)
            if zmax > args.sigmas:
                flagged.append(scene)
            print(f"{os.path.relpath(scene, ROOT):34} {ta:8.3f} {tb:8.3f} {ratio:6.3f} {zmax:7.2f}"
                  + ("  DIFFERS" if zmax > args.sigmas else ""), flush=True)
    print(f"\n{len(scenes)} scenes, {len(flagged)} flagged (|z| > {args.sigmas})")
    if ratios:
        gm = math.exp(statistics.fmean(math.log(r) for r in ratios))
        print(f"render time B / A: geometric mean {gm:.4f}, "
              f"range {min(ratios):.3f}-{max(ratios):.3f}")
    return 1 if flagged else 0


if __name__ == "__main__":
    sys.exit(main())
