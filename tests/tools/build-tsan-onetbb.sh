#!/usr/bin/env bash
# Builds oneTBB under ThreadSanitizer for the `tsan` preset, once, outside the main build.
#
# Why: TSan only understands synchronization it has instrumented. Debian's libtbb12 is
# not, so an uninstrumented TBB makes every work-stealing hand-off look like a race. This
# builds the very sources Debian ships (onetbb 2021.8.0, the version of libtbb-dev in
# Debian 12, checked against the SHA-256 of Debian's archive) with -fsanitize=thread and
# installs them into a cache directory that the tsan preset points TBB_DIR at.
#
# Usage: tests/tools/build-tsan-onetbb.sh [PREFIX]
#   PREFIX defaults to ${GVM_TSAN_TBB:-$HOME/.cache/gvm/onetbb-2021.8.0-tsan}; nothing is
#   done when PREFIX already holds the build.
set -euo pipefail

version=2021.8.0
sha256=7e9111b8bb59c8800bf6d0b06afe7b0891937443d2dae1ee1101c8e2ede6a7ef
url=http://deb.debian.org/debian/pool/main/o/onetbb/onetbb_${version}.orig.tar.xz
prefix=${1:-${GVM_TSAN_TBB:-$HOME/.cache/gvm/onetbb-${version}-tsan}}

if [ -f "$prefix/lib/cmake/TBB/TBBConfig.cmake" ]; then
  echo "instrumented oneTBB already in $prefix"
  exit 0
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "fetching $url"
curl -sSfL -o "$work/onetbb.tar.xz" "$url"
echo "$sha256  $work/onetbb.tar.xz" | sha256sum -c --quiet
tar -xJf "$work/onetbb.tar.xz" -C "$work"
src=$(find "$work" -maxdepth 1 -type d -name 'oneTBB*' -o -maxdepth 1 -type d -name 'onetbb*' | head -1)

cmake -S "$src" -B "$work/build" -G Ninja \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS="-fsanitize=thread -fno-omit-frame-pointer" \
  -DCMAKE_C_FLAGS="-fsanitize=thread -fno-omit-frame-pointer" \
  -DCMAKE_EXE_LINKER_FLAGS=-fsanitize=thread \
  -DCMAKE_SHARED_LINKER_FLAGS=-fsanitize=thread \
  -DTBB_TEST=OFF -DTBB_EXAMPLES=OFF -DTBB_STRICT=OFF -DTBBMALLOC_BUILD=OFF \
  -DCMAKE_INSTALL_PREFIX="$prefix" >/dev/null
cmake --build "$work/build"
cmake --install "$work/build" >/dev/null
echo "instrumented oneTBB installed in $prefix"
