#!/usr/bin/env bash
# Reproduces the experiments of Section 6 of Lejemble et al. 2021 (issue 5):
# convergence, robustness to position and normal noise, timings, pictures.
#
#   benchmark/paper_experiments.sh [--quick] [--out DIR] [--build DIR] [-- extra program options]
#
# Builds the program if needed (Release, in build-benchmark/ unless --build is given),
# installs gnuplot with apt-get if it is missing, runs every experiment and writes into DIR
# (default benchmark/results/, git-ignored): convergence.csv, noise_position.csv,
# noise_normals.csv, timings.csv, lidar.csv, sampler.csv, the plots (*.png, from the
# gnuplot scripts *.gp written beside them) and summary.md.
# --quick: smaller clouds and time budgets (under 2 minutes on 2 cores; CI runs it).
set -euo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"

quick=""
out="$repo/benchmark/results"
build="$repo/build-benchmark"
extra=()
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) quick="--quick" ;;
    --out) out="$2"; shift ;;
    --build) build="$2"; shift ;;
    --) shift; extra=("$@"); break ;;
    *) echo "usage: $0 [--quick] [--out DIR] [--build DIR] [-- program options]" >&2; exit 2 ;;
  esac
  shift
done
mkdir -p "$out"
out="$(cd "$out" && pwd)"

if ! command -v gnuplot >/dev/null 2>&1; then
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y --no-install-recommends gnuplot-nox
fi

start=$(date +%s)
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$repo" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
cmake --build "$build" --target paper_experiments -j"$(nproc)"
built=$(date +%s)

program="$build/benchmark/paper_experiments"
# Progress goes to stderr; the Markdown tables to stdout and summary.md.
"$program" $quick --out "$out" --data "$repo/data" ${extra[@]+"${extra[@]}"}

# Plots: every script is self-contained (data inline) and writes its PNG beside it.
(
  cd "$out"
  for script in *.gp; do
    gnuplot "$script" || echo "gnuplot could not draw $script (runs skipped by the time budget?)" >&2
  done
)
end=$(date +%s)
echo "build $((built - start)) s, experiments and plots $((end - built)) s; results in $out" >&2
