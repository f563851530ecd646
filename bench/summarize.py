#!/usr/bin/python3
"""Summarize edgewise-bench JSON files: median rates per ISA and triangle area, the speedup over
the scalar reference, and the comparison with published peer figures and with the targets.

- Coverage/*: triangles/s and pixels/s, against Intel Masked Occlusion Culling and the coverage
  targets;
- Area/*: exact-area coverage (rasterize_areas()), partially covered pixels/s against the
  target (AVX2, one core) and the reference;
- Shading/*: triangles/s, covered fragments/s and written pixels/s of draw(), against the
  shading targets (AVX2, one core); Shading/<isa>/threads:all/*: the same on every core, and the
  ratio all threads / one thread per size;
- ShadingMethod/*: fragments/s per interpolation method and perspective mode, relative to the
  production method (plane equations, perspective-correct);
- Sample/*, SamplePeer/*: texture samples/s per filter, ISA and query stream, beside
  OpenImageIO's TextureSystem, against the sampling targets (AVX2, one core, ground plane);
- TexturedDraw/*: textured pixels/s of draw() on the same ground-plane view per filter, ISA and
  derivative method, beside sample()'s rate on the view's queries; their /<precision> variants,
  the bilinear taps in the precision the default does not use, beside the default;
- DrawPeer/*: Mesa's llvmpipe on the Shading/ workloads and the trilinear and anisotropic
  (max_anisotropy 16) TexturedDraw/ ones, one thread and its default threads, beside edgewise
  (the widest ISA measured): edgewise / llvmpipe;
- Multisample/* with DrawPeer/*/threads:1/area:<px>/samples:<n>: multisampled drawing (the widest
  ISA measured) against llvmpipe on one thread at the same sample count, and each side's cost of
  n samples over one (edgewise's samples:1, llvmpipe's single-sample area:<px>);
- MeshDraw/* with DrawPeer/*/mesh/*: real meshes (per-pixel diffuse, back faces culled), edgewise
  against llvmpipe per mesh on one thread and on every core, and the median ratio over the meshes.

Usage: /usr/bin/python3 bench/summarize.py FILE.json [FILE.json ...]
  e.g. bench/results/<cpu-model>/coverage.json bench/results/<cpu-model>/shading.json
"""

import json
import re
import statistics
import sys

# Intel Masked Occlusion Culling, AVX2, precise coverage, one thread, on this machine kind
# (AMD EPYC family 26 model 2, Zen 5; bench/README.md, "Against Masked Occlusion Culling").
PEER_MOC = {8: 29.7e6, 64: 22.0e6, 1000: 11.1e6, 200000: 0.384e6}
# What edgewise aims for (AVX2, one core), triangles/s.
TARGET = {8: 50e6, 64: 25e6, 1000: 8e6, 200000: 0.5e6}
# Exact-area coverage target (AVX2, one core): partially covered pixels/s.
AREA_TARGET = 300e6
# AVX2 must be at least this much faster than the reference on 1000-px triangles.
TARGET_AVX2_OVER_REFERENCE_AT_1000 = 8.0
# Shading targets (AVX2, one core): (counter, rate) per area; small triangles are bound by
# per-triangle work, large ones by per-fragment work.
SHADING_TARGET = {8: ("triangles", 15e6), 64: ("triangles", 8e6), 1000: ("fragments", 1.2e9),
                  200000: ("fragments", 4e9)}
# The reference draws the first 1/REFERENCE_SHARE of each shading set (bench/draw/draw_bench.cpp).
REFERENCE_SHARE = 16
# The production interpolation setting, which the method table is relative to.
BASELINE_METHOD = ("plane_equations", "correct")

# Sampling targets (AVX2, one core, ground-plane stream), samples/s; anisotropic or EWA at 16x.
SAMPLE_TARGET = {"bilinear": 150e6, "trilinear": 100e6, "anisotropic": 15e6, "ewa": 15e6}
# The reference samples the first 1/SAMPLE_REFERENCE_SHARE of each stream (bench/texture/sample_bench.cpp).
SAMPLE_REFERENCE_SHARE = 64
SAMPLE_FILTERS = ["nearest", "bilinear", "bicubic_catmull_rom", "bicubic_bspline", "mip_nearest",
                  "trilinear", "supersample", "ripmap", "summed_area", "anisotropic", "ewa"]
# Which OpenImageIO mode each filter is compared with.
SAMPLE_PEER = {"nearest": "closest", "bilinear": "bilinear", "bicubic_bspline": "bicubic",
               "trilinear": "trilinear", "anisotropic": "anisotropic16"}

COVERAGE_NAME = re.compile(r"^Coverage/(?P<isa>[a-z0-9_]+)/area:(?P<area>\d+)$")
AREA_NAME = re.compile(r"^Area/(?P<isa>[a-z0-9_]+)/area:(?P<area>\d+)$")
SHADING_NAME = re.compile(r"^Shading/(?P<isa>[a-z0-9_]+)/area:(?P<area>\d+)$")
ALL_THREADS_NAME = re.compile(r"^Shading/(?P<isa>[a-z0-9_]+)/threads:all/area:(?P<area>\d+)"
                              r"(/real_time)?$")
PLAIN_DEPTH_NAME = re.compile(r"^ShadingWithoutTileDepth/(?P<isa>[a-z0-9_]+)/area:(?P<area>\d+)$")
METHOD_NAME = re.compile(r"^ShadingMethod/(?P<isa>[a-z0-9_]+)/(?P<method>[a-z_]+)/"
                         r"(?P<perspective>[a-z]+)/area:(?P<area>\d+)(/min_time:[0-9.]+)?$")
SAMPLE_NAME = re.compile(r"^Sample/(?P<isa>[a-z0-9_]+)/(?P<filter>[a-z_]+)/(?P<stream>[a-z_]+)$")
DRAW_NAME = re.compile(
    r"^TexturedDraw/(?P<isa>[a-z0-9_]+)/(?P<filter>[a-z_]+)/(?P<derivatives>[a-z]+)$")
TEXTURED_ALL_NAME = re.compile(r"^TexturedDraw/(?P<isa>[a-z0-9_]+)/threads:all/(?P<filter>[a-z_]+)/"
                               r"quad/real_time$")
# The other precision of a filter's bilinear taps, run beside the default (bench/texture/bench_texture.hpp).
SAMPLE_PRECISION_NAME = re.compile(r"^Sample/(?P<isa>[a-z0-9_]+)/(?P<filter>[a-z_]+)/"
                                   r"(?P<stream>[a-z_]+)/(?P<precision>float32|fixed16)$")
DRAW_PRECISION_NAME = re.compile(r"^TexturedDraw/(?P<isa>[a-z0-9_]+)/(?P<filter>[a-z_]+)/"
                                 r"(?P<derivatives>[a-z]+)/(?P<precision>float32|fixed16)$")
PEER_NAME = re.compile(r"^SamplePeer/oiio/(?P<mode>[a-z0-9_]+)/(?P<stream>[a-z_]+)$")
DRAW_PEER_NAME = re.compile(r"^DrawPeer/(?P<peer>[a-z0-9_]+)/threads:(?P<threads>[a-z0-9]+)/"
                            r"(?P<workload>.+?)(/manual_time)?$")
MULTISAMPLE_NAME = re.compile(r"^Multisample/(?P<isa>[a-z0-9_]+)/samples:(?P<samples>\d+)/"
                              r"area:(?P<area>\d+)$")
# The drawing peer's multisampled workloads: area:<px>/samples:<n> (bench/draw/draw_peer_workloads.hpp).
PEER_MULTISAMPLE_WORKLOAD = re.compile(r"^area:(?P<area>\d+)/samples:(?P<samples>\d+)$")
RESOLVE_NAME = re.compile(r"^Resolve/(?P<isa>[a-z0-9_]+)/(?P<filter>[a-z]+)/(?P<encoding>linear|srgb)/"
                          r"threads:(?P<threads>1|all)/msaa4/1280x720(/real_time)?$")
MESH_DRAW_NAME = re.compile(r"^MeshDraw/(?P<isa>[a-z0-9_]+)/(?P<threads>threads:all/)?"
                            r"(?P<mesh>[^/]+?)(/real_time)?$")
# The drawing peer's workloads: the edgewise benchmark each repeats (bench/draw/draw_peer_workloads.hpp)
# and the rate compared, as the shading targets count it.
DRAW_PEER_WORKLOADS = {
    "area:8": ("Shading", 8, "triangles", "tri/s"),
    "area:64": ("Shading", 64, "triangles", "tri/s"),
    "area:1000": ("Shading", 1000, "fragments", "frag/s"),
    "area:200000": ("Shading", 200000, "fragments", "frag/s"),
    "ground_plane/trilinear": ("TexturedDraw", "trilinear", "items_per_second", "px/s"),
    "ground_plane/anisotropic16": ("TexturedDraw", "anisotropic", "items_per_second", "px/s"),
}
ISA_ORDER = ["reference", "sse2", "sse4_1", "avx2", "avx512", "neon"]
METHOD_ORDER = ["nearest_vertex", "inverse_distance", "subtriangle_areas", "edge_functions",
                "scanline", "plane_equations"]


def medians(benchmarks):
    """run_name -> entry holding the median (the 'median' aggregate, with the coefficient of
    variation of its time as 'cv': CPU time, or the time a /manual_time benchmark set itself; or
    the median of the iterations when the file has no aggregates), or the error it reported."""
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
                manual = name.endswith(("/manual_time", "/real_time"))  # timed in real time
                slot["cv"] = entry.get("real_time" if manual else "cpu_time")
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
            result[name]["time_unit"] = slot["runs"][0].get("time_unit", "ns")
    return result


def si(value, unit):
    for scale, prefix in ((1e9, "G"), (1e6, "M"), (1e3, "k")):
        if abs(value) >= scale:
            return f"{value / scale:.3g} {prefix}{unit}"
    return f"{value:.3g} {unit}"


def ratio(a, b):
    return f"{a / b:.3g}x" if b else "-"


def cv_cell(entry):
    return f"{100 * entry['cv']:.1f}%" if entry.get("cv") is not None else "-"


def isa_key(isa):
    return ISA_ORDER.index(isa) if isa in ISA_ORDER else len(ISA_ORDER)


def print_table(header, rows):
    widths = [max(len(r[i]) for r in [header] + rows) for i in range(len(header))]
    for row in [header, ["-" * w for w in widths]] + rows:
        print("  ".join(cell.ljust(w) for cell, w in zip(row, widths)).rstrip())


def collect(results, pattern, key):
    """{key(match): entry} for the benchmarks whose name matches `pattern`."""
    found = {}
    for name, entry in results.items():
        match = pattern.match(name)
        if match:
            found[key(match)] = entry
    return found


def print_context(path, data, results):
    context = data.get("context", {})
    repetitions = next((e["repetitions"] for e in results.values() if "repetitions" in e), 1)
    if "cpu" in context:  # bench/run records which CPU ran
        print(f"{path}: CPU {context['cpu']}")
    print(f"{path}: host {context.get('host_name', '?')}, {context.get('num_cpus', '?')} CPUs at "
          f"{context.get('mhz_per_cpu', '?')} MHz, {context.get('date', '?')}; median of "
          f"{repetitions} repetitions (CPU time; cv: their coefficient of variation); active ISA "
          f"{context.get('edgewise_active_isa', '?')}")
    return context.get("library_build_type") == "debug"


def rows_by_area(results, width, make_row):
    """A table row per (area, ISA) result, by area then ISA: make_row(area, isa, entry, the
    area's reference entry), or for a failed benchmark its error in a row `width` cells wide."""
    rows = []
    isas = sorted({isa for _, isa in results}, key=isa_key)
    for area in sorted({a for a, _ in results}):
        reference = results.get((area, "reference"), {})
        for isa in isas:
            entry = results.get((area, isa))
            if entry is None:
                continue
            if "error" in entry:
                rows.append([str(area), isa, "ERROR: " + entry["error"]] + [""] * (width - 3))
            else:
                rows.append(make_row(area, isa, entry, reference))
    return rows


def print_coverage(coverage, clear):
    print("Coverage-only rasterization (count_coverage), 1920x1080 target, one thread")
    clear_pixels = clear.get("pixels") if clear and "error" not in clear else None
    header = ["area px", "ISA", "triangles/s", "pixels/s", "cv", "vs reference", "vs MOC",
              "vs target", "of clear px/s"]

    def row(area, isa, entry, reference):
        tps, pps = entry["triangles"], entry["pixels"]
        return [
            str(area), isa, si(tps, "/s"), si(pps, "/s"), cv_cell(entry),
            ratio(tps, reference.get("triangles", 0)) if "error" not in reference else "-",
            ratio(tps, PEER_MOC.get(area, 0)),
            ratio(tps, TARGET.get(area, 0)),
            f"{100 * pps / clear_pixels:.1f}%" if clear_pixels else "-",
        ]
    print_table(header, rows_by_area(coverage, len(header), row))

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


def print_areas(areas):
    print("Exact-area coverage (rasterize_areas()), 1920x1080 target, one thread")
    header = ["area px", "ISA", "partial px/s", "pixels/s", "triangles/s", "cv", "vs reference",
              "vs target"]

    def row(area, isa, entry, reference):
        partial = entry["partial_pixels"]
        return [
            str(area), isa, si(partial, "/s"), si(entry["pixels"], "/s"),
            si(entry["triangles"], "/s"), cv_cell(entry),
            ratio(partial, reference.get("partial_pixels", 0)) if "error" not in reference else "-",
            ratio(partial, AREA_TARGET) if isa == "avx2" else "-",
        ]
    print_table(header, rows_by_area(areas, len(header), row))
    print(f"target (AVX2, one core): {si(AREA_TARGET, '')} partially covered pixels/s")


def target_text(area):
    counter, rate = SHADING_TARGET[area]
    return f"{si(rate, '')} {counter}/s"


def print_shading(shading, plain_depth):
    print("Shaded drawing (draw(): orthographic, depth less + write, Gouraud), 1920x1080 "
          "RGBA8 + float32 depth, one thread")
    header = ["area px", "ISA", "triangles/s", "fragments/s", "written/s", "cv", "vertex stage",
              "no tile depth", "vs reference", "target (AVX2)", "vs target"]
    rows = []
    isas = sorted({isa for _, isa in shading}, key=isa_key)
    for area in sorted({a for a, _ in shading}):
        reference = shading.get((area, "reference"), {})
        for isa in isas:
            entry = shading.get((area, isa))
            if entry is None:
                continue
            if "error" in entry:
                rows.append([str(area), isa, "ERROR: " + entry["error"]] + [""] * 8)
                continue
            counter, rate = SHADING_TARGET.get(area, (None, 0))
            plain = plain_depth.get((area, isa), {})
            rows.append([
                str(area), isa, si(entry["triangles"], "/s"), si(entry["fragments"], "/s"),
                si(entry["written"], "/s"), cv_cell(entry),
                f"{100 * entry['vertex_share']:.1f}%" if "vertex_share" in entry else "-",
                si(plain["fragments"], "/s") if "fragments" in plain else "-",
                ratio(entry["triangles"], reference["triangles"])
                if "triangles" in reference else "-",
                target_text(area) if counter else "-",
                ratio(entry[counter], rate) if counter else "-",
            ])
    print_table(header, rows)

    print()
    print("fragments: covered samples; written: fragments that passed the depth test; vertex "
          "stage: share of draw()'s time spent transforming, clipping and mapping vertices; "
          "no tile depth: fragments/s with hierarchical depth off (hidden tiles not skipped)")
    print(f"the reference draws the first 1/{REFERENCE_SHARE} of each set (its rates are per "
          "triangle and per fragment, so they compare; its overdraw is lower)")
    for area in sorted(SHADING_TARGET):
        entry = shading.get((area, "avx2"))
        if entry is None or "error" in entry:
            continue
        counter, rate = SHADING_TARGET[area]
        verdict = "met" if entry[counter] >= rate else "NOT met"
        print(f"AVX2 at {area} px: {si(entry[counter], '')} {counter}/s "
              f"(target >= {target_text(area)}: {verdict}, {entry[counter] / rate:.2f}x)")


def print_threads(all_threads, shading):
    print("Shaded drawing on every core (Shading/<isa>/threads:all, wall-clock time) against one "
          "thread (Shading/<isa>, CPU time)")
    header = ["area px", "ISA", "threads", "triangles/s", "fragments/s", "cv",
              "one thread", "all / one"]
    rows = []
    for area, isa in sorted(all_threads, key=lambda k: (k[0], isa_key(k[1]))):
        entry = all_threads[(area, isa)]
        if "error" in entry:
            rows.append([str(area), isa, "ERROR: " + entry["error"]] + [""] * 5)
            continue
        one = shading.get((area, isa), {})
        rows.append([
            str(area), isa, f"{entry.get('threads', 0):.0f}", si(entry["triangles"], "/s"),
            si(entry["fragments"], "/s"), cv_cell(entry),
            si(one["triangles"], "/s") if "triangles" in one else "-",
            ratio(entry["triangles"], one["triangles"]) if "triangles" in one else "-",
        ])
    print_table(header, rows)


def print_methods(methods):
    print("Interpolation methods (draw() through a perspective camera, Gouraud), covered "
          "fragments/s and the ratio to "
          f"{BASELINE_METHOD[0]}/{BASELINE_METHOD[1]} on the same ISA")
    isas = sorted({k[3] for k in methods}, key=isa_key)
    header = ["area px", "method", "perspective"] + isas
    rows = []
    methods_seen = sorted({k[1] for k in methods},
                          key=lambda m: METHOD_ORDER.index(m) if m in METHOD_ORDER else 99)
    for area in sorted({k[0] for k in methods}):
        for method in methods_seen:
            for perspective in ("correct", "affine"):
                row = [str(area), method, perspective]
                present = False
                for isa in isas:
                    entry = methods.get((area, method, perspective, isa))
                    baseline = methods.get((area, *BASELINE_METHOD, isa), {})
                    if entry is None:
                        row.append("-")
                        continue
                    present = True
                    if "error" in entry:
                        row.append("ERROR: " + entry["error"])
                    elif "fragments" in baseline:
                        row.append(f"{si(entry['fragments'], '/s')} "
                                   f"({entry['fragments'] / baseline['fragments']:.2f}x)")
                    else:
                        row.append(si(entry["fragments"], "/s"))
                if present:
                    rows.append(row)
    print_table(header, rows)
    print()
    print("the same screen triangles as Shading/ at that area, with w varying across each "
          "triangle; affine skips the perspective divide")


def psnr_cell(entry):
    """The PSNR against ground truth a benchmark reported (when the ground truth was stored)."""
    if not entry or "error" in entry or "psnr_db" not in entry:
        return "-"
    return f"{entry['psnr_db']:.1f} dB"


def print_precisions(sample_variants, samples, draw_variants, draws):
    """Each filter's other precision beside its default, sampled and drawn: rates and PSNR."""
    print("the bilinear taps in the other precision (FilterPrecision) beside the default: "
          "samples/s (Sample/) or pixels/s (TexturedDraw/, quad derivatives), one core")
    header = ["benchmark", "filter", "stream", "ISA", "default", "other", "precision",
              "other / default", "PSNR default", "PSNR other"]
    rows = []
    for kind, variants, plain in (("Sample", sample_variants, samples),
                                  ("TexturedDraw", draw_variants, draws)):
        for key in sorted(variants, key=lambda k: (k[0], k[1], ISA_ORDER.index(k[2])
                                                   if k[2] in ISA_ORDER else 99)):
            name, where, isa, precision = key
            other = variants[key]
            default = plain.get((name, where, isa)) if kind == "Sample" else \
                plain.get((name, isa, where))
            if default is None or "error" in default or "error" in other:
                continue
            a, b = default["items_per_second"], other["items_per_second"]
            rows.append([kind, name, where, isa, si(a, "/s"), si(b, "/s"), precision,
                         f"{b / a:.2f}x", psnr_cell(default), psnr_cell(other)])
    print_table(header, rows)
    print()


def print_sampling(samples, peers):
    """Samples/s per filter and ISA for each stream, the peer's rate and the targets."""
    isas = [isa for isa in ISA_ORDER if any(k[2] == isa for k in samples)]
    for stream in ("ground_plane", "magnification"):
        if not any(key[1] == stream for key in samples):
            continue
        print(f"texture sampling, {stream} stream (1920x1080 queries, 1024^2 RGBA8 checkerboard),"
              " samples/s")
        header = ["filter"] + isas + ["avx2 / reference", "OpenImageIO", "avx2 / OIIO", "target",
                                      "PSNR avx2", "PSNR OIIO"]
        rows = []
        for name in SAMPLE_FILTERS:
            row = [name]
            rates = {}
            for isa in isas:
                entry = samples.get((name, stream, isa))
                if entry is None or "error" in entry:
                    row.append("-" if entry is None else "ERROR: " + entry["error"])
                    continue
                rates[isa] = entry["items_per_second"]
                row.append(si(rates[isa], "/s"))
            fast = rates.get("avx2")
            row.append(f"{fast / rates['reference']:.1f}x" if fast and "reference" in rates
                       else "-")
            peer = peers.get((SAMPLE_PEER.get(name), stream))
            peer_rate = peer.get("items_per_second") if peer and "error" not in peer else None
            row.append(si(peer_rate, "/s") if peer_rate else "-")
            row.append(f"{fast / peer_rate:.1f}x" if fast and peer_rate else "-")
            target = SAMPLE_TARGET.get(name) if stream == "ground_plane" else None
            if target and fast:
                verdict = "met" if fast >= target else "missed"
                row.append(f"{si(target, '/s')} ({fast / target:.2f}x, {verdict})")
            else:
                row.append("-")
            row.append(psnr_cell(samples.get((name, stream, "avx2"))))
            row.append(psnr_cell(peer))
            rows.append(row)
        print_table(header, rows)
        print()
    print(f"the reference samples the first 1/{SAMPLE_REFERENCE_SHARE} of each stream; "
          "OpenImageIO's modes: closest, bilinear, bicubic (a B-spline), trilinear, "
          "anisotropic 16 (as bench/texture/sample_bench.cpp sets them)")


def print_textured_draw(draws, samples):
    """Pixels/s of textured draw() per filter, ISA and derivative method, beside sample()."""
    print("textured drawing, the ground-plane view drawn by draw() (1920x1080, 1024^2 RGBA8 "
          "checkerboard, white flat shading), pixels/s")
    columns = [(isa, d) for isa in ISA_ORDER for d in ("quad", "analytic")
               if any(k[1] == isa and k[2] == d for k in draws)]
    header = ["filter"] + [f"{isa} {d}" for isa, d in columns] + [
        "sample() avx2", "avx2 analytic / sample()", "PSNR avx2 quad", "PSNR avx2 analytic"]
    rows = []
    for name in SAMPLE_FILTERS:
        if not any(k[0] == name for k in draws):
            continue
        row = [name]
        for isa, d in columns:
            entry = draws.get((name, isa, d))
            row.append("-" if entry is None else
                       "ERROR: " + entry["error"] if "error" in entry else
                       si(entry["items_per_second"], "/s"))
        sampled = samples.get((name, "ground_plane", "avx2"), {}).get("items_per_second")
        drawn = draws.get((name, "avx2", "analytic"), {}).get("items_per_second")
        row.append(si(sampled, "/s") if sampled else "-")
        row.append(f"{drawn / sampled:.2f}x" if sampled and drawn else "-")
        row.append(psnr_cell(draws.get((name, "avx2", "quad"))))
        row.append(psnr_cell(draws.get((name, "avx2", "analytic"))))
        rows.append(row)
    print_table(header, rows)
    print("the reference draws a quarter of the screen (its scissor); draw() includes coverage, "
          "depth, texture coordinates, derivatives and the colour write")


def print_textured_threads(all_draws, draws):
    """Textured draw() on every core against one thread, and the speed-ups its schedule allows on
    16 and 64 threads (model16, model64; bench/README.md)."""
    print("textured drawing on every core (TexturedDraw/<isa>/threads:all/<filter>/quad, "
          "wall-clock time) against one thread (CPU time), pixels/s")
    header = ["filter", "ISA", "all cores", "one thread", "all / one", "model 16", "model 64"]
    rows = []
    for (name, isa), entry in sorted(all_draws.items(),
                                     key=lambda kv: (kv[0][0], ISA_ORDER.index(kv[0][1]))):
        one = draws.get((name, isa, "quad"), {}).get("items_per_second")
        rate = entry.get("items_per_second")
        rows.append([name, isa, si(rate, "/s") if rate else "-", si(one, "/s") if one else "-",
                     f"{rate / one:.2f}x" if rate and one else "-",
                     f"{entry['model16']:.3g}x" if "model16" in entry else "-",
                     f"{entry['model64']:.3g}x" if "model64" in entry else "-"])
    print_table(header, rows)


def print_draw_peers(peers, shading, draws):
    """edgewise against a drawing peer on the same work, per workload and thread setting."""
    def edgewise_entry(workload, isa):
        kind, key, _, _ = DRAW_PEER_WORKLOADS[workload]
        entry = (shading.get((key, isa)) if kind == "Shading"
                 else draws.get((key, isa, "quad")))
        return entry if entry and "error" not in entry else None

    workloads = [w for w in DRAW_PEER_WORKLOADS if any(k[1] == w for k in peers)]
    if not workloads:
        print("drawing peer: none of the Shading/ or TexturedDraw/ workloads was measured (the "
              "meshes and multisampled workloads are below)")
        return
    measured = [isa for isa in ISA_ORDER if isa != "reference" and
                any(edgewise_entry(w, isa) for w in workloads)]
    isa = measured[-1] if measured else None

    def widest_entry(workload):
        """The entry of the widest ISA measured for this workload, and that ISA."""
        for candidate in reversed(measured):
            entry = edgewise_entry(workload, candidate)
            if entry:
                return entry, candidate
        return None, None
    for peer in sorted({k[0] for k in peers}):
        print(f"drawing peer: {peer} on the same work as edgewise ({isa or 'not measured'}, one "
              "thread): median rates, and edgewise / peer (> 1: edgewise faster)")
        header = ["workload", f"edgewise {isa or '-'}", f"{peer} 1 thread", f"{peer} default",
                  "edgewise / 1 thread", "edgewise / default", "cv 1 / default",
                  "cpu/wall 1 / default", "written diff"]
        rows = []
        for workload in workloads:
            _, _, counter, unit = DRAW_PEER_WORKLOADS[workload]
            mine, mine_isa = widest_entry(workload)
            row = [workload, si(mine[counter], unit) + ("" if mine_isa == isa else f" ({mine_isa})")
                   if mine else "-"]
            ratios, cvs, utilization = [], [], []
            difference = "-"
            for threads in ("1", "default"):
                entry = peers.get((peer, workload, threads))
                if entry is None or "error" in entry:
                    row.append("-" if entry is None else "ERROR: " + entry["error"])
                    ratios.append("-")
                    cvs.append("-")
                    utilization.append("-")
                else:
                    row.append(si(entry[counter], unit))
                    ratios.append(ratio(mine[counter], entry[counter]) if mine else "-")
                    cvs.append(cv_cell(entry))
                    utilization.append(f"{entry['cpu_per_wall']:.2f}"
                                       if "cpu_per_wall" in entry else "-")
                    difference = f"{entry.get('written_difference', 0):+.0f}"
            rows.append(row + ratios + [" / ".join(cvs), " / ".join(utilization), difference])
        print_table(header, rows)
        print()
        print(f"{peer} 1 thread: LP_NUM_THREADS=0, timed in the process's CPU time as edgewise is; "
              "default: its default rasterizer threads (one per CPU), timed in wall-clock time; "
              "cpu/wall: the process's CPU time over wall-clock time (the CPUs it kept busy; "
              "below 1 when other work took them); covered samples equal edgewise's, written "
              "samples differ by 'written diff' per draw (depth rounding at near-ties)")


def seconds(entry, clock):
    """A median's time per iteration in seconds (`clock`: cpu_time, or real_time, which holds the
    peer's manual times), or None for a missing or failed benchmark."""
    if not entry or "error" in entry:
        return None
    unit = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}[entry.get("time_unit", "ns")]
    return entry[clock] * unit


def print_multisample(multisample, draw_peers):
    """Multisampled drawing: per area and sample count, edgewise's time per draw() call (the
    widest ISA measured), llvmpipe's on one thread for the same work where it has the workload,
    llvmpipe's time / edgewise's, and each side's time at n samples over its time at one."""
    isas = sorted({k[2] for k in multisample}, key=isa_key)
    isa = isas[-1] if isas else None
    peer_counts = {}  # (area, samples) -> llvmpipe's one-thread entry; samples 1: area:<px>
    for (peer, workload, threads), entry in draw_peers.items():
        match = PEER_MULTISAMPLE_WORKLOAD.match(workload)
        if peer == "llvmpipe" and threads == "1" and match:
            peer_counts[(int(match["area"]), int(match["samples"]))] = entry
    areas = sorted({k[0] for k in multisample if k[2] == isa} | {a for a, _ in peer_counts})
    print(f"multisampled drawing (Multisample/{isa}, the Shading/ workload into an n-sample "
          "target) against llvmpipe on one thread (DrawPeer/llvmpipe/threads:1/area:<px>/samples:<n>"
          "), ms per draw; llvmpipe / edgewise > 1: edgewise faster; n / 1: the time at n samples "
          "over the same side's single-sample time")
    header = ["area px", "samples", f"edgewise {isa}", "cv", "edgewise n / 1", "llvmpipe 1 thread",
              "cv", "llvmpipe n / 1", "llvmpipe / edgewise", "written diff"]
    rows = []
    for area in areas:
        mine_one = seconds(multisample.get((area, 1, isa)), "cpu_time")
        peer_one_entry = draw_peers.get(("llvmpipe", f"area:{area}", "1"))
        peer_one = seconds(peer_one_entry, "real_time")
        counts = sorted({k[1] for k in multisample if k[0] == area and k[2] == isa} |
                        {n for a, n in peer_counts if a == area} | ({1} if peer_one else set()))
        for n in counts:
            mine_entry = multisample.get((area, n, isa))
            peer_entry = peer_one_entry if n == 1 else peer_counts.get((area, n))
            mine = seconds(mine_entry, "cpu_time")
            peer = seconds(peer_entry, "real_time")
            row = [str(area), str(n)]
            if mine_entry and "error" in mine_entry:
                row += ["ERROR: " + mine_entry["error"], "", ""]
            else:
                row += [f"{mine * 1e3:.2f}" if mine else "-",
                        cv_cell(mine_entry) if mine else "-",
                        ratio(mine, mine_one) if mine and mine_one else "-"]
            if peer_entry and "error" in peer_entry:
                row += ["ERROR: " + peer_entry["error"], "", "", "", ""]
            else:
                row += [f"{peer * 1e3:.2f}" if peer else "-",
                        cv_cell(peer_entry) if peer else "-",
                        ratio(peer, peer_one) if peer and peer_one else "-",
                        ratio(peer, mine) if peer and mine else "-",
                        f"{peer_entry.get('written_difference', 0):+.0f}" if peer else "-"]
            rows.append(row)
    print_table(header, rows)
    print()
    print("edgewise: CPU time of its one thread; llvmpipe: LP_NUM_THREADS=0, the process's CPU "
          "time; neither resolves the samples. Covered samples equal edgewise's (llvmpipe's 4x "
          "positions are the standard ones in this frame); written samples differ by 'written "
          "diff' per draw (depth rounding at near-ties)")


# The mesh benchmarks' built-in scene (bench/draw/mesh_scenes.cpp), beside the OBJ meshes, and the
# prefix of their grids of copies of a mesh (EDGEWISE_BENCH_GRIDS).
BUILT_IN_SCENE = "default_scene"
GRID_SCENE = re.compile(r"^grid\d+-")


def print_meshes(meshes, draw_peers):
    """Real meshes: frame times of edgewise (one thread; every core) and llvmpipe (one thread;
    its default threads), their ratios per mesh and the median ratio over the meshes."""
    isas = sorted({k[1] for k in meshes}, key=isa_key)
    isa = isas[-1] if isas else None
    names = sorted({k[0] for k in meshes if k[1] == isa})
    print(f"real meshes (MeshDraw/{isa}: per-pixel diffuse, back faces culled, perspective, "
          "1920x1080): ms per draw() call, and llvmpipe's time / edgewise's (> 1: edgewise faster)")
    header = ["mesh", "triangles", "fragments", f"{isa} 1 thread", "llvmpipe 1 thread",
              "ratio 1", f"{isa} all cores", "llvmpipe default", "ratio all", "edgewise all / 1",
              "serial share", "serial 16 (model)", "model 16", "model 64"]
    rows, ratios_one, ratios_all, scaling = [], [], [], []
    models = {"model16": [], "model64": []}
    grids = {"all cores / 1 thread": [], "modelled 16 threads / 1 thread": [],
             "serial share": []}

    for name in names:
        one = meshes.get((name, isa, False))
        every = meshes.get((name, isa, True))
        peer_one = draw_peers.get(("llvmpipe", "mesh/" + name, "1"))
        peer_all = draw_peers.get(("llvmpipe", "mesh/" + name, "default"))
        # The peer's manual times (its own CPU or wall-clock time) are its real_time field.
        t_one, t_all = seconds(one, "cpu_time"), seconds(every, "real_time")
        p_one, p_all = seconds(peer_one, "real_time"), seconds(peer_all, "real_time")
        row = [name, si(one["triangles"] * t_one, "") if t_one else "-",
               si(one["fragments"] * t_one, "") if t_one else "-"]
        row += [f"{t_one * 1e3:.2f}" if t_one else "-", f"{p_one * 1e3:.2f}" if p_one else "-"]
        row.append(ratio(p_one, t_one) if p_one and t_one else "-")
        row += [f"{t_all * 1e3:.2f}" if t_all else "-", f"{p_all * 1e3:.2f}" if p_all else "-"]
        row.append(ratio(p_all, t_all) if p_all and t_all else "-")
        row.append(ratio(t_one, t_all) if t_one and t_all else "-")
        counters = every or {}
        for key in ("serial_share", "model_serial16"):
            row.append(f"{counters[key] * 100:.2f}%" if key in counters else "-")
        grid = GRID_SCENE.match(name) is not None
        for key, values in models.items():
            row.append(f"{counters[key]:.3g}x" if key in counters else "-")
            if key in counters and name != BUILT_IN_SCENE and not grid:
                values.append(counters[key])
        rows.append(row)
        if grid:
            if t_one and t_all:
                grids["all cores / 1 thread"].append((name, t_one / t_all))
            if "model16" in counters:
                grids["modelled 16 threads / 1 thread"].append((name, counters["model16"]))
            if "serial_share" in counters:
                grids["serial share"].append((name, counters["serial_share"]))
        # The medians are over the OBJ meshes, as the targets are: the built-in scene and the
        # grids are table rows only.
        if name == BUILT_IN_SCENE or grid:
            continue
        if p_one and t_one:
            ratios_one.append(p_one / t_one)
        if p_all and t_all:
            ratios_all.append(p_all / t_all)
        if t_one and t_all:
            scaling.append(t_one / t_all)
    print_table(header, rows)
    for label, values in (("edgewise 1 thread / llvmpipe 1 thread", ratios_one),
                          ("edgewise all cores / llvmpipe default threads", ratios_all),
                          ("edgewise all cores / edgewise 1 thread", scaling),
                          ("modelled 16 threads / 1 thread", models["model16"]),
                          ("modelled 64 threads / 1 thread", models["model64"])):
        if values:
            print(f"median over {len(values)} meshes ({BUILT_IN_SCENE} and grids apart), {label}: "
                  f"{statistics.median(values):.3g}x "
                  f"(min {min(values):.3g}x, max {max(values):.3g}x)")
    for label, values in grids.items():
        if values:
            cells = ", ".join(f"{name} {value * 100:.2f}%" if label == "serial share" else
                              f"{name} {value:.3g}x" for name, value in values)
            print(f"grids of copies of a mesh, {label}: {cells}")
    print("llvmpipe times are its DrawPeer/ medians (1 thread: CPU time; default: wall-clock); "
          "edgewise 1 thread: CPU time; all cores: wall-clock time; serial share: the calling "
          "thread's time outside the draw's tasks over the one-thread time; serial 16 (model): the "
          "same for the draw made for 16 threads, its tasks run one after the other; model 16, 64: the "
          "speed-up the draw's schedule allows on 16 and 64 threads (bench/README.md)")
    print_thread_time(meshes, isa, names)


def print_thread_time(meshes, isa, names):
    """Where the threads' time went in the all-core draws of the meshes (the profiled draws'
    shares of threads x wall-clock time), and their work over the one-thread time."""
    shares = ["share_busy", "share_waking", "share_between", "share_tail", "share_serial"]
    rows = []
    for name in names:
        counters = meshes.get((name, isa, True)) or {}
        if "share_busy" not in counters:
            continue
        row = [name] + [f"{counters[key] * 100:.1f}%" for key in shares]
        row += [f"{counters[key]:.2f}" if key in counters else "-"
                for key in ("work_ratio", "model_work_ratio")]
        phases = int(counters.get("phases", 0))
        row.append(" ".join(f"{counters.get(f'phase{p}', 0) * 100:.0f}%"
                            f"/{counters[f'phase{p}_work']:.2f}"
                            if f"phase{p}_work" in counters else
                            f"{counters.get(f'phase{p}', 0) * 100:.0f}%"
                            for p in range(1, phases + 1)))
        rows.append(row)
    if not rows:
        return
    print()
    print(f"where the threads' time went on every core (MeshDraw/{isa}/threads:all, profiled "
          "draws; shares of threads x wall-clock time)")
    print_table(["mesh", "busy", "waking", "between", "tail", "serial", "work / 1 thread",
                 "model work / 1 thread", "phases: wall share / work over model's"], rows)
    print("busy: in a task; waking: from a phase's start to the thread's first task of it (all "
          "of it without one); between: from one of its tasks to the next; tail: from its last "
          "task to the phase's end; serial: outside the phases; work: the tasks' time, all "
          "threads; model work: the same tasks one after the other (the 16-thread model's); "
          "per phase, its share of the wall-clock time and its tasks' time over the model's "
          "(bench/README.md)")


def print_resolve(resolves, read_once):
    """resolve() of a 4x 1280x720 frame: ms per call per ISA, filter, encoding and thread count,
    the speed-up over the reference, the time over the time to read the samples once, and the box
    resolve's target (at most 2 ms, and within 2x of reading the samples once)."""
    floor = seconds(read_once, "cpu_time")
    print("resolve() of a 4x multisampled 1280x720 frame (Resolve/): ms per call; "
          f"read once: the time to read its samples once ({floor * 1e3:.3f} ms)" if floor else
          "resolve() of a 4x multisampled 1280x720 frame (Resolve/): ms per call")
    header = ["filter", "encoding", "ISA", "threads", "ms", "cv", "vs reference", "/ read once"]
    rows = []
    keys = sorted(resolves, key=lambda k: (["box", "tent", "mitchell"].index(k[0])
                                           if k[0] in ("box", "tent", "mitchell") else 3,
                                           k[1], isa_key(k[2]), k[3] != "1"))
    best_box = None
    for filter_name, encoding, isa, threads in keys:
        entry = resolves[(filter_name, encoding, isa, threads)]
        if "error" in entry:
            rows.append([filter_name, encoding, isa, threads, "ERROR: " + entry["error"], "", "", ""])
            continue
        time = seconds(entry, "cpu_time" if threads == "1" else "real_time")
        reference = seconds(resolves.get((filter_name, encoding, "reference", "1")), "cpu_time")
        rows.append([filter_name, encoding, isa, threads, f"{time * 1e3:.3f}", cv_cell(entry),
                     ratio(reference, time) if reference else "-",
                     ratio(time, floor) if floor else "-"])
        if filter_name == "box" and encoding == "linear" and threads == "1" and isa != "reference":
            if best_box is None or time < best_box[1]:
                best_box = (isa, time)
    print_table(header, rows)
    if best_box:
        isa, time = best_box
        met = time <= 2e-3 and (floor is None or time <= 2 * floor)
        print(f"target, box 4x 1280x720 on one thread at most 2 ms and within 2x of read once: "
              f"{isa} {time * 1e3:.3f} ms" + (f", {time / floor:.2f}x read once" if floor else "") +
              (" -- met" if met else " -- NOT met"))
    print("one thread: CPU time; all: wall-clock time of the call on every core")


def main(argv):
    if len(argv) < 2:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    results = {}
    debug_library = False
    for path in argv[1:]:
        with open(path, encoding="utf-8") as f:
            data = json.load(f)
        file_results = medians(data.get("benchmarks", []))
        debug_library = print_context(path, data, file_results) or debug_library
        results.update(file_results)
    if debug_library:
        print("note: the Google Benchmark library itself was built as DEBUG (Debian's package); "
              "this affects the harness only, not the measured code")

    coverage = collect(results, COVERAGE_NAME, lambda m: (int(m["area"]), m["isa"]))
    areas = collect(results, AREA_NAME, lambda m: (int(m["area"]), m["isa"]))
    shading = collect(results, SHADING_NAME, lambda m: (int(m["area"]), m["isa"]))
    plain_depth = collect(results, PLAIN_DEPTH_NAME, lambda m: (int(m["area"]), m["isa"]))
    all_threads = collect(results, ALL_THREADS_NAME, lambda m: (int(m["area"]), m["isa"]))
    methods = collect(results, METHOD_NAME,
                      lambda m: (int(m["area"]), m["method"], m["perspective"], m["isa"]))
    samples = collect(results, SAMPLE_NAME, lambda m: (m["filter"], m["stream"], m["isa"]))
    peers = collect(results, PEER_NAME, lambda m: (m["mode"], m["stream"]))
    sample_variants = collect(results, SAMPLE_PRECISION_NAME,
                              lambda m: (m["filter"], m["stream"], m["isa"], m["precision"]))
    draw_variants = collect(results, DRAW_PRECISION_NAME,
                            lambda m: (m["filter"], m["derivatives"], m["isa"], m["precision"]))
    draws = collect(results, DRAW_NAME, lambda m: (m["filter"], m["isa"], m["derivatives"]))
    textured_all = collect(results, TEXTURED_ALL_NAME, lambda m: (m["filter"], m["isa"]))
    draw_peers = collect(results, DRAW_PEER_NAME,
                         lambda m: (m["peer"], m["workload"], m["threads"]))
    multisample = collect(results, MULTISAMPLE_NAME,
                          lambda m: (int(m["area"]), int(m["samples"]), m["isa"]))
    meshes = collect(results, MESH_DRAW_NAME,
                     lambda m: (m["mesh"], m["isa"], m["threads"] is not None))
    resolves = collect(results, RESOLVE_NAME,
                       lambda m: (m["filter"], m["encoding"], m["isa"], m["threads"]))
    read_once = next((e for n, e in results.items() if n.startswith("Resolve/read_samples_once/")),
                     None)
    clear = next((e for n, e in results.items() if n.startswith("Clear/")), None)
    if not (coverage or areas or shading or methods or samples or draws or draw_peers or
            multisample or meshes or resolves):
        print(f"{', '.join(argv[1:])}: no Coverage/*, Area/*, Shading/*, ShadingMethod/*, Sample/*, "
              "TexturedDraw/*, Multisample/*, Resolve/* or DrawPeer/* benchmarks", file=sys.stderr)
        return 1

    for title_printer, found, args in ((print_coverage, coverage, (coverage, clear)),
                                       (print_areas, areas, (areas,)),
                                       (print_shading, shading, (shading, plain_depth)),
                                       (print_threads, all_threads, (all_threads, shading)),
                                       (print_methods, methods, (methods,)),
                                       (print_sampling, samples, (samples, peers)),
                                       (print_textured_draw, draws, (draws, samples)),
                                       (print_precisions, sample_variants or draw_variants,
                                        (sample_variants, samples, draw_variants, draws)),
                                       (print_textured_threads, textured_all,
                                        (textured_all, draws)),
                                       (print_draw_peers, draw_peers,
                                        (draw_peers, shading, draws)),
                                       (print_multisample, multisample,
                                        (multisample, draw_peers)),
                                       (print_meshes, meshes, (meshes, draw_peers)),
                                       (print_resolve, resolves, (resolves, read_once))):
        if found:
            print()
            title_printer(*args)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
