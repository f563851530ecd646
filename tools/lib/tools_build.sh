# shellcheck shell=bash
# The Release build of the library and the tools in build/ that tools/demo and
# tools/edgewise-atlas share (sourced by both).

# edgewise_build_tools ROOT TARGET...: configures ROOT/build (a fresh one gets only the library
# and the tools: no tests, no benchmarks; an existing one keeps its other settings) and builds
# the TARGETs. Strict: a missing image or mesh library stops the configure step with its name,
# rather than leaving the tools undefined. Compiles through the compiler cache
# (tools/lib/ccache.sh), which the check's host build then reuses.
edgewise_build_tools() {
  local root=$1
  shift
  local build_dir="$root/build"
  # shellcheck source=ccache.sh
  source "$root/tools/lib/ccache.sh"
  edgewise_ccache_launcher "$root"
  local configure=(-DCMAKE_BUILD_TYPE=Release -DEDGEWISE_BUILD_TOOLS=ON
    -DEDGEWISE_STRICT_DEPENDENCIES=ON "${EDGEWISE_CCACHE_ARGS[@]}")
  if [[ ! -f $build_dir/CMakeCache.txt ]]; then
    configure+=(-G Ninja -DEDGEWISE_BUILD_TESTS=OFF -DEDGEWISE_BUILD_BENCH=OFF)
  fi
  cmake -S "$root" -B "$build_dir" "${configure[@]}"
  cmake --build "$build_dir" --target "$@" -j "$(nproc)"
}
