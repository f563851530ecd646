# shellcheck shell=bash
# Runs named, timed stages, stops at the first failure and prints a summary table
# (sourced by tools/check).
#
# A stage is a shell function run in a subshell with `set -e`, so any failing command fails the
# stage and its exports stay inside it. Stages report their tests through edgewise_ctest
# (tools/lib/ctest.sh), which appends "passed skipped failed" lines to $EDGEWISE_STAGE_COUNTS.

EDGEWISE_STAGE_ROWS=()
EDGEWISE_TESTS_PASSED=0
EDGEWISE_TESTS_SKIPPED=0
EDGEWISE_TESTS_FAILED=0

# Whether a stage is selected: named by EDGEWISE_CHECK_STAGES (comma- or space-separated; default
# all) and not by EDGEWISE_CHECK_SKIP (the same form; default none).
edgewise_stage_selected() {
  local wanted=${EDGEWISE_CHECK_STAGES:-all} skipped=${EDGEWISE_CHECK_SKIP:-}
  [[ " ${skipped//,/ } " == *" $1 "* ]] && return 1
  [[ $wanted == all ]] && return 0
  [[ " ${wanted//,/ } " == *" $1 "* ]]
}

# Wall-clock microseconds (bash 5's EPOCHREALTIME without its decimal point).
edgewise_now_us() {
  echo "${EPOCHREALTIME/[.,]/}"
}

# Formats microseconds as m:ss.s.
edgewise_format_duration() {
  local tenths=$(($1 / 100000))
  printf '%d:%02d.%d' $((tenths / 600)) $((tenths % 600 / 10)) $((tenths % 10))
}

EDGEWISE_CHECK_START=$(edgewise_now_us)
EDGEWISE_CPU_TOTAL_S=0

# edgewise_children_cpu_seconds FILE: writes to FILE the processor time, in whole seconds, that
# this shell's finished children used (user and system: the second line of bash's `times`, run
# in this shell itself, since a subshell's children are not its parent's), which is a stage's
# when its subshell calls it last.
edgewise_children_cpu_seconds() {
  times >"$1"
  awk 'function sec(t, m) {
      m = t; sub(/m.*/, "", m); sub(/^[0-9]+m/, "", t); sub(/s$/, "", t); return m * 60 + t
    } NR == 2 { printf "%d\n", sec($1) + sec($2) }' "$1" >"$1.seconds"
  mv "$1.seconds" "$1"
}

edgewise_print_summary() {
  local format='%-12s %-8s %8s %8s %8s %8s %8s\n' row
  echo
  echo "==== Summary (cpu: the processor time of the stage's commands, summed over cores)"
  # shellcheck disable=SC2059 # the format is shared by every row
  printf "$format" stage result time cpu passed skipped failed
  for row in "${EDGEWISE_STAGE_ROWS[@]}"; do
    # shellcheck disable=SC2059,SC2086 # a row is seven words
    printf "$format" $row
  done
  local total=$(($(edgewise_now_us) - EDGEWISE_CHECK_START))
  # shellcheck disable=SC2059
  printf "$format" total "" "$(edgewise_format_duration "$total")" \
    "$(edgewise_format_duration $((EDGEWISE_CPU_TOTAL_S * 1000000)))" \
    "$EDGEWISE_TESTS_PASSED" "$EDGEWISE_TESTS_SKIPPED" "$EDGEWISE_TESTS_FAILED"
}

# edgewise_run_stage NAME DESCRIPTION FUNCTION: runs FUNCTION if NAME is selected; on failure,
# prints the summary and the final count line, and exits with the stage's status.
edgewise_run_stage() {
  local name=$1 description=$2 function=$3
  if ! edgewise_stage_selected "$name"; then
    EDGEWISE_STAGE_ROWS+=("$name not-run - - - - -")
    return 0
  fi

  echo
  echo "==== [$name] $description"
  local start status counts
  start=$(edgewise_now_us)
  counts=$(mktemp)
  set +e
  (
    set -e
    export EDGEWISE_STAGE_COUNTS=$counts
    "$function"
    edgewise_children_cpu_seconds "$counts.cpu"
  )
  status=$?
  set -e
  edgewise_record_stage "$name" "$status" "$start" "$counts"
}

# A stage started in the background: its process, start time, counts file and log.
EDGEWISE_BACKGROUND_STAGE=()

# edgewise_start_stage NAME DESCRIPTION FUNCTION: starts FUNCTION in the background (if NAME is
# selected), its output into a log, for a stage that waits on the network and the disk more than
# it computes (the fresh stage's package downloads and installs), so that the stages run
# meanwhile use the processors. One at a time; edgewise_finish_stage collects it.
edgewise_start_stage() {
  local name=$1 description=$2 function=$3
  if ! edgewise_stage_selected "$name"; then
    EDGEWISE_STAGE_ROWS+=("$name not-run - - - - -")
    return 0
  fi
  local counts log
  counts=$(mktemp)
  log=$(mktemp)
  echo
  echo "==== [$name] $description: started in the background (its output follows when it ends)"
  (
    set -e
    export EDGEWISE_STAGE_COUNTS=$counts
    "$function"
    edgewise_children_cpu_seconds "$counts.cpu"
  ) >"$log" 2>&1 &
  EDGEWISE_BACKGROUND_STAGE=("$name" "$!" "$(edgewise_now_us)" "$counts" "$log")
  # A check that ends early (a failed stage, an interrupt) stops it.
  trap 'edgewise_stop_background_stage' EXIT
}

# Ends process $1 and everything it started, children first.
edgewise_kill_tree() {
  local child
  for child in $(pgrep -P "$1" 2>/dev/null); do
    edgewise_kill_tree "$child"
  done
  kill "$1" 2>/dev/null || true
}

edgewise_stop_background_stage() {
  if ((${#EDGEWISE_BACKGROUND_STAGE[@]} > 0)); then
    edgewise_kill_tree "${EDGEWISE_BACKGROUND_STAGE[1]}"
    wait "${EDGEWISE_BACKGROUND_STAGE[1]}" 2>/dev/null || true
    rm -f "${EDGEWISE_BACKGROUND_STAGE[3]}" "${EDGEWISE_BACKGROUND_STAGE[3]}.cpu" \
      "${EDGEWISE_BACKGROUND_STAGE[4]}"
    EDGEWISE_BACKGROUND_STAGE=()
  fi
}

# edgewise_finish_stage: waits for the stage edgewise_start_stage started, prints its output and
# records it as edgewise_run_stage does.
edgewise_finish_stage() {
  ((${#EDGEWISE_BACKGROUND_STAGE[@]} > 0)) || return 0
  local name=${EDGEWISE_BACKGROUND_STAGE[0]} pid=${EDGEWISE_BACKGROUND_STAGE[1]}
  local start=${EDGEWISE_BACKGROUND_STAGE[2]} counts=${EDGEWISE_BACKGROUND_STAGE[3]}
  local log=${EDGEWISE_BACKGROUND_STAGE[4]} status
  echo
  echo "==== [$name] waiting for it to end"
  set +e
  wait "$pid"
  status=$?
  set -e
  EDGEWISE_BACKGROUND_STAGE=()
  trap - EXIT
  cat "$log"
  rm -f "$log"
  edgewise_record_stage "$name" "$status" "$start" "$counts"
}

# edgewise_record_stage NAME STATUS START COUNTS_FILE: adds the stage's row and counts; on
# failure, prints the summary and the final count line, and exits with the stage's status.
edgewise_record_stage() {
  local name=$1 status=$2 start=$3 counts=$4
  local elapsed=$(($(edgewise_now_us) - start)) passed=0 skipped=0 failed=0 p s f
  while read -r p s f; do
    passed=$((passed + p)) skipped=$((skipped + s)) failed=$((failed + f))
  done <"$counts"
  local cpu=- cpu_s
  if [[ -s $counts.cpu ]]; then
    read -r cpu_s <"$counts.cpu"
    EDGEWISE_CPU_TOTAL_S=$((EDGEWISE_CPU_TOTAL_S + cpu_s))
    cpu=$(edgewise_format_duration $((cpu_s * 1000000)))
  fi
  rm -f "$counts" "$counts.cpu"
  # A stage that fails outside ctest (a build error, a finding) counts as one failure.
  if ((status != 0 && failed == 0)); then
    failed=1
  fi
  EDGEWISE_TESTS_PASSED=$((EDGEWISE_TESTS_PASSED + passed))
  EDGEWISE_TESTS_SKIPPED=$((EDGEWISE_TESTS_SKIPPED + skipped))
  EDGEWISE_TESTS_FAILED=$((EDGEWISE_TESTS_FAILED + failed))

  local result=ok duration
  ((status == 0)) || result=FAILED
  duration=$(edgewise_format_duration "$elapsed")
  EDGEWISE_STAGE_ROWS+=("$name $result $duration $cpu $passed $skipped $failed")
  echo "==== [$name] $result in $duration"
  if ((status != 0)); then
    edgewise_print_summary
    echo "stage '$name' failed (exit status $status)"
    echo "$EDGEWISE_TESTS_PASSED passed, $EDGEWISE_TESTS_FAILED failed"
    exit "$status"
  fi
}

# Prints the summary and the final count line of a run in which every stage passed.
edgewise_finish_stages() {
  edgewise_print_summary
  echo "$EDGEWISE_TESTS_PASSED passed, $EDGEWISE_TESTS_FAILED failed"
}
