#!/usr/bin/env bash
# Installs the Debian 12 packages the project needs, if any are missing.
# As root it runs apt-get; otherwise it prints the exact apt-get line and stops.
# The optional packages (a single-host Slurm for the Slurm test, tests/slurm/)
# are installed as root too, without starting their services; when they cannot
# be installed the build goes on and that test is skipped.
set -euo pipefail

packages=(
  build-essential cmake pkg-config clang libclang-rt-dev
  libeigen3-dev libsuitesparse-dev libfftw3-dev libgsl-dev libhdf5-dev libspectra-dev
  libqhull-dev                                    # convex hulls (the minimal bounding box)
  nlohmann-json3-dev libgtest-dev libbenchmark-dev
  python3 python3-matplotlib python3-numpy python3-h5py python3-pil
  povray                                          # figures: the wires as shaded tubes
  libjs-three                                     # the data-set explorer (knots site)
  chromium chromium-driver python3-selenium       # the explorer's browser tests
  python3-dev python3-pybind11 python3-pytest     # the Python module (make python) and its tests
  doxygen                                         # the API reference (make docs)
  ffmpeg                                          # the animation of a jumping knot (make animation)
)
optional=(slurmctld slurmd slurm-client munge)

missing_of() {
  local p status
  for p in "$@"; do
    status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
    [[ "$status" == "install ok installed" ]] || echo "$p"
  done
}
mapfile -t missing < <(missing_of "${packages[@]}")
mapfile -t missing_optional < <(missing_of "${optional[@]}")

if [[ ${#missing[@]} -eq 0 && ${#missing_optional[@]} -eq 0 ]]; then
  exit 0
fi

if [[ $(id -u) -ne 0 ]]; then
  if [[ ${#missing[@]} -gt 0 ]]; then
    echo "Missing Debian packages. Install them with:" >&2
    echo "  sudo apt-get update && sudo apt-get install -y --no-install-recommends ${missing[*]}" >&2
    exit 1
  fi
  echo "Note: the Slurm test (make slurm-test) is skipped without: ${missing_optional[*]}" >&2
  exit 0
fi

export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
if [[ ${#missing[@]} -gt 0 ]]; then
  echo "Installing missing Debian packages: ${missing[*]}"
  apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
if [[ ${#missing_optional[@]} -gt 0 ]]; then
  echo "Installing the Slurm test's Debian packages: ${missing_optional[*]}"
  # The test starts its own daemons: keep the packages' services from starting
  # (a policy-rc.d that denies every start, present only during the install).
  guard=""
  if [[ ! -e /usr/sbin/policy-rc.d ]]; then
    guard=/usr/sbin/policy-rc.d
    printf '#!/bin/sh\nexit 101\n' > "$guard"
    chmod 755 "$guard"
    trap 'rm -f "$guard"' EXIT
  fi
  apt-get install -y -qq --no-install-recommends "${missing_optional[@]}" ||
    echo "Warning: could not install ${missing_optional[*]}; the Slurm test will be skipped" >&2
fi
