"""Log-log line plots as SVG, Python's standard library only (bench/scale_study.py).

plot(path, title, panels): panels is a list of dicts, one panel each, side by side:
  {"title": str, "xlabel": str, "ylabel": str,
   "series": [{"label": str, "points": [(x, y), ...], "dash": bool}, ...]}
Points with x or y <= 0 or NaN are left out; both axes are logarithmic, with ticks at powers
of ten.
"""
import math

COLOURS = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"]
PW, PH = 330, 260  # one panel
ML, MR, MT, MB = 62, 12, 30, 44  # margins inside a panel


def _valid(points):
    return [(x, y) for x, y in points if x == x and y == y and x > 0 and y > 0]


def _range(values):
    lo, hi = math.log10(min(values)), math.log10(max(values))
    lo, hi = math.floor(lo), math.ceil(hi)
    if hi - lo < 1:
        hi = lo + 1
    return lo, hi


def _panel(ox, panel):
    out = []
    series = [dict(s, points=_valid(s["points"])) for s in panel["series"]]
    series = [s for s in series if s["points"]]
    if not series:
        return out
    xs = [p[0] for s in series for p in s["points"]]
    ys = [p[1] for s in series for p in s["points"]]
    x0, x1 = _range(xs)
    y0, y1 = _range(ys)
    w, h = PW - ML - MR, PH - MT - MB

    def X(x):
        return ox + ML + (math.log10(x) - x0) / (x1 - x0) * w

    def Y(y):
        return MT + h - (math.log10(y) - y0) / (y1 - y0) * h

    out.append(f'<rect x="{ox + ML}" y="{MT}" width="{w}" height="{h}" fill="none" '
               'stroke="#444"/>')
    out.append(f'<text x="{ox + ML + w / 2}" y="{MT - 10}" text-anchor="middle" '
               f'font-weight="bold">{panel["title"]}</text>')
    xstep = max(1, (x1 - x0 + 5) // 6)
    for e in range(x0, x1 + 1, xstep):
        x = X(10.0 ** e)
        out.append(f'<line x1="{x:.1f}" y1="{MT}" x2="{x:.1f}" y2="{MT + h}" stroke="#ddd"/>')
        out.append(f'<text x="{x:.1f}" y="{MT + h + 14}" text-anchor="middle">1e{e}</text>')
    ystep = max(1, (y1 - y0 + 5) // 6)
    for e in range(y0, y1 + 1, ystep):
        y = Y(10.0 ** e)
        out.append(f'<line x1="{ox + ML}" y1="{y:.1f}" x2="{ox + ML + w}" y2="{y:.1f}" '
                   'stroke="#ddd"/>')
        out.append(f'<text x="{ox + ML - 4}" y="{y + 4:.1f}" text-anchor="end">1e{e}</text>')
    out.append(f'<text x="{ox + ML + w / 2}" y="{PH - 8}" text-anchor="middle">'
               f'{panel["xlabel"]}</text>')
    out.append(f'<text transform="translate({ox + 14},{MT + h / 2}) rotate(-90)" '
               f'text-anchor="middle">{panel["ylabel"]}</text>')
    for k, s in enumerate(series):
        colour = COLOURS[k % len(COLOURS)]
        pts = sorted(s["points"])
        path = " ".join(f"{X(x):.1f},{Y(y):.1f}" for x, y in pts)
        dash = ' stroke-dasharray="5,4"' if s.get("dash") else ""
        out.append(f'<polyline points="{path}" fill="none" stroke="{colour}" '
                   f'stroke-width="1.6"{dash}/>')
        if not s.get("dash"):
            for x, y in pts:
                out.append(f'<circle cx="{X(x):.1f}" cy="{Y(y):.1f}" r="2.6" fill="{colour}"/>')
        ly = MT + 12 + 13 * k
        out.append(f'<line x1="{ox + ML + 6}" y1="{ly - 4}" x2="{ox + ML + 22}" y2="{ly - 4}" '
                   f'stroke="{colour}" stroke-width="2"{dash}/>')
        out.append(f'<text x="{ox + ML + 26}" y="{ly}">{s["label"]}</text>')
    return out


def plot(path, title, panels):
    width = PW * len(panels)
    height = PH + 24
    body = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
            f'viewBox="0 0 {width} {height}" font-family="sans-serif" font-size="11">',
            f'<rect width="{width}" height="{height}" fill="white"/>',
            f'<text x="{width / 2}" y="16" text-anchor="middle" font-size="13">{title}</text>',
            '<g transform="translate(0,20)">']
    for k, panel in enumerate(panels):
        body += _panel(k * PW, panel)
    body += ["</g>", "</svg>"]
    with open(path, "w") as f:
        f.write("\n".join(body) + "\n")
