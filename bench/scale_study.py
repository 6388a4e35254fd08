#!/usr/bin/env python3
"""Scale study (issue 27): kiln's load time, render time and peak memory against triangle count,
instanced triangles, number of hot emitters and threads, with a projection to a 64-core node.

Scenes come from bench/scale_scenes.py (generated into bench/out/scale/, not versioned). Each
run holds the shared lock (/tmp/kiln-build.lock) for one kiln process only and is killed after
--timeout seconds (90: the lock is shared); a sweep stops at the first size that times out,
fails, or whose peak memory, extrapolated linearly from the size before, would pass
--memory-fraction of the memory available. Per run: kiln --stats's phases (load = parsing and
scene creation, BVH included; render = the render loop), camera paths, Embree's BVH peak and
the scene's committed estimate, the process's CPU time (os.wait4) and peak RSS (GNU time %M,
as bench/pairbench.py), and the 1-minute load average before the run.

Outputs in bench/results/scale/: one CSV per sweep (every run), an SVG plot per sweep (log-log)
and summary.md (medians, fitted exponents, per-unit costs, the 64-core projection).

Sweeps not named in --sweeps are read back from their CSVs, so summary.md always covers all
of them (--sweeps none: rewrite the report and plots only). --quick: small sizes, written to
bench/out/scale/results-quick/ (a smoke test of the script).

  bench/scale_study.py [--sweeps triangles,instances,spheres,hotmesh,threads] [--quick]
  bench/scale_study.py --kiln build/kiln --kiln-commit abc1234 --machine-note "..."
"""
import argparse
import csv
import math
import os
import re
import shlex
import statistics
import subprocess
import sys
import tempfile
import threading
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import scale_scenes  # noqa: E402
import scale_svg  # noqa: E402
from pairbench import GNU_TIME, kiln_phases, machine_lock  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BENCH = os.path.join(ROOT, "bench")
OBJECT_TRIANGLES = 10000  # the instanced object
FIELDS = ["sweep", "scene", "x", "triangles", "emitters", "threads", "cores", "rep", "width",
          "height",
          "spp", "paths", "load_s", "render_s", "wall_s", "cpu_s", "peak_mb", "bvh_mb",
          "scene_mb", "ns_per_path", "loadavg1", "status"]


def log(msg):
    print(f"scale_study: {msg}", file=sys.stderr, flush=True)


def stat(text, label):
    m = re.search(rf"^\s*{re.escape(label)}\s+([0-9.]+)", text, re.M)
    return float(m.group(1)) if m else float("nan")


def run_kiln(args, scene, threads, spp, pin=False):
    """One kiln run under the lock, killed after args.timeout s. Returns a dict of measures;
    status 'ok', 'timeout' or 'failed (code)'. pin: run on cores 0..threads-1 only (taskset),
    since --threads limits the render loop but not loading (Embree's BVH build and TBB loops
    at load use every core the process may run on)."""
    cores = threads if pin and threads < (os.cpu_count() or 1) else 0
    prefix = ["taskset", "-c", f"0-{cores - 1}"] if cores else []
    cmd = prefix + [GNU_TIME, "-f", "%M", "-o", None, args.kiln, os.path.basename(scene), "--spp",
           str(spp), "--seed", "1", "--threads", str(threads), "--stats", "--quiet",
           "-o", "out.exr"]
    with tempfile.TemporaryFile() as out, tempfile.NamedTemporaryFile("r") as peak:
        cmd[len(prefix) + 4] = peak.name
        with machine_lock():
            load1 = os.getloadavg()[0]
            t0 = time.perf_counter()
            proc = subprocess.Popen(cmd, cwd=os.path.dirname(scene), stdout=out,
                                    stderr=subprocess.STDOUT)
            timer = threading.Timer(args.timeout, proc.kill)
            timer.start()
            _, status, usage = os.wait4(proc.pid, 0)
            timer.cancel()
            wall = time.perf_counter() - t0
        code = os.waitstatus_to_exitcode(status)
        out.seek(0)
        text = out.read().decode(errors="replace")
        peak_kb = peak.read().split()
    r = dict(cores=cores or os.cpu_count(), wall_s=wall,
             cpu_s=usage.ru_utime + usage.ru_stime, loadavg1=load1,
             peak_mb=float(peak_kb[-1]) / 1024.0 if peak_kb and code == 0 else float("nan"))
    if code != 0:
        r["status"] = "timeout" if wall >= args.timeout else f"failed ({code})"
        log(f"{os.path.basename(scene)}: {r['status']} after {wall:.1f} s: {text[-500:]}")
        return r
    load, render = kiln_phases(text)
    paths = stat(text, "Camera paths")
    r.update(status="ok", load_s=load, render_s=render, paths=paths,
             bvh_mb=stat(text, "Embree BVH peak"),
             scene_mb=stat(text, "Committed to the scene (estimated)"),
             ns_per_path=render / paths * 1e9 if paths else float("nan"))
    return r


def memory_available_mb():
    with open("/proc/meminfo") as f:
        for line in f:
            if line.startswith("MemAvailable:"):
                return int(line.split()[1]) / 1024.0
    return float("nan")


def sweep(args, name, xs, make, configs=((1, False),), reps=None, spp=None):
    """Runs make(x) for each x (ascending) with each (threads, pinned) configuration; returns
    the rows and notes."""
    spp = spp or args.spp
    rows, notes = [], []
    last = None  # (x, peak MB) of the last size that ran
    for x in xs:
        if last and last[1] == last[1]:
            predicted = last[1] * x / last[0]
            avail = memory_available_mb()
            if predicted > args.memory_fraction * avail:
                notes.append(f"{name}: stopped before {x:g}: peak memory extrapolated from "
                             f"{last[0]:g} ({last[1]:.0f} MB) to {predicted:.0f} MB, more than "
                             f"{args.memory_fraction:.0%} of the {avail:.0f} MB available")
                break
        t0 = time.perf_counter()
        scene = make(x)
        log(f"{name} {x:g}: scene written in {time.perf_counter() - t0:.1f} s")
        stop = False
        n = reps or args.reps
        for rep in range(n):  # thread counts interleaved: each sees the same machine
            for threads, pin in configs:
                r = run_kiln(args, scene, threads, spp, pin)
                row = dict(sweep=name, scene=os.path.basename(scene), x=x, threads=threads,
                           rep=rep, width=args.width, height=args.height, spp=spp, **r)
                rows.append(row)
                log(f"{name} {x:g} t{threads} c{r['cores']} rep {rep}: {r['status']} load "
                    f"{r.get('load_s', float('nan')):.3f} s render "
                    f"{r.get('render_s', float('nan')):.3f} s peak {r['peak_mb']:.0f} MB "
                    f"(wall {r['wall_s']:.1f} s, load avg {r['loadavg1']:.2f})")
                if r["status"] != "ok":
                    notes.append(f"{name}: stopped at {x:g}: {r['status']} (limit "
                                 f"{args.timeout:.0f} s per run under the shared lock)")
                    stop = True
                    break
            if stop or r["wall_s"] > args.one_rep_above:
                break  # long runs once: the lock is shared
        if stop:
            break
        last = (x, max(r["peak_mb"] for r in rows if r["x"] == x))
    return rows, notes


def med(rows, key):
    v = [r[key] for r in rows if r.get(key) == r.get(key) and key in r]
    return statistics.median(v) if v else float("nan")


def medians(rows, threads=1):
    """{x: {key: median}} over the ok runs at `threads`."""
    out = {}
    for x in sorted({r["x"] for r in rows}):
        sel = [r for r in rows if r["x"] == x and r["threads"] == threads and r["status"] == "ok"]
        if sel:
            out[x] = {k: med(sel, k) for k in ("load_s", "render_s", "peak_mb", "bvh_mb",
                                               "scene_mb", "ns_per_path", "cpu_s", "wall_s")}
    return out


def load_line(rows):
    v = [r["loadavg1"] for r in rows if r.get("loadavg1") == r.get("loadavg1")]
    return (f"Machine: 1-minute load average before each run {min(v):.2f} to {max(v):.2f} "
            f"({len(rows)} runs)." if v else "")


def slope(points):
    """Least-squares slope of log y against log x."""
    pts = [(math.log(x), math.log(y)) for x, y in points if x > 0 and y == y and y > 0]
    if len(pts) < 2:
        return float("nan")
    mx = sum(p[0] for p in pts) / len(pts)
    my = sum(p[1] for p in pts) / len(pts)
    sxx = sum((p[0] - mx) ** 2 for p in pts)
    return sum((p[0] - mx) * (p[1] - my) for p in pts) / sxx if sxx else float("nan")


INTS = ("x", "triangles", "emitters", "threads", "cores", "rep", "width", "height", "spp")


def read_csv(args, name):
    path = os.path.join(args.results, f"{name}.csv")
    if not os.path.exists(path):
        return []
    rows = []
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            out = {}
            for k, v in row.items():
                if k in ("sweep", "scene", "status") or v == "":
                    out[k] = v if v != "" or k in ("sweep", "scene", "status") else float("nan")
                else:
                    out[k] = int(float(v)) if k in INTS else float(v)
            rows.append(out)
    return rows


def write_csv(args, name, rows):
    with open(os.path.join(args.results, f"{name}.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=FIELDS, extrasaction="ignore")
        w.writeheader()
        for row in rows:
            w.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v) for k, v in row.items()})


def size_table(name, xlabel, m, fit_from, unit):
    """Markdown table of medians, the exponents fitted from x >= fit_from and marginal costs."""
    lines = [f"| {xlabel} | load s | render s | ns/path | peak MB | Embree BVH MB | "
             "scene MB (est.) |", "|---|---|---|---|---|---|---|"]
    for x, v in m.items():
        lines.append(f"| {x:.0e} | {v['load_s']:.3f} | {v['render_s']:.3f} | "
                     f"{v['ns_per_path']:.0f} | {v['peak_mb']:.0f} | {v['bvh_mb']:.1f} | "
                     f"{v['scene_mb']:.1f} |")
    big = {x: v for x, v in m.items() if x >= fit_from}
    xs = sorted(m)
    base = m[xs[0]]["peak_mb"]  # the smallest scene's peak: executable, film, tables
    fits = {k: slope([(x, v[k]) for x, v in big.items()]) for k in ("load_s", "ns_per_path")}
    fits["peak_mb"] = slope([(x, v["peak_mb"] - base) for x, v in big.items() if x > xs[0]])
    per = {}
    if len(xs) >= 2:
        lo, hi = xs[-2], xs[-1]  # marginal costs between the two largest sizes
        per["load_ns"] = (m[hi]["load_s"] - m[lo]["load_s"]) / (hi - lo) * 1e9
        per["peak_b"] = (m[hi]["peak_mb"] - m[lo]["peak_mb"]) / (hi - lo) * 1048576
        per["render_ratio"] = m[hi]["ns_per_path"] / m[xs[0]]["ns_per_path"]
    lines += ["", f"Fitted exponents (log-log least squares, {xlabel} >= {fit_from:.0e}): "
              f"load ~ x^{fits['load_s']:.2f}, render time per path ~ "
              f"x^{fits['ns_per_path']:.2f}, peak RSS above the smallest scene's "
              f"({base:.0f} MB) ~ x^{fits['peak_mb']:.2f}."]
    if per:
        lines.append(f"Marginal costs from {lo:.0e} to {hi:.0e}: load {per['load_ns']:.0f} ns "
                     f"and peak memory {per['peak_b']:.0f} bytes per {unit}; time per path "
                     f"x{per['render_ratio']:.2f} from {xs[0]:.0e} to {hi:.0e}.")
    return lines, fits, per


def plot_sizes(args, name, title, xlabel, m):
    pts = lambda k: [(x, v[k]) for x, v in m.items()]  # noqa: E731
    scale_svg.plot(os.path.join(args.results, f"{name}.svg"), title, [
        {"title": "load (parse + build)", "xlabel": xlabel, "ylabel": "seconds",
         "series": [{"label": "load s", "points": pts("load_s")}]},
        {"title": "render time per camera path", "xlabel": xlabel, "ylabel": "ns per path",
         "series": [{"label": "1 thread", "points": pts("ns_per_path")}]},
        {"title": "memory", "xlabel": xlabel, "ylabel": "MB",
         "series": [{"label": "peak RSS", "points": pts("peak_mb")},
                    {"label": "Embree BVH peak", "points": pts("bvh_mb")},
                    {"label": "scene (estimate)", "points": pts("scene_mb")}]}])


def thread_analysis(args, rows):
    """Per scene and (threads, cores): the fastest run's phases. Render speed-up against
    --threads 1 (loading on all cores; the render loop is what --threads sets), load speed-up
    against the run pinned to 1 core. Amdahl's serial fractions from the most threads, and the
    64-core projection."""
    lines = ["Fastest run of each configuration (render: fastest (median, runs)); "
             "cores = the cores the process could run on.", "",
             "| scene | threads | cores | load s | render s | CPU s | Mpaths/s | "
             "render speed-up | render efficiency | load speed-up (vs 1 core) | peak MB |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    proj = ["| scene | Mpaths/s per thread | serial fraction render / load (Amdahl) | "
            "projected Mpaths/s on 64 cores | 64 x per-thread (ideal) | load s on 1 core -> "
            "projected on 64 | projected peak MB |", "|---|---|---|---|---|---|---|"]
    for scene in sorted({r["scene"] for r in rows}):
        by = {}
        for key in sorted({(r["threads"], r.get("cores", 0)) for r in rows
                           if r["scene"] == scene}):
            sel = [r for r in rows if r["scene"] == scene and r["status"] == "ok"
                   and (r["threads"], r.get("cores", 0)) == key]
            if sel:
                # the fastest run: the one least disturbed by other work on the machine
                by[key] = {k: min(r[k] for r in sel) for k in ("load_s", "render_s", "cpu_s")}
                by[key].update(peak_mb=med(sel, "peak_mb"), paths=med(sel, "paths"),
                               render_med=med(sel, "render_s"), runs=len(sel))
        tmax = max(t for t, _ in by)
        all_cores = max(c for _, c in by)
        b = by.get((1, all_cores))
        b1 = by.get((1, 1), b)  # pinned to one core: the load baseline
        if not b:
            continue
        for (t, c), v in by.items():
            s_r = b["render_s"] / v["render_s"]
            s_l = b1["load_s"] / v["load_s"]
            lines.append(f"| {scene} | {t} | {c} | {v['load_s']:.3f} | {v['render_s']:.3f} "
                         f"({v['render_med']:.3f}, {v['runs']}) | {v['cpu_s']:.2f} | "
                         f"{v['paths'] / v['render_s'] / 1e6:.3f} | {s_r:.2f} | {s_r / t:.2f} "
                         f"| {s_l:.2f} | {v['peak_mb']:.0f} |")
        if tmax < 2:
            continue
        v = by[(tmax, all_cores)]

        def amdahl(speedup):  # serial fraction s from S(t) = 1 / (s + (1 - s) / t)
            return min(1.0, max(0.0, (tmax / speedup - 1) / (tmax - 1)))

        def s64(serial):
            return 1 / (serial + (1 - serial) / 64)

        s_render = amdahl(b["render_s"] / v["render_s"])
        s_med = amdahl(b["render_med"] / v["render_med"])
        s_load = amdahl(b1["load_s"] / v["load_s"])
        per_thread = b["paths"] / b["render_s"] / 1e6
        mem_per_thread = (v["peak_mb"] - b["peak_mb"]) / (tmax - 1)
        proj.append(f"| {scene} | {per_thread:.3f} | {s_render:.3f} / {s_load:.2f} | "
                    f"{per_thread * s64(s_render):.1f} (speed-up {s64(s_render):.1f}; "
                    f"{s64(s_med):.1f} from the medians) | {per_thread * 64:.1f} | "
                    f"{b1['load_s']:.2f} -> {b1['load_s'] / s64(s_load):.2f} | "
                    f"{b['peak_mb'] + 63 * mem_per_thread:.0f} "
                    f"({mem_per_thread:+.1f} MB per thread) |")
    return lines, proj


def main():
    build = os.environ.get("KILN_BUILD_DIR", os.path.join(ROOT, "build"))
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--kiln", default=os.path.join(build, "kiln"))
    p.add_argument("--kiln-commit", default="", help="the commit the kiln binary was built from")
    p.add_argument("--sweeps", default="triangles,instances,spheres,hotmesh,threads")
    p.add_argument("--quick", action="store_true", help="small sizes only (a smoke test)")
    p.add_argument("--width", type=int, default=128)
    p.add_argument("--height", type=int, default=128)
    p.add_argument("--spp", type=int, default=16)
    p.add_argument("--reps", type=int, default=3, help="repetitions of runs under "
                   "--one-rep-above seconds")
    p.add_argument("--threads-spp", type=int, default=64, help="spp of the thread sweep")
    p.add_argument("--thread-reps", type=int, default=5)
    p.add_argument("--one-rep-above", type=float, default=10.0)
    p.add_argument("--timeout", type=float, default=90.0)
    p.add_argument("--memory-fraction", type=float, default=0.7)
    p.add_argument("--max-triangles", type=float, default=5e7)
    p.add_argument("--max-instances", type=float, default=1e5)
    p.add_argument("--max-emitters", type=float, default=1e6)
    p.add_argument("--out", default=os.path.join(BENCH, "out", "scale"))
    p.add_argument("--results", default=os.path.join(BENCH, "results", "scale"))
    p.add_argument("--machine-note", default="")
    args = p.parse_args()
    args.kiln = os.path.abspath(args.kiln)
    if args.quick:
        args.max_triangles, args.max_instances, args.max_emitters = 1e5, 100, 1e3
        args.results = os.path.join(args.out, "results-quick")
    os.makedirs(args.results, exist_ok=True)
    wanted = args.sweeps.split(",")
    load_start = os.getloadavg()
    t_start = time.time()
    W, H, S = args.width, args.height, args.spp
    decades = lambda lo, hi: [int(10 ** e) for e in range(lo, 10) if 10 ** e <= hi]  # noqa

    md = ["# kiln scale study (bench/scale_study.py)", "",
          f"Command: `bench/scale_study.py {shlex.join(sys.argv[1:])}`  ",
          f"kiln: {args.kiln} ({args.kiln_commit or 'commit not given'})  ",
          f"Machine: {os.cpu_count()} cores, {memory_available_mb() / 1024:.1f} GB available at "
          f"the start, shared with other agents; load average (1, 5, 15 min) "
          f"{load_start[0]:.2f} {load_start[1]:.2f} {load_start[2]:.2f} at the start. "
          f"{args.machine_note}  ",
          f"Renders: {W}x{H}, {S} spp, path integrator (maxdepth 5), seed 1; --threads 1 unless "
          f"stated (the render loop on 1 thread; loading, which --threads does not limit, on "
          f"all {os.cpu_count()} cores); medians of up to {args.reps} runs (one run when a run "
          f"took over "
          f"{args.one_rep_above:.0f} s). Each run holds the shared lock; limit "
          f"{args.timeout:.0f} s per run.", ""]
    notes = []
    outs = os.path.join(args.out, "scenes")

    def run_or_read(name, run):
        """The sweep's rows: run now if wanted (CSV written), else read from its CSV."""
        if name in wanted:
            rows, n = run()
            notes.extend(n)
            write_csv(args, name, rows)
            return rows
        rows = read_csv(args, name)
        if rows:
            notes.append(f"{name}: read from {name}.csv (an earlier run of this script)")
        return rows

    def sizes(name, xs, make, unit_name, title, header, fit_from, extra=None):
        def run():
            rows, n = sweep(args, name, xs, make)
            for r in rows:
                r.update(extra(r["x"]) if extra else {})
            return rows, n
        rows = run_or_read(name, run)
        if not rows:
            return []
        m = medians(rows)
        plot_sizes(args, name, title, unit_name + "s", m)
        t, _, _ = size_table(name, unit_name + "s", m, fit_from, unit_name)
        return header + [f"![{name}]({name}.svg)", ""] + t + [load_line(rows), ""]

    md += sizes("triangles", decades(3, args.max_triangles)
                + ([int(5e7)] if args.max_triangles >= 5e7 else []),
                lambda x: scale_scenes.mesh_scene(os.path.join(outs, "mesh"), x, W, H, S),
                "triangle", "one mesh of N triangles (binary PLY), 1 thread",
                ["## Triangles: one mesh", ""], 1e5, lambda x: {"triangles": x})
    md += sizes("instances", decades(0, args.max_instances),
                lambda x: scale_scenes.instance_scene(os.path.join(outs, "instances"), x,
                                                      OBJECT_TRIANGLES, W, H, S),
                "instance", f"one {OBJECT_TRIANGLES}-triangle object instanced K times, "
                "1 thread", ["## Instanced triangles: one object, K instances", "",
                             f"K instances of a {OBJECT_TRIANGLES}-triangle height field = "
                             f"K x {OBJECT_TRIANGLES} triangles.", ""], 1e2,
                lambda x: {"triangles": x * OBJECT_TRIANGLES})
    md += sizes("spheres", decades(0, args.max_emitters),
                lambda x: scale_scenes.sphere_emitter_scene(os.path.join(outs, "spheres"), x,
                                                            W, H, S),
                "hot sphere", "K hot spheres (800-1600 K) over a floor, 1 thread",
                ["## Hot emitters: K small hot spheres", ""], 1e2, lambda x: {"emitters": x})
    md += sizes("hotmesh", decades(1, args.max_emitters),
                lambda x: scale_scenes.hot_mesh_scene(os.path.join(outs, "mesh"), x, W, H, S),
                "hot triangle", "a mesh of N hot triangles (one light each), 1 thread",
                ["## Hot emitters: one mesh of N hot triangles", ""], 1e3,
                lambda x: {"emitters": x, "triangles": x})

    threads = list(range(1, (os.cpu_count() or 1) + 1))

    def run_threads():
        cases = [lambda: scale_scenes.mesh_scene(os.path.join(outs, "mesh"),
                                                 int(min(1e7, args.max_triangles)), W, H, S),
                 lambda: scale_scenes.sphere_emitter_scene(os.path.join(outs, "spheres"),
                                                           int(min(1e5, args.max_emitters)),
                                                           W, H, S)]
        rows, n = [], []
        for make in cases:
            configs = [(1, False), (1, True)] + [(t, False) for t in threads[1:]]
            r, nn = sweep(args, "threads", [1], lambda _x, make=make: make(), configs,
                          reps=args.thread_reps, spp=args.threads_spp)
            rows += r
            n += nn
        return rows, n

    rows = run_or_read("threads", run_threads)
    if rows:
        t, proj = thread_analysis(args, rows)
        threads = sorted({r["threads"] for r in rows})
        series = []
        for scene in sorted({r["scene"] for r in rows}):
            pts = []
            for th in threads:
                sel = [r for r in rows if r["scene"] == scene and r["threads"] == th
                       and r["status"] == "ok" and r.get("cores") in (None, os.cpu_count())]
                if sel:
                    pts.append((th, med(sel, "paths") / min(r["render_s"] for r in sel) / 1e6))
            if len(pts) >= 2:  # measured, and extended to 64 threads: ideal and Amdahl
                t2, p2 = pts[-1]
                serial = min(1.0, max(0.0, (t2 * pts[0][1] / p2 - 1) / (t2 - 1)))
                ahead = [1, 2, 4, 8, 16, 32, 64]
                name = scene.replace(".pbrt", "")
                series.append({"label": f"{name} measured", "points": pts})
                series.append({"label": f"{name} ideal", "dash": True,
                               "points": [(th, pts[0][1] * th) for th in ahead]})
                series.append({"label": f"{name} Amdahl s={serial:.3f}", "dash": True,
                               "points": [(th, pts[0][1] / (serial + (1 - serial) / th))
                                          for th in ahead]})
        scale_svg.plot(os.path.join(args.results, "threads.svg"),
                       "render throughput against threads: measured (fastest run) and projected", [
                           {"title": "camera paths per second", "xlabel": "threads",
                            "ylabel": "Mpaths/s", "series": series}])
        spp_t = rows[0]["spp"]
        md += ["## Threads", "", f"{W}x{H} at {spp_t} spp, runs of 1 and 2 threads "
               "interleaved with a --threads 1 run pinned to one core (taskset -c 0), since "
               "--threads does not limit loading.", "", "![threads](threads.svg)", ""] + t + [
            "", load_line(rows), "", "### Projection to a 64-core node", "",
            "Model: render throughput = measured 1-thread throughput x Amdahl speed-up at 64 "
            "threads, the serial fraction solved from the measured speed-up at the largest "
            "thread count here; load the same way, its serial fraction from the run pinned to "
            "one core "
            "against the run on all cores; peak memory = 1-thread peak + 63 x the measured "
            "memory per extra thread. See bench/README.md for the limits of this model.", ""]
        md += proj + [""]

    md += ["## Notes", ""] + [f"- {n}" for n in notes] + [
        f"- Load average at the end: {' '.join(f'{v:.2f}' for v in os.getloadavg())}; "
        f"the study took {(time.time() - t_start) / 60:.1f} min."]
    with open(os.path.join(args.results, "summary.md" if not args.quick else "summary.md"),
              "w") as f:
        f.write("\n".join(md) + "\n")
    print("\n".join(md))
    return 0


if __name__ == "__main__":
    sys.exit(main())
