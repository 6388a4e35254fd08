#!/usr/bin/env python3
"""kiln against pbrt-v4, paired, on scenes of every kind real pbrt-v4 scenes have and on kiln's
glow scenes: load and render time, whole-process CPU time, peak memory, error at equal time.

Scenes are generated into bench/out/pairs/ (bench/pair_scenes.py, bench/pair_glow.py). Each
repetition renders every scene once with kiln and once with pbrt-v4, back to back under the
shared lock (/tmp/kiln-build.lock), alternating which goes first, with the same seed (a new
one per repetition). Per run: the child's user + system CPU time and peak RSS (os.wait4),
process wall time, the renderer's own load and render phases, and relMSE against a pbrt-v4
reference at --ref-spp (another seed; cached in bench/out/pairs/ref/). Medians and min-max
over the repetitions go to bench/results/pairbench.md (table) and pairbench.csv (every run).

  bench/pairbench.py [--quick] [--scenes a,b] [--reps 3] [--threads 1]
See bench/README.md ("kiln against pbrt-v4") for what each column means.
"""
import argparse
import csv
import fcntl
import hashlib
import json
import os
import platform
import re
import shlex
import statistics
import subprocess
import sys
import tempfile
import time
from contextlib import contextmanager

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import pair_glow  # noqa: E402
import pair_scenes  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BENCH = os.path.join(ROOT, "bench")
LOCK = "/tmp/kiln-build.lock"
REFERENCE_SEED = 7919
FULL = pair_scenes.Size(width=192, height=128, spp=16, ref_spp=512, scale=1.0)
QUICK = pair_scenes.Size(width=32, height=24, spp=4, ref_spp=32, scale=0.02)


def log(msg):
    print(f"pairbench: {msg}", file=sys.stderr, flush=True)


@contextmanager
def machine_lock():
    """The shared lock every render on this machine takes (as `flock /tmp/kiln-build.lock`)."""
    with open(LOCK, "a") as f:
        fcntl.flock(f, fcntl.LOCK_EX)
        try:
            yield
        finally:
            fcntl.flock(f, fcntl.LOCK_UN)


GNU_TIME = "/usr/bin/time"


def run(cmd, cwd):
    """Runs cmd; returns (output text, wall s, CPU s = user + system, peak RSS MB).

    The child's CPU time comes from os.wait4. Its peak RSS comes from GNU time (`%M`, the
    ru_maxrss of a child forked by the small `time` process): a child forked by this Python
    process would report at least Python's own resident size, which it had before exec."""
    with tempfile.TemporaryFile() as out, tempfile.NamedTemporaryFile("r") as peak:
        t0 = time.perf_counter()
        proc = subprocess.Popen([GNU_TIME, "-f", "%M", "-o", peak.name] + cmd, cwd=cwd,
                                stdout=out, stderr=subprocess.STDOUT)
        _, status, usage = os.wait4(proc.pid, 0)
        wall = time.perf_counter() - t0
        proc.returncode = os.waitstatus_to_exitcode(status)
        out.seek(0)
        text = out.read().decode(errors="replace")
        peak_kb = peak.read().split()
    if proc.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)} failed ({proc.returncode}):\n{text[-2000:]}")
    rss = float(peak_kb[-1]) / 1024.0 if peak_kb else float("nan")
    return text, wall, usage.ru_utime + usage.ru_stime, rss


def kiln_cmd(args, scene, spp, seed, threads, image):
    return ([args.kiln, os.path.basename(scene), "--spp", str(spp), "--seed", str(seed),
             "--threads", str(threads), "--stats", "--quiet", "-o", image] + scene_flags(scene))


def pbrt_cmd(args, scene, spp, seed, threads, image):
    return [args.pbrt, "--nthreads", str(threads), "--spp", str(spp), "--seed", str(seed),
            "--quiet", "--log-level", "verbose", "--outfile", image, os.path.basename(scene)]


SCENE_FLAGS = {}  # kiln file -> extra kiln flags (PairScene.kiln_flags)


def scene_flags(scene):
    return SCENE_FLAGS.get(scene, [])


def kiln_phases(text):
    """kiln --stats: (load s, render s); load is parsing and scene creation (BVH included)."""
    def get(label):
        m = re.search(rf"^\s*{label}\s+([0-9.]+) s", text, re.M)
        return float(m.group(1)) if m else float("nan")
    return get("Parsing and scene creation"), get("Rendering")


def pbrt_phases(text):
    """pbrt-v4 --log-level verbose timestamps (seconds since start): load = until 'Memory used
    after scene creation' (parsing, textures, lights, BVH, integrator), render = from there to
    'Writing image'."""
    def at(msg):
        m = re.search(rf"@\s+([0-9.]+)s [^\]]*\] {msg}", text)
        return float(m.group(1)) if m else float("nan")
    created = at("Memory used after scene creation")
    return created, at("Writing image with spp") - created


def relmse(args, ref, image):
    out = subprocess.run([args.tool, "relmse", ref, image], capture_output=True, text=True,
                         check=True).stdout.split()
    return float(out[1])


def image_mean(image):
    """Sum of the R, G, B averages (oiiotool)."""
    out = subprocess.run(["oiiotool", "-i", image, "--printstats"], capture_output=True,
                         text=True).stdout
    m = re.search(r"Stats Avg: ([-0-9.e ]+)", out)
    return sum(float(v) for v in m.group(1).split()[:3]) if m else float("nan")


def calibration(args, temperatures):
    """photometric(T): pbrt-v4's scale for a `blackbody` emitter of T to emit B(T) in kiln's
    units, measured: a 32 x 32 view of a hot black quad (kiln) over the same view of a
    blackbody area light of scale 1 (pbrt-v4). Cached in bench/out/pairs/calibration.json."""
    path = os.path.join(args.out, "calibration.json")
    cache = json.load(open(path)) if os.path.exists(path) else {}
    folder = os.path.join(args.out, "calibration")
    os.makedirs(folder, exist_ok=True)
    head = ('LookAt 0 0 0  0 0 1  0 1 0\nCamera "perspective" "float fov" 30\n'
            'Film "rgb" "integer xresolution" 32 "integer yresolution" 32 '
            '"string filename" "c.exr"\nWorldBegin\n')
    quad = ('Shape "trianglemesh" "integer indices" [0 1 2 0 2 3] '
            '"point3 P" [-5 -5 3  5 -5 3  5 5 3  -5 5 3]\n')
    for T in temperatures:
        if str(T) in cache:
            continue
        k = os.path.join(folder, f"kiln-{T}.pbrt")
        p = os.path.join(folder, f"pbrt-{T}.pbrt")
        open(k, "w").write(head + f'Material "diffuse" "rgb reflectance" [0 0 0] '
                                  f'"float temperature" {T}\n' + quad)
        open(p, "w").write(head + f'AreaLightSource "diffuse" "blackbody L" {T} '
                                  '"bool twosided" true\n' + quad)
        with machine_lock():
            run([args.kiln, k, "--spp", "256", "--quiet", "-o", f"kiln-{T}.exr"], folder)
            run([args.pbrt, "--spp", "256", "--quiet", "--outfile", f"pbrt-{T}.exr", p], folder)
        cache[str(T)] = (image_mean(os.path.join(folder, f"kiln-{T}.exr"))
                         / image_mean(os.path.join(folder, f"pbrt-{T}.exr")))
        log(f"calibration: photometric({T} K) = {cache[str(T)]:.6g}")
        json.dump(cache, open(path, "w"), indent=1)
    return lambda T: cache[str(T)]


def reference(args, scene):
    """pbrt-v4 at the scene's ref_spp with its own seed, on all --ref-threads; cached."""
    text = open(scene.pbrt_file).read()
    key = hashlib.sha1(f"{text}\n{scene.ref_spp}\n{args.pbrt}".encode()).hexdigest()[:12]
    ref = os.path.join(args.out, "ref", f"{scene.name}-{scene.ref_spp}spp-{key}.exr")
    if os.path.exists(ref):
        return ref
    os.makedirs(os.path.dirname(ref), exist_ok=True)
    log(f"{scene.name}: pbrt-v4 reference at {scene.ref_spp} spp ...")
    with machine_lock():
        _, wall, _, _ = run(pbrt_cmd(args, scene.pbrt_file, scene.ref_spp, REFERENCE_SEED,
                                     args.ref_threads, ref), os.path.dirname(scene.pbrt_file))
    log(f"{scene.name}: reference took {wall:.1f} s")
    return ref


def bench_scene(args, scene, ref, rows):
    runners = {"kiln": (kiln_cmd, kiln_phases, scene.kiln_file),
               "pbrt-v4": (pbrt_cmd, pbrt_phases, scene.pbrt_file)}
    for rep in range(args.reps):
        order = ["kiln", "pbrt-v4"] if rep % 2 == 0 else ["pbrt-v4", "kiln"]
        results = {}
        with machine_lock():  # both renderers of a pair see the same machine
            for name in order:
                cmd, phases, path = runners[name]
                image = os.path.join(args.out, "renders", f"{scene.name}-{name}-{rep}.exr")
                text, wall, cpu, rss = run(cmd(args, path, scene.spp, rep + 1, args.threads,
                                               image), os.path.dirname(path))
                results[name] = (image, wall, cpu, rss, *phases(text))
        for name in ("kiln", "pbrt-v4"):
            image, wall, cpu, rss, load, render = results[name]
            err = relmse(args, ref, image) if scene.equivalent else float("nan")
            mean = image_mean(image) if rep == 0 else float("nan")
            rows.append(dict(scene=scene.name, renderer=name, rep=rep, spp=scene.spp,
                             threads=args.threads, load_s=load, render_s=render, wall_s=wall,
                             cpu_s=cpu, peak_mb=rss, relmse=err, image_mean=mean))
            log(f"{scene.name} {name:7} rep {rep}: load {load:.3f} s render {render:.3f} s "
                f"CPU {cpu:.2f} s peak {rss:.0f} MB relMSE {err:.4g}")


def med(values):
    values = [v for v in values if v == v]
    return statistics.median(values) if values else float("nan")


def cell(values, digits=2):
    values = [v for v in values if v == v]
    if not values:
        return "-"
    if len(values) == 1:
        return f"{values[0]:.{digits}f}"
    lo, mid, hi = min(values), statistics.median(values), max(values)
    return f"{mid:.{digits}f} ({lo:.{digits}f}-{hi:.{digits}f})"


def summarise(args, scenes, rows, command):
    lines = [
        "# kiln against pbrt-v4 (bench/pairbench.py)", "",
        f"Command: `{command}`  ",
        f"kiln: {args.kiln}, built from commit {args.commit}; pbrt-v4: {args.pbrt} "
        "(portable build; "
        "pbrt-v4's -march=native build is 20-25 % faster)  ",
        f"Machine: {platform.machine()}, {os.cpu_count()} cores, shared; 5-minute load average "
        f"{args.load_start:.2f} at the start, {os.getloadavg()[1]:.2f} at the end "
        f"(renders held the shared lock; other work may have run beside them). "
        f"{args.machine_note}  ",
        f"{args.reps} repetitions, {args.threads} thread(s), sizes {args.size}; medians "
        "(min-max). Times in seconds, peak RSS in MB. Reference: pbrt-v4 at the given spp, "
        "another seed.", "",
        "| scene | what | spp | load kiln | load pbrt | render kiln | render pbrt | CPU kiln | "
        "CPU pbrt | **CPU k/p** | peak kiln | peak pbrt | relMSE kiln | relMSE pbrt | "
        "**error at equal time k/p** | mean k/p |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for s in scenes:
        r = {n: [row for row in rows if row["scene"] == s.name and row["renderer"] == n]
             for n in ("kiln", "pbrt-v4")}
        col = {n: {k: [row[k] for row in r[n]] for k in rows[0]} for n in r}
        k, p = col["kiln"], col["pbrt-v4"]
        cpu_ratio = med(k["cpu_s"]) / med(p["cpu_s"])
        if s.equivalent:
            eq = (med(k["relmse"]) * med(k["render_s"])) / (med(p["relmse"]) * med(p["render_s"]))
            eq_cell = f"**{eq:.2f}**"
        else:
            eq_cell = "time only"
        mean_ratio = med(k["image_mean"]) / med(p["image_mean"])
        lines.append(
            f"| {s.name} | {s.kind} | {s.spp} | {cell(k['load_s'])} | {cell(p['load_s'])} | "
            f"{cell(k['render_s'])} | {cell(p['render_s'])} | {cell(k['cpu_s'])} | "
            f"{cell(p['cpu_s'])} | **{cpu_ratio:.2f}** | {med(k['peak_mb']):.0f} | "
            f"{med(p['peak_mb']):.0f} | {med(k['relmse']):.3g} | {med(p['relmse']):.3g} | "
            f"{eq_cell} | {mean_ratio:.3f} |")
    notes = [f"- {s.name}: {s.note}" for s in scenes if s.note]
    return "\n".join(lines + [""] + notes) + "\n"


def main():
    build = os.environ.get("KILN_BUILD_DIR", os.path.join(ROOT, "build"))
    generators = pair_scenes.GENERATORS + pair_glow.GENERATORS
    all_names = [g.__name__.replace("_", "-") for g in generators]
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--kiln", default=os.path.join(build, "kiln"))
    p.add_argument("--tool", default=os.path.join(build, "bench", "kiln_benchtool"))
    p.add_argument("--pbrt",
                   default=os.path.join(ROOT, "..", "shared", "anchors", "pbrt-v4", "pbrt"))
    p.add_argument("--scenes", default="",
                   help="comma-separated subset of: " + ", ".join(all_names))
    p.add_argument("--reps", type=int, default=None, help="repetitions (default 3, quick 1)")
    p.add_argument("--threads", type=int, default=1)
    p.add_argument("--ref-threads", type=int, default=os.cpu_count())
    p.add_argument("--quick", action="store_true", help="tiny images, few samples, 1 repetition")
    p.add_argument("--kiln-commit", default="", help="the commit the kiln binary was built from")
    p.add_argument("--machine-note", default="", help="e.g. 'other agents were building'")
    p.add_argument("--out", default=os.path.join(BENCH, "out", "pairs"))
    p.add_argument("--results", default=None,
                   help="where the table and CSV go (default bench/results/, with --quick "
                        "bench/out/pairs/)")
    args = p.parse_args()
    args.reps = args.reps or (1 if args.quick else 3)
    args.out = os.path.abspath(args.out)
    args.results = args.results or (args.out if args.quick else os.path.join(BENCH, "results"))
    size = QUICK if args.quick else FULL
    args.size = f"{size.width}x{size.height}, {size.spp} spp, reference {size.ref_spp} spp"
    args.kiln, args.pbrt = os.path.abspath(args.kiln), os.path.abspath(args.pbrt)
    # The binary's commit unless given: the last commit of its checkout before the binary was
    # written (a guess: the binary may have been built from uncommitted or later-merged work)
    mtime = int(os.path.getmtime(args.kiln))
    args.commit = subprocess.run(["git", "-C", os.path.dirname(args.kiln), "log", "-1",
                                  "--format=%h", f"--before={mtime}"],
                                 capture_output=True, text=True).stdout.strip() or "?"
    stamp = time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime(mtime))
    args.commit = args.kiln_commit or (
        f"{args.commit} (guessed: last commit before the binary's date, {stamp})")
    args.load_start = os.getloadavg()[1]
    wanted = args.scenes.split(",") if args.scenes else all_names
    for name in wanted:
        if name not in all_names:
            p.error(f"unknown scene '{name}' (known: {', '.join(all_names)})")
    os.makedirs(os.path.join(args.out, "renders"), exist_ok=True)

    scenes = []
    photometric = None
    for gen in generators:
        if gen.__name__.replace("_", "-") not in wanted:
            continue
        if gen in pair_glow.GENERATORS:
            if photometric is None:
                photometric = calibration(args, sorted(set(pair_glow.TEMPERATURES) | {1100, 1300}))
            scene = gen(args.out, size, photometric)
        else:
            scene = gen(args.out, size)
        SCENE_FLAGS[scene.kiln_file] = scene.kiln_flags
        scenes.append(scene)

    rows = []
    for scene in scenes:
        ref = reference(args, scene) if scene.equivalent else None
        bench_scene(args, scene, ref, rows)

    os.makedirs(args.results, exist_ok=True)
    suffix = "-quick" if args.quick else ""
    with open(os.path.join(args.results, f"pairbench{suffix}.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows({k: (f"{v:.6g}" if isinstance(v, float) else v) for k, v in row.items()}
                    for row in rows)
    command = "bench/pairbench.py " + shlex.join(sys.argv[1:])
    table = summarise(args, scenes, rows, command)
    with open(os.path.join(args.results, f"pairbench{suffix}.md"), "w") as f:
        f.write(table)
    print(table)
    return 0


if __name__ == "__main__":
    sys.exit(main())
