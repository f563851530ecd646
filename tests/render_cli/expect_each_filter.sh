#!/bin/sh
# expect_each_filter.sh TOOL STEM [ARGS...]: runs TOOL --each-filter -o STEM.png ARGS and passes
# when it exits with status 0, prints one table row per texture filter (all 11, in the order of
# edgewise::TextureFilter) with a fragment count above 0, and writes exactly those 11 images,
# STEM-<filter>.png, each a PNG file.
set -u
tool=$1 stem=$2
shift 2
filters='nearest bilinear bicubic_catmull_rom bicubic_bspline mip_nearest trilinear supersample
ripmap summed_area anisotropic ewa'
fail() { echo "FAIL: $*" >&2; exit 1; }
rm -f "$stem"-*.png
output=$("$tool" --each-filter -o "$stem.png" "$@")
status=$?
printf '%s\n' "$output"
[ "$status" -eq 0 ] || fail "exit status $status"
# The table's rows: between its header line and the counts that follow it.
table=$(printf '%s\n' "$output" | sed -n '/^  filter /,/^triangles/p' | sed '1d;$d')
rows=$(printf '%s\n' "$table" | awk '{print $1}' | tr '\n' ' ')
expected=$(printf '%s ' $filters)
[ "$rows" = "$expected" ] || fail "table rows '$rows', expected '$expected'"
# Columns: filter, frame, fastest and raster times (number and unit each), fragments, image.
printf '%s\n' "$table" | awk '!($8 > 0) { exit 1 }' || fail "a row without fragments"
for filter in $filters; do
  image="$stem-$filter.png"
  found=$(od -An -tx1 -N4 "$image" 2>/dev/null | tr -d ' \n')
  [ "$found" = '89504e47' ] || fail "$image is not a PNG file"
  printf '%s\n' "$table" | grep -q "^  $filter .* $image\$" || fail "no row names $image"
done
count=$(ls "$stem"-*.png | wc -l)
[ "$count" -eq 11 ] || fail "$count images, expected 11"
