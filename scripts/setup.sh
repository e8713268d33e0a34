#!/usr/bin/env bash
# Installs the Debian packages ssfx needs. Idempotent; quiet when everything is present.
set -euo pipefail

PACKAGES=(
  cmake g++ make pkg-config          # build
  libgtest-dev libgmock-dev libbenchmark-dev   # tests, microbenchmarks
  libtbb-dev                         # threads (oneTBB)
  libhwy-dev                         # SIMD (Google Highway)
  libpng-dev zlib1g-dev              # PNG / APNG
  libcairo2-dev fonts-dejavu-core fontconfig   # test images (aliased vector drawing, real text)
  libcli11-dev nlohmann-json3-dev libfmt-dev   # CLI, JSON, formatting
  clang libclang-rt-14-dev           # libFuzzer targets (fuzz smoke run in make test)
)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "setup: installing ${missing[*]}" >&2
SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
