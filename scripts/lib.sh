# Shared by scripts/report and scripts/test: install what the build needs, then configure and build.
# Sourced, not run. Debian 12 package names; nothing is downloaded outside apt.
set -euo pipefail

BALLBENCH_PACKAGES=(
  cmake g++ pkg-config
  libgtest-dev libgmock-dev libbenchmark-dev
  nlohmann-json3-dev libcli11-dev libtomlplusplus-dev libfmt-dev libeigen3-dev
  libbox2d-dev libbullet-dev libchipmunk-dev libode-dev libxxhash-dev
  liblammps-dev lammps openmpi-bin
  gnuplot-nox python3 python3-pandas nodejs
  chromium
)

# CI only (.ci/run): clang and its runtime libraries for the libFuzzer target (tests/fuzz/). The
# sanitizer build uses g++, whose ASan and UBSan runtimes come with it.
BALLBENCH_CI_PACKAGES=(
  clang libclang-rt-14-dev
)

# ballbench_install_packages [PACKAGE...]: install the missing ones of the given packages
# (default: BALLBENCH_PACKAGES).
ballbench_install_packages() {
  local wanted=("$@") missing=()
  [ ${#wanted[@]} -eq 0 ] && wanted=("${BALLBENCH_PACKAGES[@]}")
  for p in "${wanted[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "installing Debian packages: ${missing[*]}" >&2
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
}

# ballbench_install_node_engines: the Node engines' packages (adapters/node/package-lock.json) by
# `npm ci`, skipped when that lock file is what was installed last. npm comes with NodeSource's
# nodejs; Debian's nodejs needs Debian's npm, installed only where no npm is found (it conflicts
# with NodeSource's). Without node, npm or the registry the build goes on: those engines are then
# listed as unavailable, with the reason.
ballbench_install_node_engines() {
  local dir stamp
  dir="$(dirname "${BASH_SOURCE[0]}")/../adapters/node"
  stamp="$dir/node_modules/.ballbench-installed"
  command -v npm >/dev/null || (ballbench_install_packages npm) || true
  if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
    echo "node or npm not found: the Node engines (adapters/node/) will be listed as unavailable" >&2
    return 0
  fi
  cmp -s "$dir/package-lock.json" "$stamp" && return 0
  echo "installing the Node engines' packages: npm ci in adapters/node" >&2
  if (cd "$dir" && npm ci --no-audit --no-fund --loglevel=error >&2); then
    cp "$dir/package-lock.json" "$stamp"
  else
    echo "npm ci failed in adapters/node: the Node engines will be listed as unavailable" >&2
  fi
}

# ballbench_build PRESET: configure and build with a CMake preset (see CMakePresets.json).
ballbench_build() {
  local preset=$1
  cmake --preset "$preset" >&2
  cmake --build --preset "$preset" -j "$(nproc)" >&2
}
