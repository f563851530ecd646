#!/bin/sh
# expect_error.sh TOOL MESSAGE [ARGS...]: runs TOOL ARGS and passes when it exits with status 1
# and writes exactly one line to standard error, starting "edgewise-render: " and containing
# MESSAGE (a fixed string): a clear error, never a crash or a sanitizer report.
set -u
tool=$1 message=$2
shift 2
errors=$("$tool" "$@" 2>&1 >/dev/null)
status=$?
printf '%s\n' "$errors"
[ "$status" -eq 1 ] || { echo "FAIL: exit status $status, expected 1" >&2; exit 1; }
lines=$(printf '%s\n' "$errors" | wc -l)
[ "$lines" -eq 1 ] || { echo "FAIL: $lines lines on standard error, expected 1" >&2; exit 1; }
case $errors in
  "edgewise-render: "*"$message"*) ;;
  *) echo "FAIL: expected 'edgewise-render: ...$message...'" >&2; exit 1 ;;
esac
