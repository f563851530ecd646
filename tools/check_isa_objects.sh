#!/usr/bin/env bash
# Checks the x86 kernel objects of a build for the two ways per-ISA code can reach a CPU that
# cannot run it:
#   1. an object built for SSE2 or SSE4.1 (or the ISA-free library code) contains a VEX or EVEX
#      instruction;
#   2. two objects built with different flags define the same weak or global function: the
#      linker keeps one copy for both callers, so an AVX2-compiled inline function can end up
#      on the SSE2 path.
# As a control that the first check can fail, the AVX2 objects together must contain VEX
# instructions.
#
# Usage: tools/check_isa_objects.sh BUILD_DIR   (a host build of edgewise)
set -euo pipefail

if (($# != 1)); then
  echo "usage: $0 BUILD_DIR" >&2
  exit 2
fi
objects_root="$1/kernels/CMakeFiles"
if [[ ! -d $objects_root ]]; then
  echo "error: no kernel objects under $objects_root" >&2
  exit 2
fi

# One object directory per CMake target, hence per set of compiler flags: edgewise.dir holds
# the ISA-free code (default x86-64 flags), edgewise_<isa>.dir each ISA's kernels.
mapfile -t object_dirs < <(find "$objects_root" -maxdepth 1 -type d -name 'edgewise*.dir' | sort)
if [[ ${#object_dirs[@]} -eq 0 ]] || [[ ! -d $objects_root/edgewise_avx2.dir ]]; then
  echo "error: expected edgewise.dir and the x86 ISA object directories in $objects_root" >&2
  exit 2
fi

# Prints the instructions of an object that are VEX or EVEX encoded. In 64-bit mode the bytes
# C4 and C5 (LES/LDS in 32-bit mode) always start a VEX prefix and 62 (BOUND) an EVEX prefix;
# only segment and address-size prefixes may precede them.
vex_instructions() {
  objdump -d --wide "$1" | awk -F'\t' '
    /^ *[0-9a-f]+:\t/ && NF >= 3 {
      n = split($2, bytes, " ")
      i = 1
      while (i <= n && bytes[i] ~ /^(26|2e|36|3e|64|65|67)$/) i++
      if (i <= n && bytes[i] ~ /^(c4|c5|62)$/) print $3
    }'
}

failed=0

echo "VEX/EVEX instructions per object:"
for dir in "${object_dirs[@]}"; do
  target=$(basename "$dir" .dir)
  target_count=0
  while IFS= read -r object; do
    count=$(vex_instructions "$object" | wc -l)
    target_count=$((target_count + count))
    printf '  %-16s %-28s %6d\n' "$target" "$(basename "$object")" "$count"
    if [[ $target != *avx* ]] && ((count > 0)); then
      echo "error: $object is not built for AVX but contains VEX/EVEX instructions:" >&2
      vex_instructions "$object" | sort | uniq -c | sort -rn | head -n 20 >&2
      failed=1
    fi
  done < <(find "$dir" -name '*.o' | sort)
  # The control: the AVX objects (kernels; the table holds data only) must show VEX code.
  if [[ $target == *avx* ]] && ((target_count == 0)); then
    echo "error: $target has no VEX instruction: the check cannot see AVX code" >&2
    failed=1
  fi
done

# Defined functions: global (T), weak (W) and indirect (i) symbols. Data symbols (a weak
# personality routine reference, guard variables) carry no instructions.
functions_of_target() {
  find "$1" -name '*.o' -exec nm --defined-only {} + | awk '$2 ~ /^[TWi]$/ { print $3 }' | sort -u
}

echo "Functions defined by objects built with different flags:"
shared_total=0
for ((a = 0; a < ${#object_dirs[@]}; a++)); do
  for ((b = a + 1; b < ${#object_dirs[@]}; b++)); do
    shared=$(comm -12 <(functions_of_target "${object_dirs[a]}") \
      <(functions_of_target "${object_dirs[b]}"))
    if [[ -n $shared ]]; then
      echo "error: defined in both $(basename "${object_dirs[a]}" .dir) and" \
        "$(basename "${object_dirs[b]}" .dir):" >&2
      c++filt <<<"$shared" | sed 's/^/    /' >&2
      shared_total=$((shared_total + $(wc -l <<<"$shared")))
      failed=1
    fi
  done
done
echo "  $shared_total"

if ((failed)); then
  echo "ISA object check FAILED" >&2
  exit 1
fi
echo "ISA object check passed"
