#!/bin/sh
# run_tool.sh [--fresh DIR] OUT TOOL [ARGS...]: runs TOOL ARGS with its standard output in OUT
# and exits with TOOL's status. --fresh DIR empties DIR first, so that the run finds no cache.
set -u
if [ "$1" = --fresh ]; then
  rm -rf "$2" && mkdir -p "$2" || exit 1
  shift 2
fi
out=$1
shift
"$@" > "$out"
