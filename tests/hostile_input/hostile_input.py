#!/usr/bin/env python3
"""Hostile input for the command-line tools: files and options a careless or hostile user could
give them, each made at run time, each run under limits of time and memory.

  hostile_input.py --list
  hostile_input.py CASE --work DIR [--sanitized] [--tool NAME=PATH ...]

Every case asserts what the tools promise (tools/common/usage_error.hpp): the exit status (2 for
a mistake on the command line, 1 for an input or output that cannot be used, 0 where the input
is odd but valid), one line of the tool's own on standard error that names the input and the
reason, and nothing written to an output that failed. A case fails too when the tool takes
more than its time or memory.

Limits. Every tool has at most kCpuSeconds of CPU (and twice that of wall time) and kMaxRss of
resident memory, whatever the input: the targets for any input file of at most 1 MB. Unsanitized
tools also run under an address-space limit (RLIMIT_AS, kAddressSpace, or a case's own), so
that a runaway allocation fails inside the tool instead of taking the machine's memory.
AddressSanitizer reserves terabytes of address space for its shadow, so sanitized runs have no
RLIMIT_AS; they cap each allocation (max_allocation_size_mb) instead, have four times the CPU
time (the instrumentation's usual slowdown is 2x to 3x), and twice the resident memory (redzones
and the freed-memory quarantine). Leaks inside OpenImageIO are suppressed (lsan.supp).
"""

import argparse
import os
import re
import resource
import signal
import struct
import subprocess
import sys
import zlib

kCpuSeconds = 30
kMaxRss = 1 << 30  # bytes
kAddressSpace = 4 << 30  # bytes: the tools map ~1 GB of libraries and thread stacks
kSkipped = 77  # the exit status CMake's SKIP_RETURN_CODE names


# --- Files made at run time -----------------------------------------------------------------------

def png_chunk(kind, data):
    body = kind + data
    return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)


def png(width, height, idat, colour_type=6, depth=8):
    """A PNG with the header's claims and the given compressed data, true or not."""
    header = struct.pack(">IIBBBBB", width, height, depth, colour_type, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + png_chunk(b"IHDR", header) + png_chunk(b"IDAT", idat) +
            png_chunk(b"IEND", b""))


def valid_png(width, height):
    """An RGBA8 PNG whose data is all there (filter byte 0 and the same ramp on every row)."""
    ramp = (bytes(range(256)) * (width * 4 // 256 + 1))[: width * 4]
    rows = (b"\0" + ramp) * height
    return png(width, height, zlib.compress(rows, 9))


def write(path, data):
    with open(path, "wb") as f:
        f.write(data.encode() if isinstance(data, str) else data)
    return path


def symlink(target, path):
    os.symlink(target, path)
    return path


def fifo(path):
    os.mkfifo(path)
    return path


CUBE_OBJ = """v -1 -1 -1
v 1 -1 -1
v 1 1 -1
v -1 1 -1
v -1 -1 1
v 1 -1 1
v 1 1 1
v -1 1 1
f 1 2 3 4
f 5 8 7 6
f 1 5 6 2
f 2 6 7 3
f 3 7 8 4
f 5 1 4 8
"""


def scaled_obj(scale):
    lines = []
    for line in CUBE_OBJ.splitlines():
        if line.startswith("v "):
            lines.append("v " + " ".join(repr(float(v) * scale) for v in line.split()[1:]))
        else:
            lines.append(line)
    return "\n".join(lines) + "\n"


# --- The cases ------------------------------------------------------------------------------------
# Each returns a Case: the tool, its arguments, optional standard input, the expected status,
# the fixed strings its error line must hold (the input's name and the reason), and the outputs
# that must not exist afterwards.

class Case:
    def __init__(self, tool, args, status, message=(), stdin=None, stdout=None, absent=(),
                 present=(), printed=None, limits=None, cpu=kCpuSeconds):
        self.tool, self.args, self.status = tool, args, status
        self.message, self.stdin, self.stdout = list(message), stdin, stdout
        self.absent, self.present, self.address_space = list(absent), list(present), limits
        self.printed = printed  # a regular expression standard output must match
        self.cpu = cpu


CASES = {}


def case(function):
    CASES[function.__name__.replace("_", "-")] = function
    return function


FULL = "No space left on device"
DREW_FRAGMENTS = r"fragments passed +[1-9]"
NOT_REGULAR = "not a regular file"


# Outputs that cannot be written: a full disk (/dev/full), a missing folder, a folder, a
# read-only file. Each must fail with the path and the reason, never exit 0.

@case
def render_png_to_full_disk(d):
    out = symlink("/dev/full", f"{d}/out.png")
    return Case("edgewise-render", ["--scene", "torus", "--size", "64x48", "-o", out], 1, [out, FULL])


@case
def render_exr_to_full_disk(d):
    out = symlink("/dev/full", f"{d}/out.exr")
    return Case("edgewise-render", ["--scene", "torus", "--size", "64x48", "-o", out], 1, [out, FULL])


@case
def render_resolved_msaa_to_full_disk(d):
    out = symlink("/dev/full", f"{d}/out.png")
    return Case("edgewise-render", ["--size", "64x48", "--aa", "msaa4", "-o", out], 1, [out, FULL])


@case
def render_budget_comparison_to_full_disk(d):
    symlink("/dev/full", f"{d}/out-exact.png")
    return Case("edgewise-render", ["--size", "64x48", "--compare-budget", "0.004", "--repeat", "1",
                                    "-o", f"{d}/out.png"], 1, [f"{d}/out-exact.png", FULL])


@case
def render_each_filter_to_full_disk(d):
    symlink("/dev/full", f"{d}/out-nearest.png")
    return Case("edgewise-render", ["--scene", "ground", "--size", "64x48", "--texture", "checker",
                                    "--each-filter", "--repeat", "1", "-o", f"{d}/out.png"], 1,
                [f"{d}/out-nearest.png", FULL])


@case
def render_into_missing_folder(d):
    out = f"{d}/no/such/folder/out.png"
    return Case("edgewise-render", ["--size", "64x48", "-o", out], 1,
                [out, "No such file or directory"])


@case
def render_onto_a_folder(d):
    out = f"{d}/folder.png"
    os.mkdir(out)
    return Case("edgewise-render", ["--size", "64x48", "-o", out], 1, [out, "Is a directory"])


@case
def render_onto_a_read_only_file(d):
    # /proc/version refuses writers, root included.
    out = symlink("/proc/version", f"{d}/read-only.png")
    return Case("edgewise-render", ["--size", "64x48", "-o", out], 1, [out, "cannot write"])


@case
def render_to_full_standard_output(d):
    return Case("edgewise-render", ["--size", "64x48"], 1, ["standard output", "cannot write"],
                stdout="/dev/full")


@case
def city_to_full_disk(d):
    out = symlink("/dev/full", f"{d}/city.png")
    return Case("edgewise-city", ["--blocks", "2", "--frames", "1", "-o", out], 1, [out, FULL])


@case
def city_width_out_of_range(d):
    return Case("edgewise-city", ["--width", "0"], 2, ["--width"])


@case
def strokes_to_full_disk(d):
    out = symlink("/dev/full", f"{d}/strokes.png")
    return Case("edgewise-strokes", ["-o", out], 1, [out, FULL])


@case
def demo_to_full_disk(d):
    out = symlink("/dev/full", f"{d}/demo.png")
    return Case("edgewise-demo", ["-o", out], 1, [out, FULL])


@case
def coverage_listing_to_full_disk(d):
    triangles = write(f"{d}/triangles.txt", "1 1 30 2 5 20\n")
    return Case("edgewise-coverage", ["40", "30", triangles, "-o", "/dev/full"], 1,
                ["/dev/full", FULL], absent=[])


@case
def coverage_listing_to_full_standard_output(d):
    triangles = write(f"{d}/triangles.txt", "1 1 30 2 5 20\n")
    return Case("edgewise-coverage", ["40", "30", triangles], 1, ["standard output", "cannot write"],
                stdout="/dev/full")


@case
def random_triangles_to_full_disk(d):
    return Case("edgewise-random-triangles", ["64", "64", "100", "-o", "/dev/full"], 1,
                ["/dev/full", FULL])


@case
def aa_accuracy_csv_to_full_disk(d):
    return Case("edgewise-aa-accuracy", ["--triangles", "4", "--csv", "/dev/full"], 1,
                ["/dev/full", FULL])


@case
def sample_results_to_full_disk(d):
    texture = write(f"{d}/texture.png", valid_png(8, 8))
    queries = write(f"{d}/queries.bin", struct.pack("<6f", 0.5, 0.5, 0.1, 0, 0, 0.1) * 10)
    return Case("edgewise-sample", ["--texture", texture, "--filter", "trilinear", "--queries",
                                    queries, "--out", "/dev/full"], 1, ["/dev/full", FULL])


@case
def render_second_image_to_full_disk(d):
    # The disk is full for the second of two images (--compare-budget writes FILE-exact, then
    # FILE-budget).
    symlink("/dev/full", f"{d}/out-budget.png")
    return Case("edgewise-render", ["--size", "64x48", "--compare-budget", "0.004", "--repeat", "1",
                                    "-o", f"{d}/out.png"], 1, [f"{d}/out-budget.png", FULL])


# Inputs that are not regular files: devices that never end, pipes with no writer, folders,
# missing files. Refused before anything reads them.

def render_texture(path, *extra):
    return ["--scene", "ground", "--size", "64x48", "--texture", path, *extra]


@case
def texture_dev_zero(d):
    return Case("edgewise-render", render_texture("/dev/zero"), 1, ["/dev/zero", NOT_REGULAR])


@case
def texture_png_linked_to_dev_urandom(d):
    path = symlink("/dev/urandom", f"{d}/x.png")
    return Case("edgewise-render", render_texture(path), 1, [path, NOT_REGULAR])


@case
def texture_exr_linked_to_dev_zero(d):
    path = symlink("/dev/zero", f"{d}/x.exr")
    return Case("edgewise-render", render_texture(path), 1, [path, NOT_REGULAR])


@case
def texture_pfm_linked_to_dev_urandom(d):
    path = symlink("/dev/urandom", f"{d}/x.pfm")
    return Case("edgewise-render", render_texture(path), 1, [path, NOT_REGULAR])


@case
def texture_fifo_without_writer(d):
    path = fifo(f"{d}/pipe.png")
    return Case("edgewise-render", render_texture(path), 1, [path, NOT_REGULAR])


@case
def texture_missing(d):
    path = f"{d}/missing.png"
    return Case("edgewise-render", render_texture(path), 1, [path, "No such file or directory"])


@case
def texture_folder(d):
    path = f"{d}/folder.png"
    os.mkdir(path)
    return Case("edgewise-render", render_texture(path), 1, [path, "Is a directory"])


@case
def texture_empty_file(d):
    path = write(f"{d}/empty.png", b"")
    return Case("edgewise-render", render_texture(path), 1, [path, "cannot read image"])


@case
def texture_garbage_named_png(d):
    path = write(f"{d}/garbage.png", bytes(range(256)) * 64)
    return Case("edgewise-render", render_texture(path), 1, [path, "cannot read image"])


@case
def texture_text_named_jpg(d):
    path = write(f"{d}/text.jpg", "not an image\n" * 100)
    return Case("edgewise-render", render_texture(path), 1, [path, "cannot read image"])


@case
def texture_truncated_png(d):
    path = write(f"{d}/truncated.png", valid_png(64, 64)[:300])
    return Case("edgewise-render", render_texture(path), 1, [path, "cannot read image"])


# Images whose header lies about their size, and images that inflate: the size is refused from
# the header, before any pixel is allocated.

@case
def texture_header_claims_32768_squared(d):
    path = write(f"{d}/liar.png", png(32768, 32768, zlib.compress(b"\0" * 10)))
    return Case("edgewise-render", render_texture(path), 1,
                [path, "32768x32768", "over the limit", "--max-texture-mb"])


@case
def texture_inflates_to_16384_squared(d):
    rows = zlib.compressobj(9)
    data = b"".join(rows.compress(b"\0" * (16385 * 1024)) for _ in range(16)) + rows.flush()
    path = write(f"{d}/bomb.png", png(16384, 16384, data, colour_type=0))
    return Case("edgewise-render", render_texture(path), 1, [path, "16384x16384", "over the limit"])


@case
def texture_header_claims_more_than_its_data(d):
    path = write(f"{d}/short.png", png(4096, 4096, zlib.compress(b"\0" * 100)))
    return Case("edgewise-render", render_texture(path), 1, [path, "cannot read image"])


@case
def texture_over_a_lowered_limit(d):
    path = write(f"{d}/texture.png", valid_png(1024, 1024))
    return Case("edgewise-render", render_texture(path, "--max-texture-mb", "2"), 1,
                [path, "1024x1024", "4 MiB", "limit of 2 MiB"])


@case
def texture_within_a_raised_limit(d):
    path = write(f"{d}/texture.png", valid_png(1024, 1024))
    return Case("edgewise-render", render_texture(path, "--max-texture-mb", "4"), 0)


@case
def texture_limit_of_zero(d):
    return Case("edgewise-render", render_texture("checker", "--max-texture-mb", "0"), 2,
                ["--max-texture-mb", "0"])


@case
def texture_limit_not_a_number(d):
    return Case("edgewise-render", render_texture("checker", "--max-texture-mb", "lots"), 2,
                ["--max-texture-mb", "lots"])


@case
def sample_texture_header_claims_32768_squared(d):
    path = write(f"{d}/liar.png", png(32768, 32768, zlib.compress(b"\0" * 10)))
    queries = write(f"{d}/queries.bin", b"")
    return Case("edgewise-sample", ["--texture", path, "--filter", "nearest", "--queries", queries,
                                    "--out", f"{d}/out.bin"], 1, [path, "over the limit"],
                absent=[f"{d}/out.bin"])


@case
def sample_texture_dev_zero(d):
    queries = write(f"{d}/queries.bin", b"")
    return Case("edgewise-sample", ["--texture", "/dev/zero", "--filter", "nearest", "--queries",
                                    queries, "--out", f"{d}/out.bin"], 1, ["/dev/zero", NOT_REGULAR],
                absent=[f"{d}/out.bin"])


@case
def sample_queries_dev_zero(d):
    texture = write(f"{d}/texture.png", valid_png(8, 8))
    return Case("edgewise-sample", ["--texture", texture, "--filter", "nearest", "--queries",
                                    "/dev/zero", "--out", f"{d}/out.bin"], 1,
                ["/dev/zero", "not a regular file or a pipe"], absent=[f"{d}/out.bin"])


@case
def sample_queries_fifo_without_writer(d):
    # A pipe is a stream the tool reads to its end; with no writer that end is now.
    texture = write(f"{d}/texture.png", valid_png(8, 8))
    queries = fifo(f"{d}/queries.fifo")
    return Case("edgewise-sample", ["--texture", texture, "--filter", "nearest", "--queries",
                                    queries, "--out", f"{d}/out.bin"], 0)


# Meshes: devices, pipes, garbage, numbers out of range.

def render_obj(path):
    return ["--obj", path, "--size", "64x48", "-o", os.path.join(os.path.dirname(path), "o.png")]


@case
def obj_dev_zero(d):
    return Case("edgewise-render", ["--obj", "/dev/zero", "--size", "64x48"], 1,
                ["/dev/zero", NOT_REGULAR])


@case
def obj_fifo_without_writer(d):
    path = fifo(f"{d}/mesh.obj")
    return Case("edgewise-render", render_obj(path), 1, [path, NOT_REGULAR])


@case
def obj_missing(d):
    path = f"{d}/missing.obj"
    return Case("edgewise-render", render_obj(path), 1, [path, "No such file or directory"])


@case
def obj_binary_garbage(d):
    path = write(f"{d}/garbage.obj", bytes(range(256)) * 256)
    return Case("edgewise-render", render_obj(path), 1, [path], absent=[f"{d}/o.png"])


@case
def obj_face_index_out_of_range(d):
    path = write(f"{d}/bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n")
    return Case("edgewise-render", render_obj(path), 1, [path, "9"], absent=[f"{d}/o.png"])


@case
def obj_number_out_of_float_range(d):
    path = write(f"{d}/huge.obj", "v 0 0 1e999\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    return Case("edgewise-render", render_obj(path), 1, [path], absent=[f"{d}/o.png"])


@case
def obj_not_a_number(d):
    path = write(f"{d}/nan.obj", "v 0 0 nan\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    return Case("edgewise-render", render_obj(path), 1, [path], absent=[f"{d}/o.png"])


@case
def obj_scaled_by_1e20(d):
    # Any mesh whose extent is a float is framed (render/camera_setup.hpp), and drawn.
    path = write(f"{d}/far.obj", scaled_obj(1e20))
    return Case("edgewise-render", render_obj(path), 0, present=[f"{d}/o.png"],
                printed=DREW_FRAGMENTS)


@case
def obj_scaled_by_1e_minus_40(d):
    path = write(f"{d}/tiny.obj", scaled_obj(1e-40))
    return Case("edgewise-render", render_obj(path), 0, present=[f"{d}/o.png"],
                printed=DREW_FRAGMENTS)


@case
def obj_extent_beyond_float(d):
    path = write(f"{d}/vast.obj", "v -3e38 0 0\nv 3e38 0 0\nv 0 3e38 0\nf 1 2 3\n")
    return Case("edgewise-render", render_obj(path), 1, [path, "too large to frame"],
                absent=[f"{d}/o.png"])


@case
def obj_every_face_degenerate(d):
    path = write(f"{d}/flat.obj", "v 0 0 0\nv 1 1 1\nv 2 2 2\nf 1 2 3\nf 3 2 1\n")
    return Case("edgewise-render", render_obj(path), 1, [path], absent=[f"{d}/o.png"])


# Lists of triangles on a file or standard input.

@case
def coverage_triangles_dev_zero(d):
    return Case("edgewise-coverage", ["40", "30", "/dev/zero"], 1, ["/dev/zero", NOT_REGULAR])


@case
def coverage_triangles_fifo_without_writer(d):
    path = fifo(f"{d}/triangles.fifo")
    return Case("edgewise-coverage", ["40", "30", path], 1, [path, NOT_REGULAR])


@case
def coverage_dev_zero_on_standard_input(d):
    return Case("edgewise-coverage", ["40", "30", "-"], 1, ["<stdin>", "longer than"],
                stdin="/dev/zero")


@case
def coverage_dev_urandom_on_standard_input(d):
    # Random bytes may begin with a blank line or a comment (about one run in a hundred), which
    # the reader skips: the error names standard input on whichever line it meets.
    return Case("edgewise-coverage", ["40", "30", "-"], 1, ["<stdin>:"], stdin="/dev/urandom")


# Options at and past their ends: refused at once, or bounded where the cost is by nature.

@case
def strokes_tolerance_1e_minus_30(d):
    return Case("edgewise-strokes", ["--tolerance", "1e-30"], 2, ["--tolerance", "1e-30"])


@case
def strokes_exact_with_samples(d):
    return Case("edgewise-strokes", ["--exact", "--samples", "4"], 2, ["--exact", "--samples"])


@case
def render_size_past_the_limit(d):
    return Case("edgewise-render", ["--size", "70000x10"], 2, ["--size", "70000x10"])


@case
def render_size_zero(d):
    return Case("edgewise-render", ["--size", "0x10"], 2, ["--size", "0x10"])


@case
def render_largest_frame_in_a_small_address_space(d):
    # 16384 x 16384 is allowed and needs 2 GiB of framebuffer: within 1 GiB of address space it
    # must fail cleanly, saying why.
    return Case("edgewise-render", ["--size", "16384x16384", "-o", f"{d}/big.png"], 1,
                ["not enough memory", "16384x16384"], absent=[f"{d}/big.png"], limits=1 << 30)


@case
def render_ewa_with_strongly_negative_lod_bias(d):
    # EWA's work per query is bounded relative to its anisotropy, whatever the bias (sample.hpp):
    # the frame takes about a second (it took 41 s when a query could read 2^22 texels).
    return Case("edgewise-render", ["--scene", "ground", "--size", "1280x720", "--texture", "checker",
                                    "--filter", "ewa", "--lod-bias", "-8", "-o", f"{d}/ewa.png"], 0,
                present=[f"{d}/ewa.png"], cpu=10)


# --- Running a case ------------------------------------------------------------------------------

def run(name, tools, work, sanitized):
    folder = os.path.join(work, name)
    subprocess.run(["rm", "-rf", folder], check=True)
    os.makedirs(folder)
    c = CASES[name](folder)
    if sanitized and c.address_space is not None:
        # Its point is the limit itself, which AddressSanitizer's shadow memory cannot run under.
        return None
    tool = tools[c.tool]
    cpu = c.cpu * (4 if sanitized else 1)
    max_rss = kMaxRss * (2 if sanitized else 1)
    address_space = None if sanitized else c.address_space or kAddressSpace

    def limit():
        resource.setrlimit(resource.RLIMIT_CPU, (cpu, cpu + 5))
        if address_space is not None:
            resource.setrlimit(resource.RLIMIT_AS, (address_space, address_space))

    environment = dict(os.environ)
    if sanitized:
        environment["ASAN_OPTIONS"] = (environment.get("ASAN_OPTIONS", "") +
                                       ":allocator_may_return_null=1:max_allocation_size_mb=" +
                                       str((c.address_space or kMaxRss * 2) >> 20))
        suppressions = os.path.join(os.path.dirname(os.path.abspath(__file__)), "lsan.supp")
        environment["LSAN_OPTIONS"] = (environment.get("LSAN_OPTIONS", "") +
                                       ":suppressions=" + suppressions)
    stdout = open(c.stdout, "wb") if c.stdout else subprocess.PIPE
    stdin = open(c.stdin, "rb") if c.stdin else subprocess.DEVNULL
    command = [tool, *c.args]
    print("$", " ".join(command), (f"< {c.stdin}" if c.stdin else ""))
    process = subprocess.Popen(command, stdin=stdin, stdout=stdout, stderr=subprocess.PIPE,
                               preexec_fn=limit, cwd=folder, env=environment)
    try:
        printed, errors = process.communicate(timeout=2 * cpu)
    except subprocess.TimeoutExpired:
        process.kill()
        process.communicate()
        return [f"still running after {2 * cpu} s of wall time"]
    rss = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss * 1024
    errors = errors.decode(errors="replace")
    print(errors, end="")
    print(f"exit status {process.returncode}, {rss >> 20} MiB resident at most")

    failures = []
    if process.returncode < 0:
        failures.append(f"killed by signal {signal.Signals(-process.returncode).name}")
    elif process.returncode != c.status:
        failures.append(f"exit status {process.returncode}, expected {c.status}")
    if rss > max_rss:
        failures.append(f"{rss >> 20} MiB resident, over the limit of {max_rss >> 20} MiB")
    prefix = c.tool + ": "
    # Warnings ("tool: warning: ...") may accompany any run; errors are the tool's other lines.
    own = [line for line in errors.splitlines()
           if line.startswith(prefix) and not line.startswith(prefix + "warning: ")]
    if c.status != 0:
        if len(own) != 1:
            failures.append(f"{len(own)} lines of {c.tool} on standard error, expected 1")
        else:
            for text in c.message:
                if text not in own[0]:
                    failures.append(f"the error line does not hold '{text}'")
    elif own:
        failures.append("an error line from a run that should succeed")
    if c.printed and not re.search(c.printed, (printed or b"").decode(errors="replace")):
        failures.append(f"standard output does not match '{c.printed}'")
    if re.search(r"Sanitizer|runtime error:", errors):
        failures.append("a sanitizer report")
    for path in c.absent:
        if os.path.lexists(path):
            failures.append(f"{path} was left behind")
    for path in c.present:
        if not os.path.isfile(path) or os.path.getsize(path) == 0:
            failures.append(f"{path} was not written")
    return failures


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("case", nargs="?")
    parser.add_argument("--list", action="store_true")
    parser.add_argument("--work", default="hostile-input")
    parser.add_argument("--sanitized", action="store_true")
    parser.add_argument("--tool", action="append", default=[], help="NAME=PATH")
    arguments = parser.parse_args()
    if arguments.list:
        print(";".join(sorted(CASES)))
        return 0
    if arguments.case not in CASES:
        parser.error(f"unknown case '{arguments.case}'")
    tools = dict(item.split("=", 1) for item in arguments.tool)
    failures = run(arguments.case, tools, os.path.abspath(arguments.work), arguments.sanitized)
    if failures is None:
        print("skipped: this case runs under an address-space limit, which sanitized tools cannot")
        return kSkipped
    for failure in failures:
        print("FAIL:", failure, file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
