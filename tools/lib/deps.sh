# shellcheck shell=bash
# Makes sure the Debian packages a script needs are installed (sourced by tools/demo and
# tools/check).
#
# Missing packages are installed with apt-get when running as root. Otherwise the exact command
# to run is printed and the script stops, so nothing is built against a half-installed system.

# Packages every build needs: compilers, the build system and xsimd (the library's only dependency).
# shellcheck disable=SC2034 # used by the scripts that source this file
EDGEWISE_BUILD_PACKAGES=(build-essential cmake ninja-build libxsimd-dev)

# Prints the packages among "$@" that dpkg does not report as installed.
edgewise_missing_packages() {
  local package status
  for package in "$@"; do
    status=$(dpkg-query --show --showformat='${db:Status-Abbrev}' "$package" 2>/dev/null || true)
    [[ $status == ii* ]] || printf '%s\n' "$package"
  done
}

# Installs the packages among "$@" that are missing, or explains how and returns non-zero.
edgewise_require_packages() {
  if [[ ${EDGEWISE_SKIP_PACKAGE_CHECK:-0} == 1 ]]; then
    return 0
  fi
  if ! command -v dpkg-query >/dev/null; then
    echo "error: dpkg-query not found; these scripts install Debian 12 packages:" >&2
    echo "  $*" >&2
    echo "Install the equivalents and rerun with EDGEWISE_SKIP_PACKAGE_CHECK=1." >&2
    return 1
  fi

  local missing
  mapfile -t missing < <(edgewise_missing_packages "$@")
  if ((${#missing[@]} == 0)); then
    return 0
  fi

  local install=(apt-get install -y --no-install-recommends "${missing[@]}")
  if ((EUID != 0)); then
    echo "error: missing Debian packages: ${missing[*]}" >&2
    echo "Install them with:" >&2
    echo "  sudo apt-get update && sudo ${install[*]}" >&2
    return 1
  fi

  echo "Installing missing packages: ${missing[*]}"
  apt-get update
  DEBIAN_FRONTEND=noninteractive "${install[@]}"
}
