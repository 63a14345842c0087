#!/usr/bin/env bash
# The GPU check (docs/performance-render.md, "The GPU check"): the Release build packed with every
# shared library it loads, then, on a machine with a GPU, `bookspin info`, the picture tests and
# the pipeline bench in one call, each one's output kept.
#
#   scripts/gpu-check.sh pack [BUNDLE]   on the machine that built build/ (Debian 12): copies
#                                        bookspin, bookspin-bench and build/tests/picture_tests
#                                        with the libraries ldd lists (glibc's loader and libc
#                                        excepted) and Debian's glvnd libEGL into BUNDLE
#                                        (default build/gpu-bundle), and BUNDLE.tar.xz beside
#                                        it; no fonts: the programs carry their own.
#   scripts/gpu-check.sh run [BUNDLE] [OUT]
#                                        on the GPU machine, from a checkout of the same commit:
#                                        runs the three with the bundle's libraries before the
#                                        system's and NVIDIA's EGL vendor file where there is
#                                        one; writes OUT/info.txt, OUT/picture-tests.txt (a failing
#                                        frame's actual, expected and diff PNGs at the paths it
#                                        names), OUT/bench.txt with OUT/bench/, and OUT/summary.txt
#                                        (the GL renderer, the text's faces and options as
#                                        `bookspin info` names them, what passed).
#                                        Exit 0 when all three exited 0.
#
# The test programs find the goldens and scenes at the source folder compiled into them (the
# build machine's checkout, read from the program's compiled-in path, or GPU_CHECK_SOURCE_DIR);
# where that path does not exist on the GPU machine, `run` links it to this checkout (or says
# what to link), whose build/ must hold the carried build (a comparison's frames are rendered
# by build/bookspin). Nothing here needs the network.
set -uo pipefail
cd "$(dirname "$0")/.."
mode=${1:-}
bundle=${2:-build/gpu-bundle}
programs=(build/bookspin build/bookspin-bench build/tests/picture_tests)

# The libraries only FFmpeg's other codecs, filters and protocols call (docs/performance-render.md, "A
# GPU"): replaced in the bundle by stubs of the same name, symbols and versions, so that the
# bundle fits the 64 MiB a lent GPU machine takes. `run` compares `bookspin info` with the
# build's own, so a stub that bookspin reached would show.
stubbed='libx265|libcodec2|libflite[a-z0-9_]*|librsvg-2|libplacebo|libSvtAv1Enc|libaom|librav1e|libdav1d|libjxl[a-z_]*|libxml2|libicu[a-z]+|libopenmpt|libgme|libpocketsphinx|libchromaprint|libzvbi|libmysofa|librubberband|libbluray|libzmq|libssh-gcrypt|libsrt-gnutls|librabbitmq|libvidstab|libzimg|libxvidcore|libtwolame|libshine|libspeex|libgsm|libmfx|liblilv-0|libserd-0|libsord-0|libsratom-0|libopenmpt|libgdk_pixbuf-2.0|libOpenCL'

# stub_library LIB OUT: a library of the same SONAME, symbols and versions, every function an
# immediate return and every object zeros (for libraries that only FFmpeg's unused codecs call).
stub_library() {
  local lib=$1 out=$2 work soname
  work=$(mktemp -d)
  soname=$(objdump -p "$lib" | awk '/SONAME/ { print $2 }')
  readelf -W --dyn-syms "$lib" | awk -v asm="$work/stub.s" -v map="$work/stub.map" '
    $7 != "UND" && $7 != "ABS" && ($5 == "GLOBAL" || $5 == "WEAK") && ($4 == "FUNC" || $4 == "OBJECT" || $4 == "IFUNC" || $4 == "NOTYPE") && NF >= 8 {
      name = $8; ver = ""
      if (index(name, "@@")) { split(name, p, "@@"); name = p[1]; ver = p[2] }
      else if (index(name, "@")) { next }
      if (name == "" || seen[name]++) next
      if (ver == name) next
      if ($4 == "OBJECT") {
        size = $3 + 0; if (size < 1) size = 1
        printf "  .bss\n  .globl \"%s\"\n  .type \"%s\", @object\n  .size \"%s\", %d\n\"%s\":\n  .zero %d\n", name, name, name, size, name, size > asm
      } else {
        printf "  .text\n  .globl \"%s\"\n  .type \"%s\", @function\n\"%s\":\n  xor %%eax, %%eax\n  ret\n", name, name, name > asm
      }
      if (ver != "") { vers[ver] = vers[ver] "    \"" name "\";\n" } else { base = base "    \"" name "\";\n" }
      any = 1
    }
    END {
      if (!any) printf "" > asm
      n = 0
      for (v in vers) { printf "%s {\n  global:\n%s};\n", v, vers[v] > map; n++ }
      if (n == 0) printf "" > map
      else if (base != "") printf "BASE_STUB {\n  global:\n%s};\n", base > map
    }'
  local vs=()
  [ -s "$work/stub.map" ] && vs=(-Wl,--version-script="$work/stub.map")
  gcc -shared -nostdlib -o "$out" "$work/stub.s" -Wl,-soname,"$soname" "${vs[@]}" || { rm -rf "$work"; return 1; }
  rm -rf "$work"
}

pack() {
  for p in "${programs[@]}"; do
    [ -x "$p" ] || { echo "gpu-check: $p is not built (cmake --build build --target bookspin bookspin-bench picture_tests)"; exit 2; }
  done
  rm -rf "$bundle" && mkdir -p "$bundle/bin" "$bundle/lib"
  cp "${programs[@]}" "$bundle/bin/"
  # Every library the three load, by ldd, but the C library and its loader (the GPU machine's
  # own must serve: they cannot be swapped under a running system's), and the GL vendor's.
  ldd "${programs[@]}" | awk '/=> \// { print $3 }' | sort -u |
    grep -Ev '/(libc|libm|libpthread|libdl|librt|ld-linux[^/]*)\.so' |
    grep -Ev '/libnvidia|/libcuda' |
    while read -r lib; do cp -L "$lib" "$bundle/lib/"; done
  # glvnd's libEGL (loaded through libepoxy by name, not linked) and Mesa's EGL vendor file, so
  # that llvmpipe stays the fallback where the GPU's vendor is missing.
  # libepoxy opens libOpenGL.so.0 (or libGL.so.1) by name too for the GL entry points: a GPU
  # machine's image may hold neither (a bare CUDA image held none, 2026-11-27).
  for lib in /usr/lib/x86_64-linux-gnu/libEGL.so.1 /usr/lib/x86_64-linux-gnu/libGLdispatch.so.0 \
             /usr/lib/x86_64-linux-gnu/libOpenGL.so.0 /usr/lib/x86_64-linux-gnu/libGL.so.1 \
             /usr/lib/x86_64-linux-gnu/libGLX.so.0; do
    [ -e "$lib" ] && cp -L "$lib" "$bundle/lib/"
  done
  local lib
  for lib in "$bundle"/lib/*; do
    if basename "$lib" | grep -Eq "^($stubbed)\.so"; then
      stub_library "$lib" "$lib.stub" && mv "$lib.stub" "$lib" || { echo "gpu-check: could not stub $lib"; exit 1; }
    fi
  done
  # The bundle's bookspin must say what the build's says (the stubs reach nothing it runs).
  if ! diff <(build/bookspin info 2>&1 | grep -v '^EGL\|^GL ') \
            <(LD_LIBRARY_PATH="$bundle/lib" "$bundle/bin/bookspin" info 2>&1 | grep -v '^EGL\|^GL '); then
    echo "gpu-check: the bundle's bookspin info differs from the build's (above)"; exit 1
  fi
  # No fonts and no fontconfig file: every text is drawn in the typeface stage's faces, built
  # into the programs with its options (docs/architecture.md), so the GPU machine's own font
  # set-up, whatever it is, reaches no frame.
  git rev-parse HEAD > "$bundle/commit" 2>/dev/null || true
  tar -C "$(dirname "$bundle")" -cJf "$bundle.tar.xz" "$(basename "$bundle")"
  echo "gpu-check: packed $(ls "$bundle/lib" | wc -l) libraries into $bundle.tar.xz ($(du -h "$bundle.tar.xz" | cut -f1))"
}

run() {
  local out=${3:-out/gpu-check}
  [ -d "$bundle" ] || { [ -f "$bundle.tar.xz" ] && tar -C "$(dirname "$bundle")" -xJf "$bundle.tar.xz"; }
  [ -x "$bundle/bin/bookspin" ] || { echo "gpu-check: no bundle at $bundle (scripts/gpu-check.sh pack)"; exit 2; }
  mkdir -p "$out"
  out=$(cd "$out" && pwd)
  local root
  root=$(cd "$bundle" && pwd)
  export LD_LIBRARY_PATH="$root/lib:/usr/local/nvidia/lib64:/usr/lib/x86_64-linux-gnu/nvidia${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
  for vendor in /usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json \
                /usr/share/glvnd/egl_vendor.d/10_nvidia.json; do
    if [ -f "$vendor" ]; then export __EGL_VENDOR_LIBRARY_FILENAMES=$vendor; break; fi
  done
  # The source folder compiled into the test programs: linked to this checkout if missing.
  local compiled
  # (tests/support/test_paths.hpp: the program's path, SOURCE/build/bookspin, is compiled in.)
  compiled=${GPU_CHECK_SOURCE_DIR:-$(strings "$root/bin/picture_tests" | grep -m1 -E '^/.*/build/bookspin$' | sed 's|/build/bookspin$||' || true)}
  if [ -n "$compiled" ] && [ ! -e "$compiled/tests/golden" ]; then
    mkdir -p "$(dirname "$compiled")" 2>/dev/null && ln -s "$PWD" "$compiled" 2>/dev/null ||
      echo "gpu-check: link $compiled to this checkout (ln -s $PWD $compiled): the picture tests read their goldens there"
  fi
  local info_rc pictures_rc bench_rc
  "$root/bin/bookspin" info > "$out/info.txt" 2>&1
  info_rc=$?
  mkdir -p "$out/picture"
  (cd "$out/picture" && "$root/bin/picture_tests") > "$out/picture-tests.txt" 2>&1
  pictures_rc=$?
  "$root/bin/bookspin-bench" --only pipeline resolution -o "$out/bench" > "$out/bench.txt" 2>&1
  bench_rc=$?
  {
    echo "commit: $(cat "$root/commit" 2>/dev/null || echo unknown)"
    grep -E 'EGL|GL renderer|GL version|anisotrop|^text ' "$out/info.txt"
    echo "bookspin info: exit $info_rc"
    grep -E '^\[  (PASSED|FAILED) +\]' "$out/picture-tests.txt"
    echo "picture tests: exit $pictures_rc"
    echo "pipeline bench: exit $bench_rc ($out/bench)"
  } | tee "$out/summary.txt"
  [ "$info_rc" -eq 0 ] && [ "$pictures_rc" -eq 0 ] && [ "$bench_rc" -eq 0 ]
}

case "$mode" in
  pack) pack ;;
  run) run "$@" ;;
  *)
    echo "usage: scripts/gpu-check.sh pack [BUNDLE] | run [BUNDLE] [OUT]"
    exit 2
    ;;
esac
