# shellcheck shell=bash
# The compiler cache the builds share (ccache, where installed), sourced by tools/check and
# tools/lib/tools_build.sh. A compile is looked up by its preprocessed input, its flags and the
# compiler's own bytes, so builds anywhere under the source root (the fresh stage's roots
# included, which mount the same cache) reuse each other's objects when their flags agree.
#
# -Werror is left out of the key, so that tools/demo's build (without it) and the check's builds
# (with it) share their objects. A hit replays the compile's warnings but not -Werror's failure,
# so the check's -Werror builds fail on any warning in their output instead
# (edgewise_fail_on_warnings): an object that compiled with a warning fails them whether it was
# compiled now or taken from the cache.
#
# Environment: EDGEWISE_CACHE_DIR (default ${XDG_CACHE_HOME:-$HOME/.cache}/edgewise) holds it in
# ccache/; EDGEWISE_CCACHE=0 builds without it.

# edgewise_ccache_launcher ROOT: exports the cache's settings and sets EDGEWISE_CCACHE_ARGS to the
# CMake arguments that compile through it (none when ccache is missing or turned off). Not in a
# command substitution: its exports must reach the builds.
edgewise_ccache_launcher() {
  local root=$1
  EDGEWISE_CCACHE_ARGS=()
  if [[ ${EDGEWISE_CCACHE:-1} == 0 ]] || ! command -v ccache >/dev/null; then
    return 0
  fi
  export CCACHE_DIR="${EDGEWISE_CACHE_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/edgewise}/ccache"
  export CCACHE_BASEDIR=$root CCACHE_NOHASHDIR=1 CCACHE_COMPILERCHECK=content
  export CCACHE_IGNOREOPTIONS=-Werror CCACHE_MAXSIZE=${CCACHE_MAXSIZE:-8G}
  mkdir -p "$CCACHE_DIR"
  # shellcheck disable=SC2034 # read by the scripts that source this file
  EDGEWISE_CCACHE_ARGS=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
}

# edgewise_fail_on_warnings LOG: fails, naming them, if a build's output LOG holds a compiler
# warning: with the cache, -Werror alone would let a warning replayed from a hit pass.
edgewise_fail_on_warnings() {
  local warnings
  warnings=$(grep -E '(: |^)warning: ' "$1" || true)
  if [[ -n $warnings ]]; then
    echo "error: the build warned (warnings are errors here; the full output is in $1):" >&2
    echo "$warnings" >&2
    return 1
  fi
}
