#!/usr/bin/python3
"""Summarize an edgewise-bench JSON file: median triangles/s and pixels/s per ISA and triangle
area, the speedup over the scalar reference, and the comparison with published peer figures.

Usage: /usr/bin/python3 bench/summarize.py bench/results/<cpu-model>/coverage.json
"""

import json
import re
import statistics
import sys

# Intel Masked Occlusion Culling, AVX2, precise coverage, one thread, on this machine kind.
PEER_MOC = {8: 19e6, 64: 14e6, 1000: 4.9e6, 200000: 0.33e6}
# What edgewise aims for (AVX2, one core), triangles/s.
TARGET = {8: 50e6, 64: 25e6, 1000: 8e6, 200000: 0.5e6}
# AVX2 must be at least this much faster than the reference on 1000-px triangles.
TARGET_AVX2_OVER_REFERENCE_AT_1000 = 8.0

COVERAGE_NAME = re.compile(r"^Coverage/(?P<isa>[a-z0-9_]+)/area:(?P<area>\d+)$")
ISA_ORDER = ["reference", "sse2", "sse4_1", "avx2", "neon"]


def medians(benchmarks):
    """run_name -> entry holding the median (the 'median' aggregate, with the coefficient of
    variation of its CPU time as 'cv'; or the median of the iterations when the file has no
    aggregates), or the error it reported."""
    by_run = {}
    for entry in benchmarks:
        name = entry.get("run_name", entry["name"])
        slot = by_run.setdefault(name, {"median": None, "cv": None, "runs": [], "error": None})
        if entry.get("error_occurred"):
            slot["error"] = entry.get("error_message", "error")
        elif entry.get("run_type") == "aggregate":
            if entry.get("aggregate_name") == "median":
                slot["median"] = entry
            elif entry.get("aggregate_name") == "cv":
                slot["cv"] = entry.get("cpu_time")
        else:
            slot["runs"].append(entry)
    result = {}
    for name, slot in by_run.items():
        if slot["error"] is not None:
            result[name] = {"error": slot["error"]}
        elif slot["median"] is not None:
            result[name] = dict(slot["median"], cv=slot["cv"])
        elif slot["runs"]:
            keys = [k for k, v in slot["runs"][0].items() if isinstance(v, (int, float))]
            result[name] = {k: statistics.median(r[k] for r in slot["runs"] if k in r) for k in keys}
    return result


def si(value, unit):
    for scale, prefix in ((1e9, "G"), (1e6, "M"), (1e3, "k")):
        if abs(value) >= scale:
            return f"{value / scale:.3g} {prefix}{unit}"
    return f"{value:.3g} {unit}"


def ratio(a, b):
    return f"{a / b:.3g}x" if b else "-"


def main(argv):
    if len(argv) != 2:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    with open(argv[1], encoding="utf-8") as f:
        data = json.load(f)
    context = data.get("context", {})
    results = medians(data.get("benchmarks", []))

    coverage = {}  # (area, isa) -> entry
    for name, entry in results.items():
        match = COVERAGE_NAME.match(name)
        if match:
            coverage[(int(match["area"]), match["isa"])] = entry
    if not coverage:
        print(f"{argv[1]}: no Coverage/* benchmarks", file=sys.stderr)
        return 1

    repetitions = next((e["repetitions"] for e in results.values() if "repetitions" in e), 1)
    print("edgewise coverage-only rasterization, 1920x1080 target, one thread")
    print(f"host {context.get('host_name', '?')}, {context.get('num_cpus', '?')} CPUs at "
          f"{context.get('mhz_per_cpu', '?')} MHz, {context.get('date', '?')}")
    print(f"median of {repetitions} repetitions (CPU time; cv: their coefficient of variation); "
          f"active ISA "
          f"{context.get('edgewise_active_isa', '?')}")
    if context.get("library_build_type") == "debug":
        print("note: the Google Benchmark library itself was built as DEBUG (Debian's package); "
              "this affects the harness only, not the measured code")
    print()

    clear = next((e for n, e in results.items() if n.startswith("Clear/")), None)
    clear_pixels = clear.get("pixels") if clear and "error" not in clear else None

    header = ["area px", "ISA", "triangles/s", "pixels/s", "cv", "vs reference", "vs MOC",
              "vs target", "of clear px/s"]
    rows = []
    isas = sorted({isa for _, isa in coverage},
                  key=lambda i: ISA_ORDER.index(i) if i in ISA_ORDER else len(ISA_ORDER))
    for area in sorted({a for a, _ in coverage}):
        reference = coverage.get((area, "reference"), {})
        for isa in isas:
            entry = coverage.get((area, isa))
            if entry is None:
                continue
            if "error" in entry:
                rows.append([str(area), isa, "ERROR: " + entry["error"]] + [""] * 6)
                continue
            tps, pps = entry["triangles"], entry["pixels"]
            rows.append([
                str(area), isa, si(tps, "/s"), si(pps, "/s"),
                f"{100 * entry['cv']:.1f}%" if entry.get("cv") is not None else "-",
                ratio(tps, reference.get("triangles", 0)) if "error" not in reference else "-",
                ratio(tps, PEER_MOC.get(area, 0)),
                ratio(tps, TARGET.get(area, 0)),
                f"{100 * pps / clear_pixels:.1f}%" if clear_pixels else "-",
            ])
    widths = [max(len(r[i]) for r in [header] + rows) for i in range(len(header))]
    for row in [header, ["-" * w for w in widths]] + rows:
        print("  ".join(cell.ljust(w) for cell, w in zip(row, widths)).rstrip())

    print()
    print("peers (triangles/s): Intel Masked Occlusion Culling (AVX2, precise, 1 thread) "
          + ", ".join(f"{si(v, '')}@{a}px" for a, v in PEER_MOC.items()))
    print("targets (triangles/s, AVX2): "
          + ", ".join(f"{si(v, '')}@{a}px" for a, v in TARGET.items()))
    if clear is not None:
        if "error" in clear:
            print(f"framebuffer clear: ERROR: {clear['error']}")
        else:
            print(f"framebuffer clear (1920x1080 RGBA8 + float32 depth): "
                  f"{si(clear['bytes_per_second'], 'B/s')}, {si(clear['pixels'], 'pixels/s')}")

    avx2, ref = coverage.get((1000, "avx2")), coverage.get((1000, "reference"))
    if avx2 and ref and "error" not in avx2 and "error" not in ref:
        speedup = avx2["triangles"] / ref["triangles"]
        verdict = "met" if speedup >= TARGET_AVX2_OVER_REFERENCE_AT_1000 else "NOT met"
        print(f"AVX2 over reference at 1000 px: {speedup:.1f}x "
              f"(target >= {TARGET_AVX2_OVER_REFERENCE_AT_1000:g}x: {verdict})")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
