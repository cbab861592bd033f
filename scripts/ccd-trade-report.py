#!/usr/bin/env python3
"""Turns the JSON lines of scripts/ccd-trade.sh into the markdown trade table and an SVG
plot of time per query (log scale) against errors (false positives + false negatives).

Usage: scripts/ccd-trade-report.py trade.jsonl docs/ccd-trade.svg > table.md
Standard library only."""
import json
import math
import sys

lines = [json.loads(line) for line in open(sys.argv[1]) if line.strip()]

# Several rounds of the same method and data set: the counts are the same in every round
# (checked); each time is the fastest round's.
rows = []
for line in lines:
    same = [r for r in rows if r["data"] == line["data"] and r["method"] == line["method"]]
    if not same:
        rows.append(line)
        continue
    kept = same[0]
    for part in ("vertex_face", "edge_edge", None):
        a = kept if part is None else kept[part]
        b = line if part is None else line[part]
        for key in ("queries", "positives", "false_positives", "false_negatives", "stages"):
            if a[key] != b[key]:
                sys.exit(f"rounds disagree on {key} for {line['data']} {line['method']}")
        a["ns_per_query"] = min(a["ns_per_query"], b["ns_per_query"])

print("| data | method | type | queries | FP | FN | ns/query | decided by |")
print("|---|---|---|---:|---:|---:|---:|---|")
for r in rows:
    for name, part in (("vf", r["vertex_face"]), ("ee", r["edge_edge"]), ("all", r)):
        stages = ", ".join(f"{k} {v}" for k, v in part["stages"].items() if v)
        print(f"| {r['data']} | {r['method']} | {name} | {part['queries']} | "
              f"{part['false_positives']} | {part['false_negatives']} | "
              f"{part['ns_per_query']:.0f} | {stages} |")

# The plot: one panel per data set, x = ns per query (log), y = errors (FP + FN). Points
# carry no text (labels of nearby methods overlapped); a legend under the panels names
# the marks.
width, height = 760, 380
left, right, top, bottom, gap = 70, 20, 50, 110, 50
sets = sorted({r["data"] for r in rows})
panel_w = (width - left - right - gap * (len(sets) - 1)) / len(sets)
plot_h = height - top - bottom
colours = {"exact": "#1b7837", "parity": "#2166ac", "double": "#b2182b",
           "cubic": "#e08214", "rational": "#762a83"}
shapes = {"exact": "circle", "parity": "square", "double": "diamond", "cubic": "triangle",
          "rational": "circle"}


def marker(kind, x, y, colour, size=6):
    """An open square (so that a mark under it stays visible), or a filled shape."""
    if kind == "square":
        return (f'<rect x="{x - size:.1f}" y="{y - size:.1f}" width="{2 * size}" '
                f'height="{2 * size}" fill="none" stroke="{colour}" stroke-width="2"/>')
    if kind == "diamond":
        return (f'<polygon points="{x:.1f},{y - size:.1f} {x + size:.1f},{y:.1f} '
                f'{x:.1f},{y + size:.1f} {x - size:.1f},{y:.1f}" fill="{colour}"/>')
    if kind == "triangle":
        return (f'<polygon points="{x:.1f},{y - size:.1f} {x + size:.1f},{y + size:.1f} '
                f'{x - size:.1f},{y + size:.1f}" fill="{colour}"/>')
    return f'<circle cx="{x:.1f}" cy="{y:.1f}" r="{size * 0.8:.1f}" fill="{colour}"/>'


def error_ticks(max_err):
    """0 and at most four round steps (1, 2 or 5 times a power of ten) up to max_err."""
    scale = 10 ** math.floor(math.log10(max(max_err, 1)))
    step = next(m * scale for m in (1, 2, 5, 10) if max(max_err, 1) / (m * scale) <= 4)
    step = max(1, int(step))
    return list(range(0, step * math.ceil(max(max_err, 1) / step) + 1, step))


svg = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
       f'font-family="sans-serif" font-size="12">',
       f'<rect width="{width}" height="{height}" fill="white"/>',
       f'<text x="{width / 2}" y="20" text-anchor="middle" font-size="14" font-weight="bold">'
       f'CCD methods: time per query against wrong answers (one run)</text>']
lo = math.floor(math.log10(min(r["ns_per_query"] for r in rows)))
hi = math.ceil(math.log10(max(r["ns_per_query"] for r in rows)))
for i, name in enumerate(sets):
    x0 = left + i * (panel_w + gap)
    mine = [r for r in rows if r["data"] == name]
    ticks = error_ticks(max(r["false_positives"] + r["false_negatives"] for r in mine))
    y_max = ticks[-1]
    svg.append(f'<text x="{x0 + panel_w / 2}" y="{top - 8}" text-anchor="middle">{name}</text>')
    svg.append(f'<rect x="{x0}" y="{top}" width="{panel_w}" height="{plot_h}" fill="none" '
               f'stroke="#888"/>')
    for e in range(lo, hi + 1):
        x = x0 + (e - lo) / (hi - lo) * panel_w
        svg.append(f'<line x1="{x:.1f}" y1="{top + plot_h}" x2="{x:.1f}" y2="{top + plot_h + 4}" '
                   f'stroke="#888"/>')
        svg.append(f'<text x="{x:.1f}" y="{top + plot_h + 18}" text-anchor="middle">'
                   f'10<tspan dy="-5" font-size="9">{e}</tspan></text>')
    for t in ticks:
        y = top + plot_h - t / y_max * plot_h
        svg.append(f'<line x1="{x0 - 4}" y1="{y:.1f}" x2="{x0}" y2="{y:.1f}" stroke="#888"/>')
        svg.append(f'<text x="{x0 - 7}" y="{y + 4:.1f}" text-anchor="end">{t}</text>')
    svg.append(f'<text x="{x0 + panel_w / 2}" y="{top + plot_h + 38}" text-anchor="middle">'
               f'ns per query (log scale)</text>')
    for r in mine:
        err = r["false_positives"] + r["false_negatives"]
        x = x0 + (math.log10(r["ns_per_query"]) - lo) / (hi - lo) * panel_w
        y = top + plot_h - err / y_max * plot_h
        svg.append(marker(shapes.get(r["method"], "circle"), x, y,
                          colours.get(r["method"], "black")))
svg.append(f'<text x="18" y="{top + plot_h / 2}" transform="rotate(-90 18 {top + plot_h / 2})" '
           f'text-anchor="middle">false positives + false negatives</text>')
methods = [m for m in colours if any(r["method"] == m for r in rows)]
legend_y = height - 28
step = (width - left - right) / max(1, len(methods))
for k, m in enumerate(methods):
    x = left + k * step + 10
    svg.append(marker(shapes[m], x, legend_y - 4, colours[m]))
    svg.append(f'<text x="{x + 12}" y="{legend_y}">{m}</text>')
svg.append("</svg>")
open(sys.argv[2], "w").write("\n".join(svg) + "\n")
