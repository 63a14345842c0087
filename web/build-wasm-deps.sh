#!/usr/bin/env bash
# Builds the C and C++ libraries the explorer's fit (the Phone-toss lab, web/fit_bindings.cpp)
# links, for WebAssembly with Debian's emscripten, from Debian's own source packages (the
# versions the native build links; scripts/install-deps.sh fetches and unpacks them, Debian's
# patches applied, into web/deb-src/):
#   - zlib (inflate) and minizip (unzip.c, ioapi.c): the phyphox zip, read by the same
#     src/fit/recording_zip.cpp as the command line's;
#   - utf8proc (utf8proc.c with its tables): a recording's name in any alphabet, NFC and cut
#     at a whole character, by the same src/common/file_name.cpp as the command line's;
#   - Ceres: the same solver as the command line's, with its own small logging (miniglog,
#     FATAL only: the fit says what failed in its own line), no threads, no LAPACK, no sparse
#     libraries and no fixed-size Schur specializations (the fit's DENSE_SCHUR runs the
#     dynamic-size one), Eigen from Debian's headers.
# Into OUT/deps/prefix: lib/libceres.a, lib/libz.a, lib/libminizip.a, lib/libutf8proc.a and
# their headers.
# Nothing to do, nothing done: OUT/deps/inputs.sha256 holds the hash of this script and the
# source folders' names, written after a build.
# Usage: web/build-wasm-deps.sh OUT_DIR
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
[ $# -eq 1 ] || { echo "usage: web/build-wasm-deps.sh OUT_DIR" >&2; exit 2; }
mkdir -p "$1/deps"
deps="$(cd "$1/deps" && pwd)"
src="$here/deb-src"
command -v em++ >/dev/null || { echo "build-wasm-deps: em++ not found (apt-get install emscripten)" >&2; exit 3; }
for p in ceres-solver minizip zlib utf8proc; do
  ls -d "$src/$p"-*/ >/dev/null 2>&1 ||
    { echo "build-wasm-deps: $src/$p-*: missing (make deps: scripts/install-deps.sh fetches Debian's source)" >&2; exit 3; }
done
ceres_src="$(ls -d "$src"/ceres-solver-*/ | head -1)"
minizip_src="$(ls -d "$src"/minizip-*/ | head -1)"
zlib_src="$(ls -d "$src"/zlib-*/ | head -1)"
utf8proc_src="$(ls -d "$src"/utf8proc-*/ | head -1)"
export NODE_PATH="${NODE_PATH:-/usr/share/nodejs}"
# Debian's ccache in front of emscripten's clang where it is installed: unchanged files are not
# compiled again, in this build tree or a clone elsewhere (docs/performance.md, "CI").
if command -v ccache >/dev/null && [ -z "${EM_COMPILER_WRAPPER:-}" ]; then
  export EM_COMPILER_WRAPPER=ccache CCACHE_BASEDIR="$(dirname "$here")" CCACHE_NOHASHDIR=1
fi
stamp="$deps/inputs.sha256"
inputs=$( { sha256sum "$here/build-wasm-deps.sh"; echo "$ceres_src $minizip_src $zlib_src $utf8proc_src"; } | sha256sum | cut -d ' ' -f 1)
prefix="$deps/prefix"
if [ -f "$prefix/lib/libceres.a" ] && [ -f "$prefix/lib/libminizip.a" ] && [ -f "$prefix/lib/libutf8proc.a" ] && [ "$(cat "$stamp" 2>/dev/null)" = "$inputs" ]; then
  exit 0
fi
rm -rf "$deps/zlib" "$deps/minizip" "$deps/utf8proc" "$prefix" "$stamp"
mkdir -p "$deps/zlib" "$deps/minizip" "$deps/utf8proc" "$prefix/lib" "$prefix/include"

# zlib: the library's own C files (no gz* file I/O is used), as Debian's Makefile lists them.
objs=()
for name in adler32 crc32 inffast inflate inftrees zutil uncompr; do
  emcc -O2 -DNDEBUG -c "$zlib_src/$name.c" -o "$deps/zlib/$name.o"
  objs+=("$deps/zlib/$name.o")
done
emar rcs "$prefix/lib/libz.a" "${objs[@]}"
cp "$zlib_src/zlib.h" "$zlib_src/zconf.h" "$prefix/include/"

# minizip: the unzip side and its file API, as libminizip-dev's headers include them.
mkdir -p "$prefix/include/minizip"
for name in unzip ioapi; do
  emcc -O2 -DNDEBUG -DNOCRYPT -I"$prefix/include" -c "$minizip_src/$name.c" -o "$deps/minizip/$name.o"
  cp "$minizip_src/$name.h" "$prefix/include/minizip/"
done
emar rcs "$prefix/lib/libminizip.a" "$deps/minizip/unzip.o" "$deps/minizip/ioapi.o"

# utf8proc: its one C file (it includes its tables, utf8proc_data.c), static, as Debian builds it.
emcc -O2 -DNDEBUG -DUTF8PROC_STATIC -c "$utf8proc_src/utf8proc.c" -o "$deps/utf8proc/utf8proc.o"
emar rcs "$prefix/lib/libutf8proc.a" "$deps/utf8proc/utf8proc.o"
cp "$utf8proc_src/utf8proc.h" "$prefix/include/"

# Ceres: only the library (no tests, examples or benchmarks).
mkdir -p "$deps/ceres"
(cd "$deps/ceres" &&
  emcmake cmake "$ceres_src" -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX="$prefix" \
    -DMINIGLOG=ON -DMINIGLOG_MAX_LOG_LEVEL=-3 -DGFLAGS=OFF -DSUITESPARSE=OFF -DCXSPARSE=OFF \
    -DLAPACK=OFF -DCUDA=OFF -DEIGENSPARSE=OFF -DSCHUR_SPECIALIZATIONS=OFF \
    -DCERES_THREADING_MODEL=NO_THREADS -DBUILD_TESTING=OFF -DBUILD_EXAMPLES=OFF \
    -DBUILD_BENCHMARKS=OFF -DPROVIDE_UNINSTALL_TARGET=OFF -DEigen3_DIR=/usr/share/eigen3/cmake \
    -DCMAKE_FIND_ROOT_PATH_MODE_PACKAGE=BOTH -DCMAKE_CXX_FLAGS="-fexceptions" >/dev/null &&
  emmake make -j "${JOBS:-2}" ceres >/dev/null &&
  emmake make install >/dev/null)
echo "$inputs" > "$stamp"
echo "build-wasm-deps: $prefix/lib: libceres.a, libminizip.a, libz.a, libutf8proc.a"
