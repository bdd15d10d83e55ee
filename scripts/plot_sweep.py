#!/usr/bin/python3
"""Time against error for the sweep scenes (scripts/sweep.sh).

Reads the driver's CSV (median times), the runner's manifest (descriptions) and the PNG images
that pineda_conformance wrote under --dir, measures every variant's error against llvmpipe's
render of its family's accurate variant, and writes a CSV table and a chart.

Scene names are sweep_<family>_<variant>; descriptions "<family title>: <label>", the accurate
variant's label ending in " (accurate)". Errors are computed over RGB (the PNGs carry no alpha):
a pixel is bad when a channel differs by more than --tolerance (2, as in the conformance diff);
PSNR = 10 log10(255^2 / mean squared channel difference).

Needs matplotlib and numpy (Debian python3-matplotlib): run with /usr/bin/python3.
"""
import argparse
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

ACCURATE = " (accurate)"
PSNR_IDENTICAL = 60.0  # where identical images (infinite PSNR) are drawn


def load_png(path):
    img = mpimg.imread(path)
    if img.dtype != np.uint8:
        img = np.rint(img * 255.0)
    return img[:, :, :3].astype(np.int32)


def compare(test, ref, tolerance):
    if test.shape != ref.shape:
        return None
    d = np.abs(test - ref)
    worst = d.max(axis=2)
    mse = float((d.astype(np.float64) ** 2).mean())
    return {
        "bad_percent": 100.0 * float((worst > tolerance).mean()),
        "max_diff": int(worst.max()),
        "psnr": math.inf if mse == 0.0 else 10.0 * math.log10(255.0 * 255.0 / mse),
    }


def read_manifest(path):
    desc = {}
    with open(path) as f:
        for line in f:
            fields = line.rstrip("\n").split("\t")
            if len(fields) >= 10:
                desc[fields[0]] = fields[9]
    return desc


def read_times(path):
    times = {}
    with open(path) as f:
        for row in csv.DictReader(f):
            times[row["scene"]] = (float(row["pineda_ms"]), float(row["llvmpipe_ms"]))
    return times


def fmt_psnr(v):
    return "inf" if math.isinf(v) else "%.1f" % v


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--dir", required=True, help="pineda_conformance --out directory")
    ap.add_argument("--csv", required=True, help="table to write")
    ap.add_argument("--png", required=True, help="chart to write")
    ap.add_argument("--tolerance", type=int, default=2)
    args = ap.parse_args()

    desc = read_manifest(os.path.join(args.dir, "manifest.tsv"))
    times = read_times(os.path.join(args.dir, "driver.csv"))

    families = {}  # family -> {"title", "accurate", "variants": [(scene, label)]}
    for scene in sorted(times):
        parts = scene.split("_", 2)
        if len(parts) < 3 or parts[0] != "sweep" or scene not in desc:
            continue
        title, _, label = desc[scene].partition(": ")
        fam = families.setdefault(parts[1], {"title": title, "accurate": None, "variants": []})
        if label.endswith(ACCURATE):
            label = label[: -len(ACCURATE)]
            fam["accurate"] = scene
        fam["variants"].append((scene, label))

    rows = []
    for key, fam in families.items():
        acc = fam["accurate"]
        if acc is None:
            print("plot_sweep: family %s has no accurate variant (ran with a --filter?)" % key,
                  file=sys.stderr)
            continue
        try:
            ref = load_png(os.path.join(args.dir, acc, "llvmpipe.png"))
        except OSError as e:
            print("plot_sweep: %s" % e, file=sys.stderr)
            continue
        # The accurate variant first, then the others by Pineda's time.
        fam["variants"].sort(key=lambda v: (v[0] != acc, -times[v[0]][0]))
        for scene, label in fam["variants"]:
            pineda_ms, llvm_ms = times[scene]
            try:
                pin = load_png(os.path.join(args.dir, scene, "pineda.png"))
                llv = load_png(os.path.join(args.dir, scene, "llvmpipe.png"))
            except OSError as e:
                print("plot_sweep: %s: %s" % (scene, e), file=sys.stderr)
                continue
            vs_acc = compare(pin, ref, args.tolerance)
            same = compare(pin, llv, args.tolerance)
            llv_acc = compare(llv, ref, args.tolerance)
            if vs_acc is None or same is None or llv_acc is None:
                continue
            rows.append({
                "family": key, "title": fam["title"], "variant": label, "scene": scene,
                "shown": label + (" *" if scene == acc else ""),
                "accurate": int(scene == acc), "pineda_ms": pineda_ms, "llvmpipe_ms": llvm_ms,
                "llvmpipe_accurate_ms": times[acc][1],
                "pineda_speedup": times[acc][0] / pineda_ms if pineda_ms > 0 else 0.0,
                "bad_percent": vs_acc["bad_percent"], "psnr": vs_acc["psnr"],
                "max_diff": vs_acc["max_diff"],
                "llvmpipe_bad_percent": llv_acc["bad_percent"], "llvmpipe_psnr": llv_acc["psnr"],
                "same_variant_bad_percent": same["bad_percent"],
                "same_variant_psnr": same["psnr"],
            })
    if not rows:
        print("plot_sweep: nothing to report", file=sys.stderr)
        return 1

    cols = ["family", "variant", "scene", "accurate", "pineda_ms", "llvmpipe_ms",
            "llvmpipe_accurate_ms", "pineda_speedup", "bad_percent", "psnr", "max_diff",
            "llvmpipe_bad_percent", "llvmpipe_psnr", "same_variant_bad_percent",
            "same_variant_psnr"]
    with open(args.csv, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(cols)
        for r in rows:
            w.writerow(["%.4f" % r[c] if isinstance(r[c], float) else r[c] for c in cols])

    print("%-52s %9s %8s %8s %7s %6s | %9s %7s %7s | %8s" % (
        "variant (* = accurate)", "pineda", "speedup", "llvmpipe", "bad%", "PSNR",
        "llvm bad%", "PSNR", "llvm acc", "same bad%"))
    print("-" * 142)
    for r in rows:
        print("%-52s %7.2fms %7.2fx %6.2fms %7.3f %6s | %9.3f %7s %6.2fms | %8.3f" % (
            (r["title"] + ": " + r["shown"])[:52], r["pineda_ms"], r["pineda_speedup"],
            r["llvmpipe_ms"], r["bad_percent"], fmt_psnr(r["psnr"]), r["llvmpipe_bad_percent"],
            fmt_psnr(r["llvmpipe_psnr"]), r["llvmpipe_accurate_ms"],
            r["same_variant_bad_percent"]))
    print("(errors against llvmpipe's accurate render of the family; 'llvm' = llvmpipe's own "
          "render of the variant; 'same' = Pineda against llvmpipe, same variant)")
    print("csv: %s" % args.csv)

    fams = [k for k in families if any(r["family"] == k for r in rows)]
    fig, axes = plt.subplots(2, len(fams), figsize=(max(8.0, 5.2 * len(fams)), 8.5),
                             squeeze=False)
    for col, key in enumerate(fams):
        fr = [r for r in rows if r["family"] == key]
        for row, metric in enumerate(("bad_percent", "psnr")):
            ax = axes[row][col]
            for source, marker, colour, label in (
                    ("pineda", "o", "tab:blue", "Pineda"),
                    ("llvmpipe", "x", "0.6", "llvmpipe, same variant")):
                mkey = metric if source == "pineda" else "llvmpipe_" + metric
                xs = [r[mkey] for r in fr]
                if metric == "psnr":
                    xs = [PSNR_IDENTICAL if math.isinf(x) else min(x, PSNR_IDENTICAL) for x in xs]
                ys = [r[source + "_ms"] for r in fr]
                ax.scatter(xs, ys, marker=marker, color=colour, label=label, zorder=3)
                if source != "pineda":
                    continue
                # Staggered labels: variants of equal cost and error would print over each other.
                for i, (x, y, r) in enumerate(zip(xs, ys, fr)):
                    ax.annotate(r["shown"], (x, y), textcoords="offset points",
                                xytext=(5, 4 - 9 * (i % 3)), fontsize=7)
            ax.axhline(fr[0]["llvmpipe_accurate_ms"], color="tab:red", linestyle="--",
                       linewidth=1, label="llvmpipe, accurate variant")
            ax.set_ylim(bottom=0)
            ax.grid(True, alpha=0.3)
            if metric == "bad_percent":
                worst = max(max(r["bad_percent"], r["llvmpipe_bad_percent"]) for r in fr)
                ax.set_xscale("symlog", linthresh=0.1)
                ax.set_xlim(0, min(100.0, max(1.0, 2.0 * worst)))
                ax.set_xlabel("bad pixels %% (channel difference > %d) vs llvmpipe accurate"
                              % args.tolerance)
                ax.set_title(fr[0]["title"])
            else:
                ax.set_xlabel("PSNR dB vs llvmpipe accurate (identical at %d)"
                              % PSNR_IDENTICAL)
                lowest = min(min(r["psnr"], r["llvmpipe_psnr"]) for r in fr)
                # Better quality to the left in both rows.
                ax.set_xlim(PSNR_IDENTICAL + 2, min(PSNR_IDENTICAL - 10, lowest - 3))
            ax.set_ylabel("frame time ms (median)")
            if col == 0 and row == 0:
                ax.legend(fontsize=7, loc="lower right")
    fig.suptitle("Time against error: quality variants chosen through GL state or the shader "
                 "(* = accurate)",
                 fontsize=11)
    fig.tight_layout()
    fig.savefig(args.png, dpi=110)
    print("chart: %s" % args.png)
    return 0


if __name__ == "__main__":
    sys.exit(main())
