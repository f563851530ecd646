# shellcheck shell=bash
# The compiler cache the builds share (ccache, where installed), sourced by tools/check and
# tools/lib/tools_build.sh. A compile is looked up by its preprocessed input, its flags and the
# compiler's own bytes, so builds anywhere under the source root (the fresh stage's roots
# included, which mount the same cache) reuse each other's objects when their flags agree.
#
# -Werror is left out of the key: the check's builds compile with it, so every object they store
# compiled without a warning, and a build without it (tools/demo's) may reuse them. Builds
# without -Werror only read the cache (edgewise_ccache_launcher read-only): an object they stored
# could carry a warning that a -Werror build would then take without failing.
#
# Environment: EDGEWISE_CACHE_DIR (default ${XDG_CACHE_HOME:-$HOME/.cache}/edgewise) holds it in
# ccache/; EDGEWISE_CCACHE=0 builds without it.

# edgewise_ccache_launcher ROOT [read-only]: exports the cache's settings and sets
# EDGEWISE_CCACHE_ARGS to the CMake arguments that compile through it (none when ccache is
# missing or turned off). Not in a command substitution: its exports must reach the builds.
edgewise_ccache_launcher() {
  local root=$1 mode=${2:-}
  EDGEWISE_CCACHE_ARGS=()
  if [[ ${EDGEWISE_CCACHE:-1} == 0 ]] || ! command -v ccache >/dev/null; then
    return 0
  fi
  export CCACHE_DIR="${EDGEWISE_CACHE_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/edgewise}/ccache"
  export CCACHE_BASEDIR=$root CCACHE_NOHASHDIR=1 CCACHE_COMPILERCHECK=content
  export CCACHE_IGNOREOPTIONS=-Werror CCACHE_MAXSIZE=${CCACHE_MAXSIZE:-8G}
  if [[ $mode == read-only ]]; then
    export CCACHE_READONLY=1
  else
    unset CCACHE_READONLY
  fi
  mkdir -p "$CCACHE_DIR"
  # shellcheck disable=SC2034 # read by the scripts that source this file
  EDGEWISE_CCACHE_ARGS=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
}
