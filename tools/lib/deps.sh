# shellcheck shell=bash
# The Debian 12 packages each command needs, and the function that installs them (sourced by
# tools/demo and tools/check).
#
# One list for tools/demo and one per stage of tools/check; tools/check installs the lists of the
# stages it runs. Each list names what its command uses itself, with the reason beside it, and
# leaves what those packages depend on to apt. docs/requirements.md shows the same
# lists; tests/requirements compares the two. The `fresh` stage proves them: each command, run
# first on a minimal Debian root, must pass with what it installed itself.
#
# Missing packages are installed with apt-get when running as root. Otherwise the exact command
# to run is printed and the script stops, so nothing is built against a half-installed system.

# shellcheck disable=SC2034 # the lists are read by the scripts that source this file

# The Release build of the library and the tools (tools/lib/tools_build.sh) that tools/demo and
# tools/edgewise-atlas start with, and the check's host build too.
EDGEWISE_TOOLS_PACKAGES=(
  g++                  # GCC 12, the C++20 compiler, with binutils (linker, objdump, nm)
  cmake                # the build system (3.22 or newer)
  ninja-build          # the generator the scripts configure with
  libxsimd-dev         # the SIMD batches the library's kernels are written in
  libtbb-dev           # oneTBB: the library runs draw()'s and count_coverage()'s threads on it
  libopenimageio-dev   # image files: the tools read textures and write EXR images
  libpng-dev           # libpng: the tools encode their PNG images with it
  openimageio-tools    # OpenImageIO's CMake package imports its tools (/usr/bin/iconvert...): no configure without
  libtinyobjloader-dev # edgewise-render reads OBJ meshes (testing/scene)
  libcli11-dev         # CLI11: every tool parses its command line with it
  ccache               # the compiler cache the builds share (tools/lib/ccache.sh)
)

# tools/edgewise-atlas: the tools' build, the study program (timed with Google Benchmark) and
# the charts.
EDGEWISE_ATLAS_PACKAGES=(
  "${EDGEWISE_TOOLS_PACKAGES[@]}"
  libbenchmark-dev   # Google Benchmark: the studies time their methods with the benchmarks' harness
  python3-matplotlib # draws the atlas's charts (tools/atlas/plot_atlas.py)
)

# tools/demo: the tools' build, edgewise-render, edgewise-city, edgewise-strokes and edgewise-demo,
# and last the method atlas's quick run (tools/edgewise-atlas, which installs the same list).
EDGEWISE_DEMO_PACKAGES=("${EDGEWISE_ATLAS_PACKAGES[@]}")

# tools/check, stage by stage.
EDGEWISE_CHECK_FORMAT_PACKAGES=(
  clang-format # the format stage's formatter (clang-format 14)
)
# The host build is the tools' build plus the test suite and the benchmarks.
EDGEWISE_CHECK_HOST_PACKAGES=(
  "${EDGEWISE_TOOLS_PACKAGES[@]}"
  libgtest-dev       # GoogleTest: the test suite
  libbenchmark-dev   # Google Benchmark: edgewise-bench, built with everything else
  libegl-dev         # EGL (headers, libEGL): llvmpipe for edgewise-bench's DrawPeer/ and tests/peer
  libopengl-dev      # libOpenGL, their GL entry points (CMake's FindOpenGL needs it with EGL)
  libgl-dev          # GL/glcorearb.h, their GL declarations
  libgl1-mesa-dri    # Mesa's llvmpipe, which DrawPeer/ measures and tests/peer compares with
  python3-matplotlib # the atlas's charts, drawn by its test from a short run
  python3            # runs the hostile-input suite (tests/hostile_input)
)
# The host build, then objdump and nm (binutils, from g++) read its objects.
EDGEWISE_CHECK_ISA_OBJECTS_PACKAGES=("${EDGEWISE_CHECK_HOST_PACKAGES[@]}")
EDGEWISE_CHECK_AARCH64_PACKAGES=(
  cmake                 # the build system
  ninja-build           # the generator
  libxsimd-dev          # xsimd's headers, which the cross compiler sees through a folder of its own
  googletest            # GoogleTest's sources in /usr/src/googletest, built for AArch64
  g++-aarch64-linux-gnu # the AArch64 cross compiler
  qemu-user             # runs the AArch64 test binaries (qemu-aarch64)
  ccache                # the compiler cache the builds share (tools/lib/ccache.sh)
)
# The host build without the benchmarks, instrumented, with clang; the fuzz targets too.
EDGEWISE_CHECK_SANITIZE_PACKAGES=(
  clang-14             # the instrumented build's compiler (libFuzzer needs clang)
  libclang-rt-14-dev   # clang's AddressSanitizer, UBSan and libFuzzer runtimes
  cmake                # the build system
  ninja-build          # the generator
  libxsimd-dev         # the kernels' SIMD batches
  libtbb-dev           # oneTBB, the library's threads
  libopenimageio-dev   # the tools, whose tests run sanitized too
  libpng-dev           # the tools' PNG images
  openimageio-tools    # OpenImageIO's CMake package needs them; oiiotool writes test textures
  libtinyobjloader-dev # edgewise-render and the mesh tests
  libcli11-dev         # CLI11: the tools' command lines
  libgtest-dev         # GoogleTest: the test suite
  python3              # runs the hostile-input suite (tests/hostile_input)
  ccache               # the compiler cache the builds share (tools/lib/ccache.sh)
)
# The multi-thread tests, built with ThreadSanitizer; tasks on std::thread, not oneTBB (tools/check).
EDGEWISE_CHECK_TSAN_PACKAGES=(
  g++          # GCC 12 with its ThreadSanitizer runtime
  cmake        # the build system
  ninja-build  # the generator
  libxsimd-dev # the kernels' SIMD batches
  libgtest-dev # GoogleTest: the tests
  ccache       # the compiler cache the builds share (tools/lib/ccache.sh)
)
# The fuzz targets, built in the sanitize stage's build (the suite and the tools with them).
EDGEWISE_CHECK_FUZZ_PACKAGES=("${EDGEWISE_CHECK_SANITIZE_PACKAGES[@]}")
# The host build, installed, then a consumer project built against it with the same tools.
EDGEWISE_CHECK_INSTALL_PACKAGES=("${EDGEWISE_CHECK_HOST_PACKAGES[@]}")
EDGEWISE_CHECK_FRESH_PACKAGES=(
  debootstrap # builds the minimal Debian 12 root the two commands run on
  socat       # the root's only way out: a relay to the package mirror
  iproute2    # brings up loopback in the root's own network namespace
)

# Prints the packages of tools/check's stage $1, one per line.
edgewise_check_stage_packages() {
  local variable
  variable="EDGEWISE_CHECK_$(tr 'a-z-' 'A-Z_' <<<"$1")_PACKAGES[@]"
  if ! declare -p "${variable%'[@]'}" >/dev/null 2>&1; then
    echo "error: no package list for check stage '$1' in tools/lib/deps.sh" >&2
    return 1
  fi
  printf '%s\n' "${!variable}"
}

# Prints the packages among "$@" that dpkg does not report as installed.
edgewise_missing_packages() {
  local package status
  for package in "$@"; do
    status=$(dpkg-query --show --showformat='${db:Status-Abbrev}' "$package" 2>/dev/null || true)
    [[ $status == ii* ]] || printf '%s\n' "$package"
  done
}

# Installs the packages among "$@" that are missing, or explains how and returns non-zero.
edgewise_require_packages() {
  if [[ ${EDGEWISE_SKIP_PACKAGE_CHECK:-0} == 1 ]]; then
    return 0
  fi
  if ! command -v dpkg-query >/dev/null; then
    echo "error: dpkg-query not found; these scripts install Debian 12 packages:" >&2
    echo "  $*" >&2
    echo "Install the equivalents and rerun with EDGEWISE_SKIP_PACKAGE_CHECK=1." >&2
    return 1
  fi

  local missing
  mapfile -t missing < <(edgewise_missing_packages "$@" | sort -u)
  if ((${#missing[@]} == 0)); then
    return 0
  fi

  local install=(apt-get install -y --no-install-recommends "${missing[@]}")
  if ((EUID != 0)); then
    echo "error: missing Debian packages: ${missing[*]}" >&2
    echo "Install them with:" >&2
    echo "  sudo apt-get update && sudo ${install[*]}" >&2
    return 1
  fi

  echo "Installing missing packages: ${missing[*]}"
  apt-get update
  DEBIAN_FRONTEND=noninteractive "${install[@]}"
}
