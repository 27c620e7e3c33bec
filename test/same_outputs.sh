#!/usr/bin/env bash
# The tool's outputs on a fixed set of runs, compared between two builds: for changes that must
# not change what users get (a refactor, a file split). Every run writes its file, its exit
# status and its stdout and stderr (the summary, warnings and errors, the times left out); the
# two builds must give the same bytes for each.
#
#   test/same_outputs.sh OLD_TOOL NEW_TOOL [WORK_DIR]
#
# OLD_TOOL, NEW_TOOL: two builds of build/tools/point_set_curvatures (e.g. one from a worktree
# of the commit before the change). Exit status 0 if every run matches, 1 otherwise (the runs
# that differ are listed). About a minute on 2 cores.
set -uo pipefail
if [ $# -lt 2 ]; then
  echo "usage: $0 OLD_TOOL NEW_TOOL [WORK_DIR]" >&2
  exit 2
fi
old=$(realpath "$1")
new=$(realpath "$2")
work=$(realpath -m "${3:-$(mktemp -d)}")
data=$(realpath "$(dirname "$0")/../data")
mkdir -p "$work"
export SOURCE_DATE_EPOCH=0  # (the LAS header's creation date)

# a cloud without normals (the first three columns of the Goursat sample) and a malformed one
awk 'NR > 1 && NR <= 5001 { print $1, $2, $3 }' "$data/goursat_010000.xyz" > "$work/goursat_xyz.xyz"
printf '0 0 0\n1 0\n' > "$work/malformed.xyz"

# name|expected exit status|input|output|options (no input: the options alone)
runs=(
  "help|0|||--help"
  "radius_color|0|$data/goursat_010000.xyz|out.ply|--radius 1.5 --color mean"
  "default_normals|0|$data/goursat_010000.xyz|out.csv|"
  "fixed_count|0|$data/goursat_010000.xyz|out.csv|--neighbors 40"
  "no_normals|0|$work/goursat_xyz.xyz|out.ply|"
  "no_normals_plane|0|$work/goursat_xyz.xyz|out.csv|--normal-fit plane --neighbors 30 --orient mst"
  "lidar_paper|0|$data/goursat-lidar.xyz|out.csv|--variant paper --neighbors 40"
  "las_scalar|0|$data/real/sample_c.las|out.ply|--ply-names scalar"
  "las_to_las|0|$data/real/sample_c.las|out.las|--float --neighbors 40"
  "las_tiled|0|$data/real/warsaw_small.las|out.csv|--neighbors 40 --orient +z --memory-limit 200K"
  "las_fields|0|$data/real/warsaw_small.las|out.csv|--fields mean,k_min,dmax,neighbors,valid --drop-attributes"
  "pss|0|$data/goursat_010000.xyz|out.ply|--method pss --neighbors 30 --ascii"
  "jet|0|$data/goursat_010000.xyz|out.csv|--method jet --neighbors 40"
  "apss|0|$data/goursat_010000.xyz|out.csv|--method apss --radius 1.5"
  "vcm|0|$data/goursat_010000.xyz|out.csv|--method vcm --radius 1.5"
  "wavejet|0|$data/goursat-lidar.xyz|out.csv|--method wavejet --neighbors 40"
  "barycenter|0|$data/goursat-lidar.xyz|out.csv|--method barycenter --radius 3.5x"
  "small_radius|3|$data/goursat-lidar.xyz|out.csv|--radius 0.01"
  "malformed|2|$work/malformed.xyz|out.csv|"
  "bad_option|2|$data/goursat-lidar.xyz|out.csv|--neighbors two"
)

differ=0
for run in "${runs[@]}"; do
  IFS='|' read -r name expected input output options <<< "$run"
  for side in old new; do
    dir="$work/$side/$name"
    rm -rf "$dir" && mkdir -p "$dir"
    tool=$old
    [ "$side" = new ] && tool=$new
    # (options split on spaces on purpose)
    # shellcheck disable=SC2086
    if [ -z "$input" ]; then
      (cd "$dir" && "$tool" $options > stdout 2> stderr; echo $? > status)
    else
      (cd "$dir" && "$tool" "$input" "$output" $options > stdout 2> stderr; echo $? > status)
    fi
    # times differ from run to run
    sed -i -E '/^  time  /d' "$dir/stdout"
  done
  # (a run that fails in both builds alike would pass unseen: each has its expected status)
  if [ "$(cat "$work/new/$name/status")" != "$expected" ]; then
    echo "unexpected: $name: exit status $(cat "$work/new/$name/status"), expected $expected" >&2
    differ=1
  fi
  for f in status stdout stderr ${output:+"$output"}; do
    [ ! -e "$work/old/$name/$f" ] && [ ! -e "$work/new/$name/$f" ] && continue  # (none written)
    if ! cmp -s "$work/old/$name/$f" "$work/new/$name/$f"; then
      echo "differ: $name: $f" >&2
      differ=1
    fi
  done
done
if [ "$differ" -ne 0 ]; then
  echo "the two builds differ (outputs in $work)" >&2
  exit 1
fi
echo "same outputs on ${#runs[@]} runs (in $work)"
