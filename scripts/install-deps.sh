#!/usr/bin/env bash
# Installs the Debian 12 packages bookspin needs, only those that are missing.
# Uses sudo when not root. Safe to run repeatedly.
set -euo pipefail
packages=(
  build-essential cmake pkg-config git ca-certificates time ccache
  libeigen3-dev libtomlplusplus-dev libcli11-dev libboost-dev
  libepoxy-dev libegl-dev libegl-mesa0 libgl1-mesa-dri libgbm1
  libssl-dev libpng-dev libdeflate-dev pngcheck libcairo2-dev libfreetype-dev fonts-dejavu-core fonts-dejavu-extra
  libharfbuzz-dev libfribidi-dev fonts-droid-fallback fonts-symbola
  # names in every script on the class's projector (docs/class.md, "Names"): Noto for the
  # scripts DejaVu lacks (Devanagari and the other Indic scripts, Thai, …), CJK and colour emoji
  fonts-noto-core fonts-noto-cjk fonts-noto-color-emoji
  libassimp-dev libtinygltf-dev
  libavcodec-dev libavformat-dev libavutil-dev libswscale-dev libavfilter-dev ffmpeg
  libgtest-dev libbenchmark-dev libmujoco-dev libbullet-dev libode-dev
  libceres-dev libminizip-dev libutf8proc-dev dpkg-dev
  clang clang-format libclang-rt-14-dev
  chromium chromium-driver python3-selenium poppler-utils
  pybind11-dev python3-numpy python3-pytest python3-tqdm python3-pip python3-venv python3-setuptools
  python3-wheel jupyter-nbconvert python3-ipykernel python3-matplotlib
  python3-aiohttp python3-psycopg python3-segno python3-cryptography python3-psutil python3-idna
  postgresql-15
  # the school's reverse proxy in class/tests/test_class_school.py (docs/class.md, "A school's server")
  nginx-light
  slurm-wlm munge
  emscripten
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
# node and npm for the explorer page (web/package.json: three.js, esbuild) and the glTF browser
# test (tests/browser/package.json: the Khronos glTF-Validator, three.js). Debian's nodejs and
# npm, unless a node with npm is already installed another way (e.g. NodeSource's, which
# carries its own npm and conflicts with Debian's npm package).
if ! command -v npm >/dev/null 2>&1 || ! command -v node >/dev/null 2>&1; then
  for p in nodejs npm; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
  done
fi
install_web_packages() {
  # The explorer's pinned npm packages (web/package-lock.json), here in the install step so that
  # `make figures` downloads nothing; skipped when they are in place or npm is missing.
  local web
  web="$(cd "$(dirname "$0")/../web" && pwd)"
  if command -v npm >/dev/null 2>&1 &&
     { [ ! -d "$web/node_modules" ] || [ "$web/package-lock.json" -nt "$web/node_modules/.package-lock.json" ]; }; then
    (cd "$web" && npm ci --no-audit --no-fund --loglevel=error)
  fi
}
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
install_web_sources() {
  # The explorer's fit (the Phone-toss lab) compiles Ceres and minizip with zlib, and utf8proc
  # (a recording's name in any alphabet, src/common/file_name.hpp), for
  # WebAssembly from Debian's own source packages, the versions the native build links
  # (web/build-wasm-deps.sh): fetched here, in the install step, unpacked with Debian's patches
  # into web/deb-src/ (not in git). Skipped when they are in place or emscripten is missing.
  local web src
  web="$(cd "$(dirname "$0")/../web" && pwd)"
  src="$web/deb-src"
  command -v em++ >/dev/null 2>&1 || return 0
  # Complete when every package is in place (a checkout from before utf8proc fetches it now).
  if [ -f "$src/.complete" ]; then
    local have=1 p
    for p in ceres-solver minizip zlib utf8proc; do ls -d "$src/$p"-*/ >/dev/null 2>&1 || have=0; done
    [ "$have" = 1 ] && return 0
  fi
  # Debian's deb-src entries for bookworm, beside the machine's binary ones.
  if ! grep -rqsE '^(deb-src|Types:.*deb-src)' /etc/apt/sources.list /etc/apt/sources.list.d/; then
    printf '%s\n' 'Types: deb-src' 'URIs: http://deb.debian.org/debian' 'Suites: bookworm' \
      'Components: main' 'Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg' |
      $sudo tee /etc/apt/sources.list.d/bookspin-deb-src.sources >/dev/null
  fi
  $sudo apt-get update -qq
  rm -rf "$src"
  mkdir -p "$src"
  (cd "$src" && apt-get source -qq ceres-solver minizip zlib utf8proc 2>&1 | grep -v '^W: Download is performed unsandboxed' || true)
  for p in ceres-solver minizip zlib utf8proc; do
    ls -d "$src/$p"-*/ >/dev/null 2>&1 || { echo "install-deps: apt-get source $p failed" >&2; exit 1; }
  done
  rm -f "$src"/*.tar.* "$src"/*.dsc
  touch "$src/.complete"
}
if [ ${#missing[@]} -eq 0 ]; then
  install_web_packages
  install_web_sources
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
install_web_packages
install_web_sources
