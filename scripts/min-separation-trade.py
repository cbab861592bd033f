#!/usr/bin/env python3
"""The minimum-separation trade: the exact method against the per-axis box test in plain
doubles, on the public CCD queries, at several separations, in one run.

    scripts/min-separation-trade.py [--exe build/bin/exactgeo] [--data DIR] [--repeat N]

For each query set and separation it runs `exactgeo ccd --min-separation D` with
`--method exact` and `--method double` (the box test), joins their per-query answers and
prints one Markdown row per set, type and separation: positives of each, the box test's
false positives and false negatives against the exact answers, and ns per query of
each (the fastest of `--repeat` passes) with their ratio. Exit code 1 when the box test
misses a pair the exact method finds (it must not: it is conservative by design).
"""

import argparse
import csv
import json
import os
import subprocess
import sys
import tempfile

SEPARATIONS = ["1e-6", "1e-4", "1e-2"]


def run(exe, method, delta, path, repeat, per_query):
    out = subprocess.run(
        [exe, "ccd", "--json", "--method", method, "--min-separation", delta,
         "--repeat", str(repeat), "--per-query", per_query, path],
        check=True, capture_output=True, text=True).stdout
    answers = {}
    with open(per_query, newline="") as f:
        for row in csv.DictReader(f):
            answers[(row["path"], row["index"])] = (row["type"], row["result"] == "1")
    return json.loads(out), answers


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--exe", default="build/bin/exactgeo")
    parser.add_argument("--data", default=os.path.join("..", "shared", "data", "ccd"),
                        help="folder holding sample-queries/ and scalable-ccd-data/")
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    missed = 0
    print("| set | type | δ | exact positives | box positives | box FP | box FN "
          "| exact ns | box ns | box / exact |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    with tempfile.TemporaryDirectory() as scratch:
        for name, folder in [("handcrafted", "sample-queries"),
                             ("simulation", "scalable-ccd-data")]:
            path = os.path.join(args.data, folder)
            for delta in SEPARATIONS:
                exact, exact_answers = run(args.exe, "exact", delta, path, args.repeat,
                                           os.path.join(scratch, "exact.csv"))
                box, box_answers = run(args.exe, "double", delta, path, args.repeat,
                                       os.path.join(scratch, "box.csv"))
                for kind, key in [("vf", "vertex_face"), ("ee", "edge_edge")]:
                    fp = fn = 0
                    for query, (qtype, truth) in exact_answers.items():
                        if qtype != kind:
                            continue
                        answer = box_answers[query][1]
                        fp += answer and not truth
                        fn += truth and not answer
                    missed += fn
                    e, b = exact[key], box[key]
                    print(f"| {name} | {kind} | {delta} | {e['positives']} | {b['positives']} "
                          f"| {fp} | {fn} | {e['ns_per_query']:.0f} | {b['ns_per_query']:.0f} "
                          f"| {b['ns_per_query'] / e['ns_per_query']:.1f} |", flush=True)
    return 1 if missed else 0


if __name__ == "__main__":
    sys.exit(main())
