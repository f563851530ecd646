# shellcheck shell=bash
# Runs ctest in a build directory and records how many tests passed, were skipped and failed
# (sourced by tools/check).
#
# ctest's summary ("100% tests passed, 0 tests failed out of 57") counts skipped tests as passed,
# so the tests listed under "The following tests did not run" are subtracted and reported apart.

# edgewise_ctest BUILD_DIR [CTEST_ARGS...]: returns ctest's exit status.
edgewise_ctest() {
  local build_dir=$1
  shift
  local log="$build_dir/ctest.log" status_file="$build_dir/ctest.status"
  # ctest's status is kept in a file: a pipeline's status is tee's unless pipefail is set.
  echo 0 >"$status_file"
  {
    ctest --test-dir "$build_dir" --output-on-failure --no-tests=error -j "$EDGEWISE_JOBS" "$@" \
      || echo "$?" >"$status_file"
  } | tee "$log"
  local status
  status=$(<"$status_file")

  local summary total failed not_run
  summary=$(grep -E '^[0-9]+% tests passed, [0-9]+ tests? failed out of [0-9]+' "$log" \
    | tail -n 1 || true)
  if [[ -z $summary ]]; then
    echo "error: no ctest summary line in $log" >&2
    return 1
  fi
  failed=$(sed -E 's/.* ([0-9]+) tests? failed out of.*/\1/' <<<"$summary")
  total=$(sed -E 's/.* out of ([0-9]+).*/\1/' <<<"$summary")
  not_run=$(sed -n '/^The following tests did not run:/,$p' "$log" \
    | grep -cE '\((Skipped|Disabled)\)$' || true)
  echo "$((total - failed - not_run)) $not_run $failed" >>"$EDGEWISE_STAGE_COUNTS"
  return "$status"
}
