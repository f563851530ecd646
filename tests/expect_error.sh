#!/bin/sh
# expect_error.sh TOOL STATUS MESSAGE [ARGS...]: runs TOOL ARGS and passes when it exits with
# STATUS and writes exactly one line to standard error, starting with the tool's name and ": "
# and containing MESSAGE (a fixed string): a clear error, never a crash or a sanitizer report.
set -u
tool=$1 expected_status=$2 message=$3
shift 3
name=$(basename "$tool")
errors=$("$tool" "$@" 2>&1 >/dev/null)
status=$?
printf '%s\n' "$errors"
[ "$status" -eq "$expected_status" ] ||
  { echo "FAIL: exit status $status, expected $expected_status" >&2; exit 1; }
lines=$(printf '%s\n' "$errors" | wc -l)
[ "$lines" -eq 1 ] || { echo "FAIL: $lines lines on standard error, expected 1" >&2; exit 1; }
case $errors in
  "$name: "*"$message"*) ;;
  *) echo "FAIL: expected '$name: ...$message...'" >&2; exit 1 ;;
esac
