#!/usr/bin/python3
"""Scaling charts for scripts/scaling.sh: time against triangle count and against resolution.

Each --run T:DIR is one pineda_conformance run with PINEDA_THREADS=T and LP_NUM_THREADS=T
(DIR holds its driver.csv and the runner's manifest.tsv). Writes one CSV with every point, and
two log-log charts with a linear reference slope. The printed slopes are least-squares fits of
log(time) against log(size) over the upper half of the points (the lower ones are dominated by
fixed per-frame cost or, for triangles, by the constant fill).

Needs matplotlib and numpy (Debian python3-matplotlib): run with /usr/bin/python3.
"""
import argparse
import csv
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def read_run(directory):
    desc = {}
    with open(os.path.join(directory, "manifest.tsv")) as f:
        for line in f:
            fields = line.rstrip("\n").split("\t")
            if len(fields) >= 10:
                desc[fields[0]] = fields
    points = []
    with open(os.path.join(directory, "driver.csv")) as f:
        for row in csv.DictReader(f):
            scene = row["scene"]
            if scene not in desc:
                continue
            width, height = int(row["width"]), int(row["height"])
            if scene.startswith("scale_tris_"):
                m = re.search(r"(\d+) triangles", desc[scene][9])
                kind, size = "tris", int(m.group(1)) if m else 0
            elif scene.startswith("scale_res_"):
                kind, size = "res", width * height
            else:
                continue
            points.append({"kind": kind, "scene": scene, "size": size, "width": width,
                           "height": height, "pineda_ms": float(row["pineda_ms"]),
                           "llvmpipe_ms": float(row["llvmpipe_ms"])})
    return points


def slope(xs, ys):
    """Least-squares slope of log y against log x over the upper half of the points."""
    pairs = sorted((x, y) for x, y in zip(xs, ys) if x > 0 and y > 0)
    pairs = pairs[(len(pairs) - 1) // 2:]
    if len(pairs) < 2:
        return float("nan")
    lx, ly = np.log([p[0] for p in pairs]), np.log([p[1] for p in pairs])
    return float(np.polyfit(lx, ly, 1)[0])


def end_slope(xs, ys):
    """Slope of log y against log x between the two largest sizes: the asymptotic cost."""
    pairs = sorted((x, y) for x, y in zip(xs, ys) if x > 0 and y > 0)
    if len(pairs) < 2:
        return float("nan")
    (x0, y0), (x1, y1) = pairs[-2], pairs[-1]
    return float(np.log(y1 / y0) / np.log(x1 / x0))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--run", action="append", required=True, help="THREADS:DIR")
    ap.add_argument("--honoured", type=int, default=1,
                    help="1 when the Pineda library reads PINEDA_THREADS")
    ap.add_argument("--csv", required=True)
    ap.add_argument("--png-tris", required=True)
    ap.add_argument("--png-res", required=True)
    args = ap.parse_args()

    series = []  # (impl, threads, points)
    for spec in args.run:
        threads, _, directory = spec.partition(":")
        pts = read_run(directory)
        series.append(("pineda", int(threads), pts))
        series.append(("llvmpipe", int(threads), pts))

    with open(args.csv, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["kind", "scene", "triangles", "width", "height", "pixels", "threads",
                    "pineda_threads_honoured", "pineda_ms", "llvmpipe_ms",
                    "pineda_over_llvmpipe"])
        for impl, threads, pts in series:
            if impl != "pineda":
                continue
            for p in sorted(pts, key=lambda p: (p["kind"], p["size"])):
                w.writerow([p["kind"], p["scene"], p["size"] if p["kind"] == "tris" else "",
                            p["width"], p["height"], p["width"] * p["height"], threads,
                            args.honoured, "%.4f" % p["pineda_ms"], "%.4f" % p["llvmpipe_ms"],
                            "%.3f" % (p["pineda_ms"] / p["llvmpipe_ms"])
                            if p["llvmpipe_ms"] > 0 else ""])
    print("csv: %s" % args.csv)

    def label(impl, threads):
        if impl == "llvmpipe":
            return "llvmpipe, LP_NUM_THREADS=%d" % threads
        if args.honoured:
            return "Pineda, PINEDA_THREADS=%d" % threads
        return "Pineda, PINEDA_THREADS=%d (ignored: no worker threads)" % threads

    styles = {"pineda": ("tab:blue", "o"), "llvmpipe": ("tab:red", "s")}
    for kind, png, xlabel, title in (
            ("tris", args.png_tris, "triangles",
             "Time against triangle count (same 1024x1024 area covered)"),
            ("res", args.png_res, "pixels (window size)",
             "Time against resolution (textured mesh)")):
        fig, ax = plt.subplots(figsize=(8, 6))
        ax.set_xscale("log")  # before the tick labels below, which a scale change would reset
        ax.set_yscale("log")
        print("%s: slope of log time against log %s (fit over the upper half of the points, and "
              "between the two largest)" % (kind, xlabel))
        ref_anchor = None
        for impl, threads, pts in series:
            pk = sorted((p for p in pts if p["kind"] == kind), key=lambda p: p["size"])
            if not pk:
                continue
            xs = [p["size"] for p in pk]
            ys = [p[impl + "_ms"] for p in pk]
            colour, marker = styles[impl]
            s, e = slope(xs, ys), end_slope(xs, ys)
            ax.plot(xs, ys, marker=marker, color=colour,
                    linestyle="-" if threads == 1 else "--", alpha=1.0 if threads == 1 else 0.7,
                    label="%s (slope %.2f, last step %.2f)" % (label(impl, threads), s, e))
            print("  %-58s fit %.2f  last step %.2f   ms: %s" % (
                label(impl, threads), s, e, "  ".join("%.1f" % y for y in ys)))
            if kind == "res":
                ax.set_xticks(xs, ["%dx%d" % (p["width"], p["height"]) for p in pk],
                              rotation=30, fontsize=8)
            else:
                ax.set_xticks(xs, ["%dk" % round(x / 1000) if x < 1e6 else "%.2fM" % (x / 1e6)
                                   for x in xs], fontsize=8)
            ax.minorticks_off()
            if ref_anchor is None or (impl == "pineda" and threads == 1):
                ref_anchor = (xs[-1], ys[-1], xs[0])
        if ref_anchor is not None:
            x1, y1, x0 = ref_anchor
            ax.plot([x0, x1], [y1 * x0 / x1, y1], color="0.5", linestyle=":",
                    label="linear reference (slope 1)")
        ax.set_xlabel(xlabel)
        ax.set_ylabel("frame time ms (median)")
        ax.set_title(title)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(png, dpi=110)
        print("chart: %s" % png)
    return 0


if __name__ == "__main__":
    sys.exit(main())
