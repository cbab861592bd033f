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

# The plot: one panel per data set, x = log10(ns per query), y = errors.
width, height, margin = 720, 300, 60
sets = sorted({r["data"] for r in rows})
panel_w = (width - margin) / len(sets)
colours = {"exact": "#1b7837", "parity": "#2166ac", "double": "#b2182b",
           "cubic": "#e08214", "rational": "#762a83"}
svg = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
       f'font-family="sans-serif" font-size="11">',
       f'<rect width="{width}" height="{height}" fill="white"/>']
lo = math.floor(math.log10(min(r["ns_per_query"] for r in rows)))
hi = math.ceil(math.log10(max(r["ns_per_query"] for r in rows)))
for i, name in enumerate(sets):
    x0 = margin + i * panel_w
    plot_w, plot_h, top = panel_w - 30, height - 90, 30
    mine = [r for r in rows if r["data"] == name]
    max_err = max(1, max(r["false_positives"] + r["false_negatives"] for r in mine))
    svg.append(f'<text x="{x0 + plot_w / 2}" y="18" text-anchor="middle">{name}</text>')
    svg.append(f'<rect x="{x0}" y="{top}" width="{plot_w}" height="{plot_h}" fill="none" stroke="#888"/>')
    for e in range(lo, hi + 1):
        x = x0 + (e - lo) / (hi - lo) * plot_w
        svg.append(f'<text x="{x}" y="{top + plot_h + 14}" text-anchor="middle">1e{e}</text>')
    svg.append(f'<text x="{x0 + plot_w / 2}" y="{top + plot_h + 30}" text-anchor="middle">'
               f'ns per query (log)</text>')
    svg.append(f'<text x="{x0 - 6}" y="{top + 4}" text-anchor="end">{max_err}</text>')
    svg.append(f'<text x="{x0 - 6}" y="{top + plot_h}" text-anchor="end">0</text>')
    for r in mine:
        err = r["false_positives"] + r["false_negatives"]
        x = x0 + (math.log10(r["ns_per_query"]) - lo) / (hi - lo) * plot_w
        y = top + plot_h - err / max_err * plot_h
        c = colours.get(r["method"], "black")
        svg.append(f'<circle cx="{x:.1f}" cy="{y:.1f}" r="5" fill="{c}"/>')
        svg.append(f'<text x="{x + 7:.1f}" y="{y - 6:.1f}" fill="{c}">{r["method"]} ({err})</text>')
svg.append(f'<text x="14" y="{height / 2}" transform="rotate(-90 14 {height / 2})" '
           f'text-anchor="middle">false positives + false negatives</text>')
svg.append("</svg>")
open(sys.argv[2], "w").write("\n".join(svg) + "\n")
