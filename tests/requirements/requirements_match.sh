#!/usr/bin/env bash
# The table of docs/requirements.md shows exactly the package lists of tools/lib/deps.sh: one row
# for tools/demo and one per stage of tools/check (the stages its `stages=(...)` line names),
# each with the same packages. Every package in a list has its reason on its own line of
# deps.sh ("name  # why").
#
#   requirements_match.sh REPOSITORY_ROOT
# shellcheck source-path=SCRIPTDIR
# shellcheck disable=SC2016 # the backticks are Markdown's, matched literally
set -euo pipefail

root=$1
table="$root/docs/requirements.md"
deps="$root/tools/lib/deps.sh"
# shellcheck source=../../tools/lib/deps.sh
source "$deps"

failures=0
fail() {
  echo "FAIL: $*" >&2
  failures=$((failures + 1))
}

# The check's stages, from its one list.
stage_line=$(grep -E '^stages=\(' "$root/tools/check") || {
  echo "FAIL: no stages=(...) line in tools/check" >&2
  exit 1
}
read -r -a stages <<<"$(sed -E 's/^stages=\((.*)\)$/\1/' <<<"$stage_line")"
((${#stages[@]} > 0)) || fail "tools/check names no stages"

# The table's rows: "| <command> | `pkg` `pkg` ... |".
[[ -f $table ]] || fail "docs/requirements.md is missing"
declare -A table_packages
while IFS= read -r row; do
  command=$(cut -d'|' -f2 <<<"$row")
  packages=$(cut -d'|' -f3 <<<"$row")
  case $command in
    *'`tools/demo`'*) key=demo ;;
    *'`tools/check` stage `'*) key=$(sed -E 's/.*stage `([^`]*)`.*/\1/' <<<"$command") ;;
    *) continue ;;
  esac
  [[ -z ${table_packages[$key]+set} ]] || fail "docs/requirements.md has two rows for '$key'"
  table_packages[$key]=$({ grep -oE '`[^`]+`' <<<"$packages" || true; } | tr -d '`' | sort -u \
    | tr '\n' ' ')
done < <(grep -E '^\|' "$table")

# compare KEY PACKAGES...: the table's row KEY lists exactly PACKAGES.
compare() {
  local key=$1
  shift
  local listed
  listed=$(printf '%s\n' "$@" | sort -u | tr '\n' ' ')
  if [[ -z ${table_packages[$key]+set} ]]; then
    fail "docs/requirements.md has no row for '$key' (deps.sh lists: $listed)"
  elif [[ ${table_packages[$key]} != "$listed" ]]; then
    fail "'$key': docs/requirements.md lists '${table_packages[$key]}', tools/lib/deps.sh '$listed'"
  fi
  unset "table_packages[$key]"
}

compare demo "${EDGEWISE_DEMO_PACKAGES[@]}"
all_packages=("${EDGEWISE_DEMO_PACKAGES[@]}")
for stage in "${stages[@]}"; do
  if ! mapfile -t packages < <(edgewise_check_stage_packages "$stage") || ((${#packages[@]} == 0)); then
    fail "tools/lib/deps.sh has no package list for the check stage '$stage'"
    continue
  fi
  compare "$stage" "${packages[@]}"
  all_packages+=("${packages[@]}")
done
for key in "${!table_packages[@]}"; do
  fail "docs/requirements.md has a row for '$key', which is not tools/demo or a stage of tools/check"
done

# The fresh stage runs the check on the demo's root (tools/check_fresh_debian.sh): the check's
# stages there must list every package of the demo's list, or the check could pass on one that
# only the demo installed.
fresh_check_packages=$(for stage in host isa-objects install; do
  edgewise_check_stage_packages "$stage"
done | sort -u)
unlisted=$(comm -23 <(printf '%s\n' "${EDGEWISE_DEMO_PACKAGES[@]}" | sort -u) \
  <(printf '%s\n' "$fresh_check_packages"))
[[ -z $unlisted ]] || fail "tools/demo installs packages that the check's host, isa-objects" \
  "and install stages do not list: ${unlisted//$'\n'/ }"

# Each package's reason, beside it.
for package in $(printf '%s\n' "${all_packages[@]}" | sort -u); do
  if ! grep -qE "^[[:space:]]*${package//+/\\+}[[:space:]]+#[[:space:]]*[^[:space:]]" "$deps"; then
    fail "tools/lib/deps.sh gives no reason beside '$package' (\"$package  # why\")"
  fi
done

if ((failures > 0)); then
  exit 1
fi
echo "docs/requirements.md matches tools/lib/deps.sh: tools/demo and ${#stages[@]} check stages"
