#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Builds the .deb of BUILD_DIR (cmake/BenchScopePackaging.cmake), unpacks it into a scratch root with dpkg -x and
# runs the installed CLI from there: --version, devices (resources found next to the installed binary, not in the
# source tree) and a short run flops checked against the closed form.
#   usage: test_deb_package.sh BUILD_DIR [PACKAGE [RUNNER]]
#   PACKAGE: benchscope-cli (default; a -DBENCHSCOPE_GUI=OFF build: must not depend on Qt) or benchscope (the GUI's)
#   RUNNER: e.g. "qemu-aarch64 -L /usr/aarch64-linux-gnu" for a cross build's package (the arm64 hook, docs/robot.md)
set -euo pipefail
build=$(cd "$1" && pwd)
package=${2:-benchscope-cli}
runner=${3:-}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "test_deb_package: $*" >&2; exit 1; }

cpack --config "$build/CPackConfig.cmake" -G DEB -B "$work/out" >"$work/cpack.log" 2>&1 ||
  { cat "$work/cpack.log" >&2; fail "cpack failed"; }
debs=("$work"/out/"$package"_*.deb)
[ -f "${debs[0]}" ] || fail "no ${package}_*.deb in: $(ls "$work/out")"
deb=${debs[0]}
echo "package: $(basename "$deb")"
[ "$(dpkg-deb -f "$deb" Package)" = "$package" ] || fail "Package is not $package"
arch=$(dpkg-deb -f "$deb" Architecture)
echo "Architecture: $arch"
if [[ "$runner" == *aarch64* ]] && [ "$arch" != arm64 ]; then fail "a package run under qemu-aarch64 is $arch, not arm64"; fi
depends=$(dpkg-deb -f "$deb" Depends)
echo "Depends: $depends"
# dpkg-shlibdeps filled in the libraries the binaries link; the robot's package has no Qt.
grep -q "libopencv" <<<"$depends" || fail "Depends lacks OpenCV: $depends"
grep -q "libsqlite3" <<<"$depends" || fail "Depends lacks SQLite: $depends"
# Loaded on first use (core/image_files), so named by cmake/BenchScopePackaging.cmake rather than dpkg-shlibdeps.
grep -q "libopencv-imgcodecs" <<<"$depends" || fail "Depends lacks OpenCV's imgcodecs: $depends"
if [ "$package" = benchscope-cli ] && grep -qi "qt" <<<"$depends"; then fail "benchscope-cli depends on Qt: $depends"; fi
# The listing goes to a file: grep -q closing a pipe early would kill dpkg-deb (SIGPIPE) and fail under pipefail.
dpkg-deb -c "$deb" >"$work/contents"
if [ "$package" = benchscope ]; then
  grep -q "libqt6" <<<"$depends" || fail "the GUI package does not depend on Qt 6: $depends"
  grep -q "\./usr/bin/benchscope$" "$work/contents" || fail "no usr/bin/benchscope in the GUI package"
fi
grep -q "\./usr/bin/benchscope-cli$" "$work/contents" || fail "no usr/bin/benchscope-cli in the package"
grep -q "\./usr/share/benchscope/resources/devices/cpu-cores.json$" "$work/contents" || fail "resources not packaged"
# The library's numbers are packaged; its kept sources, third-party files, never are (docs/third-party-data.md).
grep -q "\./usr/share/benchscope/resources/library/library.json$" "$work/contents" || fail "library.json not packaged"
if grep -q "/resources/library/sources/" "$work/contents"; then fail "third-party kept sources are packaged"; fi

dpkg -x "$deb" "$work/root"
cli="$work/root/usr/bin/benchscope-cli"
[ -x "$cli" ] || fail "no usr/bin/benchscope-cli in the package"
run() { env -u BENCHSCOPE_RESOURCE_DIR $runner "$cli" "$@"; }

run --version | tee "$work/version"
grep -q "^benchscope-cli " "$work/version" || fail "--version printed no version"
# The device table comes from the unpacked package, not from the source tree this build was configured from.
run devices --table >"$work/table"
head -1 "$work/table"
grep -qF "$work/root/usr/share/benchscope/resources/devices/devices.json" "$work/table" ||
  fail "devices --table did not read the installed resources: $(head -1 "$work/table")"
run devices >"$work/devices"
grep -q "^cpu-simd: " "$work/devices" || fail "devices lists no cpu-simd backend"
run run flops --backend cpu-simd --points 1,4 --iterations 200000 --workers 2 --repeats 1 --json >"$work/run.json" ||
  fail "run flops failed"
grep -q '"benchscope-run"' "$work/run.json" || fail "run flops printed no benchscope-run JSON"
# The library from the package alone: its results with URL and lines, and where a kept copy would be.
run library show mlperf-v3.0-orin_trt_maxq-resnet50-singlestream >"$work/library" || fail "library show failed"
grep -q "source: *https://github.com/mlcommons/inference_results_v3.0/" "$work/library" ||
  fail "library show gave no URL: $(cat "$work/library")"
grep -q "line 7: *90th percentile latency" "$work/library" || fail "library show gave no line: $(cat "$work/library")"
# An image file written and read back by the installed CLI: OpenCV's imgcodecs is loaded on first use
# (core/image_files), found by its soname where the package's Depends put it.
run synth-frame --out "$work/frame" --size 64x48 >/dev/null || fail "synth-frame (writes a PNG) failed"
[ -s "$work/frame-truth.png" ] || fail "synth-frame wrote no PNG"
run import "$work/frames.bsw" "$work/frame-truth.png" --quiet || fail "importing the PNG it wrote failed"
echo "test_deb_package: installed CLI ran (--version, devices, run flops, library show, a PNG written and read)"
