# Shared by scripts/report and scripts/test: install what the build needs, then configure and build.
# Sourced, not run. Debian 12 package names; nothing is downloaded outside apt.
set -euo pipefail

BALLBENCH_PACKAGES=(
  cmake g++ pkg-config
  libgtest-dev libgmock-dev libbenchmark-dev
  nlohmann-json3-dev libcli11-dev libtomlplusplus-dev libfmt-dev libeigen3-dev
  libbox2d-dev libbullet-dev libchipmunk-dev libode-dev libxxhash-dev
  gnuplot-nox python3 python3-pandas
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

# ballbench_build PRESET: configure and build with a CMake preset (see CMakePresets.json).
ballbench_build() {
  local preset=$1
  cmake --preset "$preset" >&2
  cmake --build --preset "$preset" -j "$(nproc)" >&2
}
