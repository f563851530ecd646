#!/bin/sh
# expect_image.sh TOOL IMAGE [ARGS...]: runs TOOL -o IMAGE ARGS and passes when it exits with
# status 0, IMAGE starts with the signature of its format (by extension), and the printed
# "fragments passed" count is above 0.
set -u
tool=$1 image=$2
shift 2
rm -f "$image"
output=$("$tool" -o "$image" "$@")
status=$?
printf '%s\n' "$output"
[ "$status" -eq 0 ] || { echo "FAIL: exit status $status" >&2; exit 1; }
case $image in
  *.png) signature='89504e47' ;;  # \x89 P N G
  *.exr) signature='762f3101' ;;  # OpenEXR magic number 20000630, little-endian
  *) echo "FAIL: no known signature for $image" >&2; exit 1 ;;
esac
found=$(od -An -tx1 -N4 "$image" 2>/dev/null | tr -d ' \n')
[ "$found" = "$signature" ] || { echo "FAIL: $image starts with '$found', not $signature" >&2; exit 1; }
passed=$(printf '%s\n' "$output" | sed -n 's/^ *fragments passed *\([0-9][0-9]*\).*/\1/p')
[ -n "$passed" ] && [ "$passed" -gt 0 ] || { echo "FAIL: fragments passed '$passed'" >&2; exit 1; }
