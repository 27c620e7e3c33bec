#!/usr/bin/env bash
# Builds the fuzz targets of the tool's readers with clang (libFuzzer, AddressSanitizer,
# UndefinedBehaviorSanitizer) and runs each for a fixed number of executions on a copy of the
# seed corpus (test/fuzz/corpus: one small valid or nearly valid file per format; add every
# crash found later). Exits non-zero on the first crash, leaking or sanitizer report; the
# input is left in the output folder as crash-* / leak-*.
#
# Then the differential fuzzer of the tiled runs (fuzz_tiles.py) on the built tool TOOL:
# TILE_CASES adversarial clouds, each run whole, with --threads 1 and in tiles at two memory
# limits, which must agree byte for byte, exit 0, 2 or 3, and end within 30 s (a hang or a
# pathological tiling: a run takes about 0.1 s, and this one runs beside a sanitizer build on
# 2 cores, so a wall-time bound near that would flake); a failing case is left in
# OUT/tiles/failure-1.
#
#   test/fuzz/run_fuzzers.sh [EXECUTIONS=200000] [OUT=build-fuzz] [TOOL=build/tools/point_set_curvatures] [TILE_CASES=250]
#
# Needs clang++ and Debian's libclang-rt-14-dev (the fuzzer runtime), python3, and the tool
# built (target point_set_curvatures_tool).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
repo="$(cd "$here/../.." && pwd)"
runs="${1:-200000}"
out="${2:-$repo/build-fuzz}"
tool="${3:-$repo/build/tools/point_set_curvatures}"
tile_cases="${4:-250}"
mkdir -p "$out"
out="$(cd "$out" && pwd)"
if [ ! -x "$tool" ]; then
  echo "run_fuzzers.sh: no tool at $tool: build the target point_set_curvatures_tool first" >&2
  exit 1
fi
tool="$(cd "$(dirname "$tool")" && pwd)/$(basename "$tool")"  # (the script changes folder below)
clang++ -std=c++17 -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
  "$here/fuzz_readers.cpp" "$repo/io/src/read_point_cloud.cpp" "$repo/io/src/read_ply.cpp" "$repo/io/src/read_las.cpp" \
  -I "$repo/io/include" -o "$out/fuzz_readers"
rm -rf "$out/corpus"
cp -r "$here/corpus" "$out/corpus"
cd "$out"
start=$(date +%s)
./fuzz_readers -runs="$runs" -max_len=4096 -timeout=10 -rss_limit_mb=1024 corpus 2> fuzz_readers.log || {
  tail -40 fuzz_readers.log >&2
  echo "fuzz_readers found a crash: see $out" >&2
  exit 1
}
end=$(date +%s)
grep -E "^#[0-9]+.*(DONE|pulse)" fuzz_readers.log | tail -1 >&2 || true
echo "fuzz_readers: $runs executions in $((end - start)) s, no crash" >&2

python3 "$here/fuzz_tiles.py" --tool "$tool" --cases "$tile_cases" --out "$out/tiles" --timeout 30 || {
  echo "fuzz_tiles found a difference between whole and tiled runs: see $out/tiles" >&2
  exit 1
}
