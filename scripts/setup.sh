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
  libopenexr-dev                     # float buffers (depth, AO) as EXR
  libvulkan-dev glslc mesa-vulkan-drivers vulkan-validationlayers   # scene renderer (lavapipe on CPU)
  libassimp-dev libstb-dev libglm-dev  # scene import, textures, vector math
  libembree-dev                      # ray-traced AO ground truth
  libcli11-dev nlohmann-json3-dev libfmt-dev   # CLI, JSON, formatting
  clang libclang-rt-14-dev           # libFuzzer targets (fuzz smoke run in make test)
  clang-format-14                    # the formatting check (.clang-format is pinned to 14)
  chromium                           # the HTML report's browser test (headless, via playwright-core)
  ffmpeg                             # the frame-pipe test (ffmpeg | ssfx aa --raw | ffmpeg)
  pybind11-dev python3-dev python3-numpy python3-pytest   # the Python module and its tests
  python3-matplotlib python3-dask python3-distributed     # its examples (a plot; a Dask cluster)
)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# Node.js and npm: any installation will do (Debian's packages only when there is none).
command -v node >/dev/null && command -v npm >/dev/null || missing+=(nodejs npm)

if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}" >&2
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# playwright-core for the report test, pinned by tests/report/package-lock.json (it drives
# Debian's chromium; no browser download).
REPORT_TEST="$(cd "$(dirname "$0")/.." && pwd)/tests/report"
if [ ! -d "$REPORT_TEST/node_modules/playwright-core" ]; then
  echo "setup: npm ci in tests/report" >&2
  (cd "$REPORT_TEST" && PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1 npm ci --no-audit --no-fund --loglevel=error >/dev/null)
fi
