#!/usr/bin/env bash
# tools/check's `fresh` stage: proves that tools/demo and tools/check install every Debian
# package they use. One minimal Debian 12 root (debootstrap --variant=minbase: the essential
# packages and apt, nothing else), chrooted, as root, in a network namespace whose only way out
# is a relay to the package mirror, runs:
#   1. tools/demo, as the root's first command; it must exit 0 and write its images;
#   2. then, with the demo's sources, build, images and caches removed (its packages stay),
#      tools/check with EDGEWISE_CHECK_STAGES=host,isa-objects,install: the Release build, the
#      whole suite and the installed package (tools/check runs these stages here rather than on
#      the machine itself when its fresh stage runs).
# The check's stages list every package the demo's list names (the script refuses to start
# otherwise), so everything on the root when the check starts is something the check installs
# itself: one root proves both lists, and its packages are installed once.
# The root mounts the compiler cache (tools/lib/ccache.sh), so the check's build reuses the
# demo's objects: a compile hits only when every header it reads is there with the same bytes.
# A command that uses a package it did not install fails there: a program is missing, or CMake
# stops at configure time (both commands configure with EDGEWISE_STRICT_DEPENDENCIES, so no
# missing library silently leaves out a tool or a test).
#
#   tools/check_fresh_debian.sh WORK_DIR
#
# WORK_DIR holds the root while it runs (about 4 GB). It is emptied first, and again at the end
# when both commands pass; after a failed command the root stays there to look into
# (chroot WORK_DIR/root).
#
# The minimal root is built once and kept as a tarball in the cache folder, with the package
# files the root downloaded (apt's archive folder): later runs unpack it in seconds, and apt-get
# still installs every package from the mirror's current index. A tarball older than 30 days is
# built again.
#
# Environment:
#   EDGEWISE_CACHE_DIR               the cache (default ${XDG_CACHE_HOME:-$HOME/.cache}/edgewise)
#   EDGEWISE_DEBIAN_MIRROR           the archive (default http://deb.debian.org/debian)
#   EDGEWISE_DEBIAN_SECURITY_MIRROR  security updates (default http://deb.debian.org/debian-security)
#                                    Both plain http: the root has no CA certificates, and apt
#                                    checks the archive's signatures itself.
#   EDGEWISE_FRESH_REFRESH=1         build the root again instead of using the cached tarball
#   EDGEWISE_FRESH_CHECK_STAGES      tools/check's stages in its root (default
#                                    host,isa-objects,install)
#   EDGEWISE_FRESH_COUNTS_FILE       where to copy that check's "passed skipped failed" counts
#   EDGEWISE_JOBS                    passed on to both commands when set
# shellcheck source-path=SCRIPTDIR
set -euo pipefail

suite=bookworm
mirror=${EDGEWISE_DEBIAN_MIRROR:-http://deb.debian.org/debian}
security_mirror=${EDGEWISE_DEBIAN_SECURITY_MIRROR:-http://deb.debian.org/debian-security}

# Prints "host port" of an http:// URL, or fails.
url_host_port() {
  if [[ ! $1 =~ ^http://([^/:]+)(:([0-9]+))?(/.*)?$ ]]; then
    echo "error: '$1' is not an http:// mirror URL" >&2
    return 1
  fi
  echo "${BASH_REMATCH[1]} ${BASH_REMATCH[3]:-80}"
}

# Inside the root's own mount and network namespaces (the script runs itself there through
# unshare): loopback, relays to the host's side of each mirror relay, the kernel file systems,
# the shared package and compiler caches, then the command, chrooted, with a clean environment.
#   --inside ROOTFS ARCHIVES CCACHE RELAYS ENV... -- COMMAND...
# RELAYS is "address:port:socket ..."; ENV holds NAME=VALUE words for the command.
if [[ ${1:-} == --inside ]]; then
  rootfs=$2 archives=$3 compiler_cache=$4 relays=$5
  shift 5
  environment=()
  while [[ $1 != -- ]]; do
    environment+=("$1")
    shift
  done
  shift

  trap 'kill $(jobs -p) 2>/dev/null || true' EXIT
  ip link set lo up
  for relay in $relays; do
    IFS=: read -r address port socket <<<"$relay"
    socat "TCP-LISTEN:$port,bind=$address,reuseaddr,fork" "UNIX-CONNECT:$socket" &
  done
  for relay in $relays; do
    IFS=: read -r address port _ <<<"$relay"
    for _ in $(seq 50); do
      ss -Hltn "src $address:$port" | grep -q . && break
      sleep 0.1
    done
  done

  mount -t proc proc "$rootfs/proc"
  mount -t sysfs -o ro sysfs "$rootfs/sys"
  mount -t tmpfs -o mode=1777 tmpfs "$rootfs/dev/shm"
  mount --bind /dev/pts "$rootfs/dev/pts"
  mount --bind "$archives" "$rootfs/var/cache/apt/archives"
  mkdir -p "$rootfs/root/.cache/edgewise/ccache"
  mount --bind "$compiler_cache" "$rootfs/root/.cache/edgewise/ccache"

  set +e
  chroot "$rootfs" /usr/bin/env -i PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
    HOME=/root LANG=C.UTF-8 TERM="${TERM:-dumb}" "${environment[@]}" \
    /bin/bash -c 'cd /root/edgewise && exec "$@"' command "$@"
  exit $?
fi

if (($# != 1)); then
  echo "usage: $0 WORK_DIR" >&2
  exit 2
fi
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
work=$(mkdir -p "$1" && cd "$1" && pwd)
self="$root/tools/check_fresh_debian.sh"
cache=${EDGEWISE_CACHE_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/edgewise}

if ((EUID != 0)); then
  echo "error: the fresh stage runs debootstrap and chroot, which need root;" \
    "skip it with EDGEWISE_CHECK_SKIP=fresh" >&2
  exit 1
fi

# Every mount the stage makes lives in a private mount namespace and vanishes with it, so a root
# is plain files to this side. Refuse to delete one that something else has mounted into.
remove_tree() {
  local mounted
  mounted=$(findmnt --raw --noheadings --output TARGET | grep -F "$1/" || true)
  if [[ -n $mounted ]]; then
    echo "error: not deleting $1: something is mounted below it:" >&2
    echo "$mounted" >&2
    return 1
  fi
  rm -rf "$1"
}

# The check runs on the root after the demo, so its stages must list every package the demo's
# list names: otherwise it could pass on a package that only the demo installed.
# shellcheck source=lib/deps.sh
source "$root/tools/lib/deps.sh"
check_stages=${EDGEWISE_FRESH_CHECK_STAGES:-host,isa-objects,install}
unlisted=$(comm -23 <(printf '%s\n' "${EDGEWISE_DEMO_PACKAGES[@]}" | sort -u) \
  <(for stage in ${check_stages//,/ }; do edgewise_check_stage_packages "$stage"; done | sort -u))
if [[ -n $unlisted ]]; then
  echo "error: tools/demo installs packages that tools/check's stages $check_stages do not list" \
    "(tools/lib/deps.sh): ${unlisted//$'\n'/ }; the check would not prove its own list on the" \
    "demo's root" >&2
  exit 1
fi

now() { date +%s; }
elapsed() { printf '%d min %02d s' $((($(now) - $1) / 60)) $((($(now) - $1) % 60)); }

remove_tree "$work"
mkdir -p "$work" "$cache/apt-archives" "$cache/ccache"
available_kb=$(df --output=avail -k "$work" | tail -n 1)
if ((available_kb < 8 * 1024 * 1024)); then
  echo "error: $((available_kb / 1024)) MB free under $work; the fresh stage needs 8 GB" >&2
  exit 1
fi

# The minimal root, from the cache or built anew.
arch=$(dpkg --print-architecture)
tarball="$cache/debian-$suite-minbase-$arch.tar.gz"
if [[ ${EDGEWISE_FRESH_REFRESH:-0} == 1 ]] || [[ -z $(find "$tarball" -mtime -30 2>/dev/null) ]]; then
  start=$(now)
  echo "Building a minimal Debian root with debootstrap (cached in $tarball)"
  # In a mount namespace of its own, so nothing debootstrap mounts can outlive it.
  unshare --mount --fork -- debootstrap --variant=minbase --arch="$arch" "$suite" \
    "$work/debootstrap" "$mirror"
  tar -C "$work/debootstrap" --numeric-owner -czf "$tarball.partial" .
  mv "$tarball.partial" "$tarball"
  remove_tree "$work/debootstrap"
  echo "Built the root in $(elapsed "$start")"
else
  echo "Minimal Debian root: $tarball (built $(date -r "$tarball" +%F))"
fi

# The relays: on this side, a Unix socket per mirror host that forwards to that host and nowhere
# else; in the root's namespace, a loopback address per host that the root's /etc/hosts gives the
# host's name.
declare -A relay_address
relays="" hosts_lines="" index=0
for url in "$mirror" "$security_mirror"; do
  host_port=$(url_host_port "$url")
  read -r host port <<<"$host_port"
  [[ -n ${relay_address[$host:$port]:-} ]] && continue
  address="127.0.0.$((10 + index))" socket="$work/relay-$index.sock"
  relay_address[$host:$port]=$address
  socat "UNIX-LISTEN:$socket,fork,unlink-early,mode=600" "TCP:$host:$port" &
  relays+="$address:$port:$socket "
  hosts_lines+="$address $host"$'\n'
  index=$((index + 1))
done
trap 'kill $(jobs -p) 2>/dev/null || true' EXIT

# The sources a fresh installation of Debian 12 lists.
sources_list="deb $mirror $suite main
deb $mirror $suite-updates main
deb $security_mirror $suite-security main
"

# Copies the working tree (what git tracks or would, without the build folders) to $1.
copy_sources() {
  mkdir -p "$1"
  if git -C "$root" rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    git -C "$root" ls-files -z --cached --others --exclude-standard \
      | while IFS= read -r -d '' file; do
        [[ -e $root/$file ]] && printf '%s\0' "$file"
      done \
      | tar -C "$root" --null --files-from=- -cf - | tar -C "$1" -xf -
  else
    tar -C "$root" --exclude='./build*' --exclude=./out --exclude=./.git -cf - . \
      | tar -C "$1" -xf -
  fi
}

# Prints the packages installed on the root $1, sorted.
installed_packages() {
  # shellcheck disable=SC2016 # dpkg-query's format, not the shell's
  chroot "$1" dpkg-query --show --showformat='${Package}\n' | sort
}

# make_root ROOTFS: a new minimal root in ROOTFS, from the tarball, set up to reach the mirror
# through the relays, with the working tree in /root/edgewise.
make_root() {
  local rootfs=$1
  mkdir -p "$rootfs"
  tar -C "$rootfs" --numeric-owner -xzf "$tarball"
  printf '%s' "$sources_list" >"$rootfs/etc/apt/sources.list"
  printf '127.0.0.1 localhost\n%s' "$hosts_lines" >"$rootfs/etc/hosts"
  rm -f "$rootfs/etc/resolv.conf"
  # No services start in a chroot (as in Debian's container images): packages that ship one
  # install without trying, and without invoke-rc.d's warning.
  printf '#!/bin/sh\nexit 101\n' >"$rootfs/usr/sbin/policy-rc.d"
  chmod 755 "$rootfs/usr/sbin/policy-rc.d"
  # dpkg as in Debian's slim container images: no fsync after each file (the root is thrown
  # away, so a crash loses nothing worth keeping), and no manuals, documentation or translations,
  # which nothing here reads.
  cat >"$rootfs/etc/dpkg/dpkg.cfg.d/edgewise-fresh-root" <<'DPKG'
force-unsafe-io
path-exclude=/usr/share/man/*
path-exclude=/usr/share/doc/*
path-exclude=/usr/share/info/*
path-exclude=/usr/share/locale/*
DPKG
  copy_sources "$rootfs/root/edgewise"
}

# clear_home ROOTFS: removes what a command left in root's home and /tmp (the sources, builds,
# images and caches), so the next command starts from the working tree alone; the installed
# packages stay.
clear_home() {
  local rootfs=$1 entry
  for entry in "$rootfs"/root/{,.}* "$rootfs"/tmp/{,.}*; do
    [[ ${entry##*/} == . || ${entry##*/} == .. || ! -e $entry ]] && continue
    remove_tree "$entry"
  done
  copy_sources "$rootfs/root/edgewise"
}

# run_in_root NAME ROOTFS ENV... -- COMMAND...: COMMAND in /root/edgewise of ROOTFS.
run_in_root() {
  local name=$1 rootfs=$2
  shift 2
  local start
  start=$(now)
  installed_packages "$rootfs" >"$work/$name.before"

  echo
  echo "==== fresh: $name on the Debian 12 root $rootfs"
  local status=0
  unshare --mount --net --fork -- "$self" --inside "$rootfs" "$cache/apt-archives" \
    "$cache/ccache" "$relays" "$@" || status=$?

  installed_packages "$rootfs" >"$work/$name.after"
  local installed
  installed=$(comm -13 "$work/$name.before" "$work/$name.after" | wc -l)
  echo "==== fresh: $name exited with status $status after $(elapsed "$start");" \
    "it installed $installed packages on a root of $(wc -l <"$work/$name.before")"
  return "$status"
}

# Checks the demo's images: each named file, and a textured one per filter, begins with PNG's
# signature.
check_demo_images() {
  local out="$1/root/edgewise/out" image signature count=0
  for image in "$out/edgewise-render.png" "$out/edgewise-demo.png" "$out"/textured-*.png; do
    signature=$(od -An -tx1 -N8 "$image" 2>/dev/null | tr -d ' \n' || true)
    if [[ $signature != 89504e470d0a1a0a ]]; then
      echo "error: the demo did not write the PNG image $image" >&2
      return 1
    fi
    count=$((count + 1))
  done
  if ((count < 3)); then
    echo "error: the demo wrote no textured-<filter>.png image in $out" >&2
    return 1
  fi
  echo "fresh: the demo wrote $count PNG images"
}

jobs_env=()
[[ -n ${EDGEWISE_JOBS:-} ]] && jobs_env=("EDGEWISE_JOBS=$EDGEWISE_JOBS")
stage_start=$(now)
rootfs="$work/root"
make_root "$rootfs"

run_in_root demo "$rootfs" "${jobs_env[@]}" -- tools/demo
check_demo_images "$rootfs"
clear_home "$rootfs"

counts=/root/edgewise/.check-counts
run_in_root check "$rootfs" "${jobs_env[@]}" "EDGEWISE_CHECK_STAGES=$check_stages" \
  "EDGEWISE_CHECK_COUNTS_FILE=$counts" -- tools/check
if [[ -n ${EDGEWISE_FRESH_COUNTS_FILE:-} ]]; then
  cp "$rootfs$counts" "$EDGEWISE_FRESH_COUNTS_FILE"
fi

remove_tree "$work"
echo "fresh: tools/demo, then tools/check, passed on a fresh Debian 12 root in $(elapsed "$stage_start")"
