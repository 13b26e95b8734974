#!/usr/bin/env bash
# Installs everything the project needs to build and test, from Debian 12 packages.
set -euo pipefail
packages=(
  cmake ninja-build g++ pkg-config
  libtbb-dev libopenmesh-dev libspdlog-dev
  libprotobuf-dev protobuf-compiler
  libgtest-dev libgmock-dev libbenchmark-dev
  libgmp-dev libabsl-dev
  coinor-libcbc-dev
  libgrpc++-dev protobuf-compiler-grpc grpc-proto libssl-dev libcli11-dev
  python3-grpcio python3-protobuf
  zlib1g-dev chromium
  libocct-data-exchange-dev libocct-modeling-algorithms-dev libocct-modeling-data-dev libocct-foundation-dev
  libopenmpi-dev openmpi-bin
  libembree-dev
)
# Node.js and npm build the HTML report's script (service/report/web); machines that
# already have them (from NodeSource, say) keep theirs.
command -v node >/dev/null || packages+=(nodejs)
command -v npm >/dev/null || packages+=(npm)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
