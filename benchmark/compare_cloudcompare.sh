#!/usr/bin/env bash
# Side by side with CloudCompare, the point-cloud tool many users compute curvatures with
# (Tools > Other > Curvature, or its command line -CURV MEAN|GAUSS RADIUS): the same Goursat
# clouds of data/, the same radius, errors against the analytic surface
# (benchmark/goursat_errors.py) and the time of the curvature step.
#
#   benchmark/compare_cloudcompare.sh [--out DIR] [--build DIR] [--repetitions N] [--points N]
#
# Needs CloudCompare (Debian 12: apt-get install cloudcompare; run headless with
# QT_QPA_PLATFORM=offscreen, set here), python3-numpy, bc, and the package's tool and
# large_cloud program (built in DIR, default build/, if missing). Writes DIR (default
# benchmark/results/cloudcompare, git-ignored) and prints Markdown tables. Last, both are
# timed on a terrain of --points points (default 1000000, benchmark/large_cloud.cpp) at
# radius 3.5 (about 39 neighbours).
#
# Timing: CloudCompare has no per-step timer on its command line, so its curvature step is
# the difference between a run with -CURV and the same run without it (load and save only),
# each the best of N (default 3). The tool's is its own "curvatures" phase (also the best of
# N); both use every core.
set -euo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"

out="$repo/benchmark/results/cloudcompare"
build="$repo/build"
repetitions=3
points=1000000
while [ $# -gt 0 ]; do
  case "$1" in
    --out) out="$2"; shift ;;
    --build) build="$2"; shift ;;
    --repetitions) repetitions="$2"; shift ;;
    --points) points="$2"; shift ;;
    *) echo "usage: $0 [--out DIR] [--build DIR] [--repetitions N] [--points N]" >&2; exit 2 ;;
  esac
  shift
done
if ! command -v CloudCompare >/dev/null 2>&1; then
  echo "$0: CloudCompare is not installed (Debian 12: apt-get install cloudcompare)" >&2
  exit 2
fi
python=/usr/bin/python3
[ -x "$python" ] || python=python3
tool="$build/tools/point_set_curvatures"
if [ ! -x "$tool" ] || [ ! -x "$build/benchmark/large_cloud" ]; then
  cmake -S "$repo" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$build" -j"$(nproc)" --target point_set_curvatures_tool large_cloud
fi
mkdir -p "$out"
out="$(cd "$out" && pwd)"
export QT_QPA_PLATFORM=offscreen

# least A B: the smaller of two numbers (A when B is empty)
least() {
  if [ -z "$2" ] || [ "$(echo "$1 < $2" | bc -l)" = 1 ]; then echo "$1"; else echo "$2"; fi
}

# best_of N COMMAND...: the least wall time of N runs, in seconds
best_of() {
  local n="$1"; shift
  local best="" t0 t1
  for _ in $(seq "$n"); do
    t0=$(date +%s.%N)
    "$@" >/dev/null 2>&1
    t1=$(date +%s.%N)
    best=$(least "$(echo "$t1 - $t0" | bc -l)" "$best")
  done
  echo "$best"
}

# cc_seconds CLOUD RADIUS OUTPUT: CloudCompare's -CURV MEAN step, the best of N runs with it
# (writing OUTPUT) less the best of N runs without it
cc_seconds() {
  local cc=(CloudCompare -SILENT -AUTO_SAVE OFF -O "$1")
  local base with
  base=$(best_of "$repetitions" "${cc[@]}" -C_EXPORT_FMT ASC -SAVE_CLOUDS FILE "$out/plain.asc")
  with=$(best_of "$repetitions" "${cc[@]}" -CURV MEAN "$2" -C_EXPORT_FMT ASC -SAVE_CLOUDS FILE "$3")
  # on small clouds the step is below the noise of two process times
  echo "d = $with - $base; if (d < 0) d = 0; d" | bc -l
}

# tool_steps INPUT PREFIX EXTENSION RADIUS CC_SECONDS: runs the tool's methods on INPUT (the
# best of N runs each, written to PREFIX-METHOD.EXTENSION) and prints the time of their
# curvature phases beside CloudCompare's
tool_steps() {
  local m t best times=()
  for m in aso paper pss jet; do
    local args=(--method "$m")
    [ "$m" = paper ] && args=(--method aso --variant paper)
    best=""
    for _ in $(seq "$repetitions"); do
      t=$("$tool" "$1" "$2-$m.$3" "${args[@]}" --radius "$4" 2>&1 | sed -n 's/.*curvatures \([0-9.]*\),.*/\1/p' | head -1)
      best=$(least "$t" "$best")
    done
    times+=("$best")
  done
  printf 'curvature step (s): ASO default %s, paper %s, PSS %s, jets %s; CloudCompare (MEAN) %.3f\n' \
    "${times[@]}" "$5"
}

for spec in "goursat_010000 1.5" "goursat_050000 1.0" "goursat_050000 1.5" "goursat-lidar 1.4"; do
  set -- $spec
  cloud="$1" r="$2"
  # CloudCompare's ASCII reader takes the comment line for a malformed point: drop it
  grep -v '^#' "$repo/data/$cloud.xyz" > "$out/$cloud.xyz"
  CloudCompare -SILENT -AUTO_SAVE OFF -O "$out/$cloud.xyz" -CURV GAUSS "$r" -C_EXPORT_FMT ASC \
    -SAVE_CLOUDS FILE "$out/$cloud-$r-cc-GAUSS.asc" >/dev/null 2>&1
  cc_time=$(cc_seconds "$out/$cloud.xyz" "$r" "$out/$cloud-$r-cc-MEAN.asc")
  steps=$(tool_steps "$repo/data/$cloud.xyz" "$out/$cloud-$r" csv "$r" "$cc_time")
  echo
  echo "### $cloud.xyz, r = $r (errors x1e-3)"
  echo
  "$python" "$repo/benchmark/goursat_errors.py" "$out/$cloud.xyz" \
    "ASO, default=$out/$cloud-$r-aso.csv" "ASO, paper's variant=$out/$cloud-$r-paper.csv" \
    "PSS=$out/$cloud-$r-pss.csv" "osculating jets (CGAL)=$out/$cloud-$r-jet.csv" \
    "CloudCompare 2.11 -CURV=$out/$cloud-$r-cc-MEAN.asc:cc_mean" \
    "CloudCompare 2.11 -CURV=$out/$cloud-$r-cc-GAUSS.asc:cc_gauss"
  echo
  echo "$steps"
done

# timing on a large cloud (no analytic curvature: time only)
"$build/benchmark/large_cloud" "$points" "$out/terrain.ply" >/dev/null
echo
echo "### terrain of $points points (large_cloud), r = 3.5"
echo
tool_steps "$out/terrain.ply" "$out/terrain" ply 3.5 "$(cc_seconds "$out/terrain.ply" 3.5 "$out/plain.asc")"
