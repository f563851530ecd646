#!/bin/sh
# plot_rejects_bad_input.sh PLOT_ATLAS DIR: tools/atlas/plot_atlas.py exits with status 1 and
# names the problem for a folder with no study, for a study whose CSV has no points for one of its
# charts, a bad header, or a row without its point's label.
set -u
plot=$1 dir=$2
rm -rf "$dir" && mkdir -p "$dir" || exit 1
fail() { echo "FAIL: $*" >&2; exit 1; }

expect() {  # expect MESSAGE: the plot fails with status 1 and MESSAGE on standard error
  errors=$(/usr/bin/python3 "$plot" "$dir" 2>&1 >/dev/null)
  status=$?
  printf '%s\n' "$errors"
  [ "$status" -eq 1 ] || fail "exit status $status, expected 1"
  case $errors in
    *"$1"*) ;;
    *) fail "expected '$1'" ;;
  esac
}

expect "no study (*.json) in $dir"
cat >"$dir/s.json" <<'JSON'
{"study": "s", "title": "t", "cpu": "c", "charts": [{"id": "a", "title": "t", "x_label": "x",
 "y_label": "y", "x_log": false, "y_log": false, "kind": "line", "reading": "r"}]}
JSON
printf 'chart,series,x,y\nb,s,1,2\n' >"$dir/s.csv"
expect "s.csv: no points for chart a"
printf 'chart,series,x\n' >"$dir/s.csv"
expect "s.csv:1: expected the header chart,series,x,y"
printf 'chart,series,x,y,label\na,s,1,2\n' >"$dir/s.csv"
expect "s.csv:2: 4 fields, expected 5"
echo "plot_atlas.py rejects bad input"
