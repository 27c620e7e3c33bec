#!/usr/bin/env bash
# Line coverage of the readers (io/) by a fuzzing corpus (not run by CI): builds the fuzz
# target with clang's source-based coverage, runs it once over every file of CORPUS (for
# example the corpus grown by run_fuzzers.sh in OUT/corpus) and prints llvm-cov's report for
# io/src/read_*.cpp and io/src/input_bytes.h.
#
#   test/fuzz/coverage.sh [CORPUS=build-fuzz/corpus] [OUT=build-fuzz-coverage]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
repo="$(cd "$here/../.." && pwd)"
corpus="$(cd "${1:-$repo/build-fuzz/corpus}" && pwd)"
out="${2:-$repo/build-fuzz-coverage}"
mkdir -p "$out"
out="$(cd "$out" && pwd)"
clang++ -std=c++17 -O1 -fsanitize=fuzzer -fprofile-instr-generate -fcoverage-mapping \
  "$here/fuzz_readers.cpp" "$repo/io/src/read_point_cloud.cpp" "$repo/io/src/read_ply.cpp" "$repo/io/src/read_las.cpp" \
  -I "$repo/io/include" -o "$out/fuzz_readers_coverage"
cd "$out"
rm -f ./*.profraw
LLVM_PROFILE_FILE="$out/readers.profraw" ./fuzz_readers_coverage -runs=0 "$corpus" 2> coverage_run.log
llvm-profdata merge -sparse readers.profraw -o readers.profdata
llvm-cov report ./fuzz_readers_coverage -instr-profile=readers.profdata \
  "$repo/io/src/read_point_cloud.cpp" "$repo/io/src/read_ply.cpp" "$repo/io/src/read_las.cpp" "$repo/io/src/input_bytes.h"
