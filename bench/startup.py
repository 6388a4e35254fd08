#!/usr/bin/env python3
"""Start-up cost of the kiln command: CPU time and peak memory before and around the first sample.

Each case runs RUNS times; for each run the child's own resource usage is read with os.wait4
(CPU = user + system time, peak = its maximum resident set size). Reported: the median CPU time
and the largest peak. With --baseline, an older kiln binary runs the same cases in the same run,
interleaved, and the ratios are printed.

  bench/startup.py [--kiln build/kiln] [--baseline OLD_KILN] [--runs 10] [--out FILE]

Cases (scenes/cornell-box: 400 x 400, 33 shapes, one area light):
  version        kiln --version: loading the executable and its libraries
  first-sample   one pixel at 1 spp (--pixelbounds): parse, build, one sample, write a 1-pixel EXR
  cornell-exr    the whole image at 1 spp, written as EXR
  cornell-png    the same written as PNG
  textured-px    scenes/textured-meshes (two PLY meshes, a PNG texture), one pixel at 1 spp
"""
import argparse
import os
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENE = os.path.join(ROOT, "scenes", "cornell-box", "cornell-box.pbrt")
TEXTURED = os.path.join(ROOT, "scenes", "textured-meshes", "textured-meshes.pbrt")


def cases(out_dir):
    return [
        ("version", ["--version"]),
        ("first-sample", [SCENE, "--spp", "1", "--pixelbounds", "200", "201", "200", "201",
                          "--quiet", "-o", os.path.join(out_dir, "px.exr")]),
        ("cornell-exr", [SCENE, "--spp", "1", "--quiet", "-o", os.path.join(out_dir, "c.exr")]),
        ("cornell-png", [SCENE, "--spp", "1", "--quiet", "-o", os.path.join(out_dir, "c.png")]),
        ("textured-px", [TEXTURED, "--spp", "1", "--pixelbounds", "100", "101", "100", "101",
                         "--quiet", "-o", os.path.join(out_dir, "t.exr")]),
    ]


def measure(command):
    """CPU seconds and peak resident memory (MB) of one run of command."""
    proc = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(proc.pid, 0)
    err = proc.stderr.read().decode(errors="replace")
    proc.stderr.close()
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit("failed: %s\n%s" % (" ".join(command), err))
    return usage.ru_utime + usage.ru_stime, usage.ru_maxrss / 1024.0


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--kiln", default=os.path.join(ROOT, "build", "kiln"))
    ap.add_argument("--baseline", help="an older kiln binary to compare with")
    ap.add_argument("--runs", type=int, default=10)
    ap.add_argument("--out", default=os.path.join(ROOT, "bench", "results", "startup.txt"))
    args = ap.parse_args()
    binaries = [("kiln", args.kiln)] + ([("baseline", args.baseline)] if args.baseline else [])

    lines = ["start-up cost, median CPU time (user + system) and largest peak RSS of %d runs"
             % args.runs, "%-13s %-9s %10s %10s" % ("case", "binary", "CPU ms", "peak MB")]
    results = {}
    with tempfile.TemporaryDirectory() as out_dir:
        for name, case_args in cases(out_dir):
            samples = {label: [] for label, _ in binaries}
            for _ in range(args.runs):
                for label, binary in binaries:  # interleaved: both see the same machine load
                    samples[label].append(measure([binary] + case_args))
            for label, _ in binaries:
                cpu = statistics.median(s[0] for s in samples[label]) * 1000
                peak = max(s[1] for s in samples[label])
                results[(name, label)] = (cpu, peak)
                lines.append("%-13s %-9s %10.1f %10.1f" % (name, label, cpu, peak))
            if args.baseline:
                (c, p), (bc, bp) = results[(name, "kiln")], results[(name, "baseline")]
                lines.append("%-13s %-9s %9.3fx %9.3fx" % (name, "ratio", c / bc, p / bp))
    text = "\n".join(lines)
    print(text)
    os.makedirs(os.path.dirname(args.out), exist_ok=True)
    with open(args.out, "w") as f:
        f.write(text + "\n")


if __name__ == "__main__":
    main()
