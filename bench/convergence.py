#!/usr/bin/env python3
"""Convergence benchmark: relative MSE against render time for kiln's benchmark scenes.

For each scene and each sampling strategy, renders at 1, 2, 4, ... samples per pixel (up to
--max-spp, or until one render takes more than --time-budget / 2 seconds), measures each image's
relMSE against a high-spp reference and writes

    bench/results/convergence.csv   one row per render
    bench/results/convergence.png   log-log plot of relMSE against render time

References are rendered once (--ref-spp, a seed different from the test renders so that errors
are independent) and cached in bench/out/ref/, keyed by a hash of the scene text, resolution and
sample count; --rerender-reference renders them again (do that after renderer changes that
alter the converged image). relMSE and the plot come from kiln_benchtool (bench/benchtool.cpp)
so that no Python packages beyond the standard library are needed.

Strategies: STRATEGIES maps a name to a Strategy: extra kiln command-line flags and/or extra
parameters for the scene's `Integrator "path"` directive (applied to a copy of the scene in
bench/out/scenes/). light-only / BSDF-only / MIS use kiln --strategy; area-lights / uniform-lights pick emitters by area or uniformly instead of by power
(kiln --light-sampler), one-wavelength traces 1 wavelength per path instead of 4 (kiln
--wavelengths). Select them with e.g. --strategies default,bsdf,area-lights. The reference always uses "default".
"""

import argparse
import csv
import hashlib
import os
import re
import subprocess
import sys
import time
from dataclasses import dataclass, field
from typing import List, Optional, Tuple

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BENCH = os.path.join(ROOT, "bench")


@dataclass
class BenchScene:
    name: str
    path: str  # relative to the repository root
    # (x, y) resolution override, applied to a copy of the scene in bench/out/scenes/ (only for
    # scenes without relative file references, which the copy would break).
    resolution: Optional[Tuple[int, int]] = None


SCENES = [
    BenchScene("cornell-diffuse", "bench/scenes/cornell-diffuse.pbrt"),
    # The glowing spheres of Wilkie & Weidlich 2011, Sec. 4.1, as the lead's scene defines them.
    BenchScene("glowing-spheres", "scenes/wilkie2011/blackbody-lights.pbrt", (160, 100)),
    # Kirchhoff emission from smooth gold spheres (kiln's point), same ring.
    BenchScene("kirchhoff-gold", "scenes/wilkie2011/gold-kirchhoff-ambient.pbrt", (160, 100)),
    BenchScene("glossy-conductors", "bench/scenes/glossy-conductors.pbrt"),
    BenchScene("hot-spot", "bench/scenes/hot-spot.pbrt"),
    # A large thermal emitter mesh with a per-vertex heat field: cool almost everywhere, one
    # small hot spot (power-proportional emitter selection matters here).
    BenchScene("hot-spot-mesh", "bench/scenes/hot-spot-mesh.pbrt"),
    # A large emitter whose temperature comes from an image heat map.
    BenchScene("heat-mapped-emitter", "bench/scenes/heat-mapped-emitter.pbrt"),
]

@dataclass
class Strategy:
    flags: List[str] = field(default_factory=list)  # extra kiln command-line flags
    integrator: str = ""  # extra parameters of Integrator "path", in pbrt syntax


# Strategy name -> how to render with it (see the module docstring).
STRATEGIES = {
    "default": Strategy(),  # the scene as written (MIS unless the scene says otherwise)
    "mis": Strategy(flags=["--strategy", "mis"]),
    "light": Strategy(flags=["--strategy", "light"]),
    "bsdf": Strategy(flags=["--strategy", "bsdf"]),
    "area-lights": Strategy(flags=["--light-sampler", "area"]),
    "uniform-lights": Strategy(flags=["--light-sampler", "uniform"]),
    "one-wavelength": Strategy(flags=["--wavelengths", "1"]),
}

TEST_SEED = 1
REFERENCE_SEED = 7919

SUMMARY = re.compile(r"kiln: (\d+)x(\d+), (\d+) spp, ([0-9.]+)s wall, ([0-9.]+) Mpaths/s")


def log(msg: str) -> None:
    print(f"convergence: {msg}", file=sys.stderr, flush=True)


def scene_file(scene: BenchScene, out_dir: str, strategy: Strategy = Strategy()) -> Tuple[str, str]:
    """The file to render (a modified copy if needed) and its text (for the cache key)."""
    src = os.path.join(ROOT, scene.path)
    with open(src, encoding="utf-8") as f:
        text = f.read()
    if scene.resolution is None and not strategy.integrator:
        return src, text
    if strategy.integrator:
        if re.search(r'^\s*Integrator\s+"path"', text, re.M):
            text = re.sub(r'^(\s*Integrator\s+"path")', rf"\g<1> {strategy.integrator}", text,
                          count=1, flags=re.M)
        else:
            text = re.sub(r"^(\s*WorldBegin)", rf'Integrator "path" {strategy.integrator}\n\g<1>',
                          text, count=1, flags=re.M)
    if re.search(r'^\s*(Include|Import)\b|"[^"]*\.(ply|png|tga|pfm|spd)"',
                 text, re.M):
        log(f"warning: {scene.path} references other files; its resized copy may not load")
    if scene.resolution is not None:
        x, y = scene.resolution
        text = re.sub(r'("integer xresolution"\s*\[?\s*)\d+', rf"\g<1>{x}", text)
        text = re.sub(r'("integer yresolution"\s*\[?\s*)\d+', rf"\g<1>{y}", text)
    os.makedirs(os.path.join(out_dir, "scenes"), exist_ok=True)
    suffix = "" if not strategy.integrator else "-" + hashlib.sha1(
        strategy.integrator.encode()).hexdigest()[:8]
    dst = os.path.join(out_dir, "scenes", scene.name + suffix + ".pbrt")
    with open(dst, "w", encoding="utf-8") as f:
        f.write(text)
    return dst, text


def render(kiln: str, scene_path: str, out: str, spp: int, seed: int, threads: Optional[int],
           extra: List[str]) -> Tuple[float, float, float]:
    """Renders; returns (render-loop seconds, process wall seconds, Mpaths/s)."""
    cmd = [kiln, scene_path, "-o", out, "--spp", str(spp), "--seed", str(seed)] + extra
    if threads:
        cmd += ["--threads", str(threads)]
    t0 = time.perf_counter()
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    wall = time.perf_counter() - t0
    if proc.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)} failed ({proc.returncode}):\n{proc.stderr}")
    m = None
    for line in proc.stderr.splitlines():
        m = SUMMARY.search(line) or m
    if m is None:  # summary format changed: fall back to the process time
        return wall, wall, 0.0
    return float(m.group(4)), wall, float(m.group(5))


def rel_mse(tool: str, ref: str, test: str) -> Tuple[float, float, float]:
    """(relMSE, MSE, render seconds from the test's header or -1) of test against ref; the one
    place to switch to `kiln diff` later."""
    proc = subprocess.run([tool, "relmse", ref, test], stdout=subprocess.PIPE, text=True,
                          check=True)
    f = proc.stdout.split()
    return float(f[1]), float(f[3]), float(f[7])


def reference(args, scene: BenchScene, path: str, text: str) -> str:
    key = hashlib.sha1(f"{text}\n{scene.resolution}\n{args.ref_spp}".encode()).hexdigest()[:12]
    ref_dir = os.path.join(args.out, "ref")
    os.makedirs(ref_dir, exist_ok=True)
    ref = os.path.join(ref_dir, f"{scene.name}-{args.ref_spp}spp-{key}.exr")
    if os.path.exists(ref) and not args.rerender_reference:
        log(f"{scene.name}: cached reference {os.path.relpath(ref, ROOT)}")
        return ref
    log(f"{scene.name}: rendering reference at {args.ref_spp} spp ...")
    seconds, _, mpaths = render(args.kiln, path, ref, args.ref_spp, REFERENCE_SEED,
                                args.threads, [])
    log(f"{scene.name}: reference took {seconds:.1f} s ({mpaths:.2f} Mpaths/s)")
    return ref


def write_strategy_table(rows, path: str) -> None:
    """Error at equal time of each strategy relative to the default, per scene: relMSE x time
    at the largest sample count both reached (relMSE falls as 1/time, so this is the ratio of
    the times needed for equal error; < 1 means better than the default)."""
    data = {}
    for scene, strategy, spp, seconds, _, _, relmse, *_ in rows:
        data.setdefault((scene, strategy), {})[int(spp)] = (float(seconds), float(relmse))
    scenes = sorted({s for s, _ in data})
    strategies = sorted({t for _, t in data if t != "default"})
    lines = ["| scene | " + " | ".join(strategies) + " |",
             "|---|" + "---|" * len(strategies)]
    for scene in scenes:
        base = data.get((scene, "default"), {})
        cells = []
        for strategy in strategies:
            other = data.get((scene, strategy), {})
            common = sorted(set(base) & set(other))
            if not common:
                cells.append("-")
                continue
            spp = common[-1]
            (tb, eb), (to, eo) = base[spp], other[spp]
            cells.append(f"{eo * to / (eb * tb):.2f}x ({spp} spp)")
        lines.append(f"| {scene} | " + " | ".join(cells) + " |")
    with open(path, "w") as f:
        f.write("Error at equal time relative to the default strategy (MIS, power light "
                "selection, 4 wavelengths); > 1 is worse.\n\n" + "\n".join(lines) + "\n")
    log(f"wrote {os.path.relpath(path, ROOT)}")


def main() -> int:
    build = os.environ.get("KILN_BUILD_DIR", os.path.join(ROOT, "build"))
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--kiln", default=os.path.join(build, "kiln"))
    p.add_argument("--tool", default=os.path.join(build, "bench", "kiln_benchtool"))
    p.add_argument("--scenes", default=",".join(s.name for s in SCENES),
                   help="comma-separated subset of: " + ", ".join(s.name for s in SCENES))
    p.add_argument("--strategies", default="default",
                   help="comma-separated subset of: " + ", ".join(STRATEGIES))
    p.add_argument("--max-spp", type=int, default=256)
    p.add_argument("--time-budget", type=float, default=20.0,
                   help="stop doubling once a render would exceed this many seconds")
    p.add_argument("--ref-spp", type=int, default=2048)
    p.add_argument("--threads", type=int, default=None)
    p.add_argument("--rerender-reference", action="store_true")
    p.add_argument("--out", default=os.path.join(BENCH, "out"))
    p.add_argument("--results", default=os.path.join(BENCH, "results"))
    args = p.parse_args()

    scenes = [s for s in SCENES if s.name in args.scenes.split(",")]
    strategies = args.strategies.split(",")
    for s in strategies:
        if s not in STRATEGIES:
            p.error(f"unknown strategy '{s}' (known: {', '.join(STRATEGIES)})")
    os.makedirs(args.results, exist_ok=True)
    rows = []
    for scene in scenes:
        path, text = scene_file(scene, args.out)
        ref = reference(args, scene, path, text)
        for strategy in strategies:
            strat = STRATEGIES[strategy]
            spath, _ = scene_file(scene, args.out, strat)
            img_dir = os.path.join(args.out, "renders", scene.name)
            os.makedirs(img_dir, exist_ok=True)
            spp = 1
            while spp <= args.max_spp:
                img = os.path.join(img_dir, f"{strategy}-{spp}spp.exr")
                seconds, wall, mpaths = render(args.kiln, spath, img, spp, TEST_SEED,
                                               args.threads, strat.flags)
                rel, mse, header_seconds = rel_mse(args.tool, ref, img)
                if header_seconds > 0:  # more digits than kiln's summary line
                    seconds = header_seconds
                eff = 1.0 / (rel * seconds) if rel > 0 and seconds > 0 else 0.0
                if spp == 1:
                    # The reference's own error: about relMSE(1 spp) / ref-spp for Monte Carlo
                    # (less with quasi-Monte Carlo samplers); measured relMSE >= this floor.
                    floor = rel / args.ref_spp
                rows.append([scene.name, strategy, spp, f"{seconds:.4f}", f"{wall:.3f}",
                             f"{mpaths:.3f}", f"{rel:.6g}", f"{mse:.6g}", f"{eff:.6g}",
                             f"{floor:.3g}"])
                log(f"{scene.name} [{strategy}] {spp:4d} spp  {seconds:7.3f} s  "
                    f"relMSE {rel:.4g}")
                if 2 * seconds > args.time_budget:
                    break
                spp *= 2

    csv_path = os.path.join(args.results, "convergence.csv")
    with open(csv_path, "w", newline="", encoding="utf-8") as f:
        w = csv.writer(f)
        w.writerow(["scene", "strategy", "spp", "seconds", "process_seconds", "mpaths_per_s",
                    "relmse", "mse", "efficiency", "ref_floor"])
        w.writerows(rows)
    log(f"wrote {os.path.relpath(csv_path, ROOT)}")
    write_strategy_table(rows, os.path.join(args.results, "strategies.md"))
    png = os.path.join(args.results, "convergence.png")
    subprocess.run([args.tool, "plot", csv_path, png,
                    f"kiln convergence (reference {args.ref_spp} spp)"], check=True)
    log(f"wrote {os.path.relpath(png, ROOT)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
