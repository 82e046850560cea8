#!/bin/bash
# The fast preset's study (issue 47 item 4): every candidate leaf rule x plane search, one JVM each,
# on four meshes, ray set R; tradeoff's totals at 1, 10 and 100 rays per triangle.
# usage: src/bench/fast-preset/run.sh JAR OUTDIR RUNS RAYS MESH...   (then: python3 src/bench/fast-preset/pick.py OUTDIR)
# The study of docs/sah.md ("Quality presets") ran it with RUNS 5, RAYS 1000000 on bunny.obj, its 2 x 2 grid
# (src/bench/grid_obj.py bunny.obj 2), scenes:clustered-spheres and src/bench/big_and_small_obj.py bunny.obj.
[ $# -ge 5 ] && [ -f "$1" ] || { echo "usage: run.sh JAR OUTDIR RUNS RAYS MESH... (JAR: target/kdtree.jar; MESH: an OBJ or scenes:NAME)" >&2; exit 2; }
jar=$1; out=$2; runs=$3; rays=$4; shift 4
mkdir -p "$out"
meshes=("$@")
cands=(
 "exact-l1|"
 "exact-l6|--leaf-below 6"
 "exact-l8|--leaf-below 8"
 "exact-l11|--leaf-below 11"
 "b32-l6|--algorithm binned --bins 32 --exact-below 32 --leaf-below 6"
 "b32-l8|--algorithm binned --bins 32 --exact-below 32 --leaf-below 8"
 "b32-l8-e16|--algorithm binned --bins 32 --exact-below 16 --leaf-below 8"
 "b32-l11|--algorithm binned --bins 32 --exact-below 32 --leaf-below 11"
 "b32-l11-e16|--algorithm binned --bins 32 --exact-below 16 --leaf-below 11"
 "b16-l8|--algorithm binned --bins 16 --exact-below 32 --leaf-below 8"
)
for m in "${meshes[@]}"; do
  name=$(basename "$m" .obj); name=${name#scenes:}
  for c in "${cands[@]}"; do
    id=${c%%|*}; opts=${c#*|}
    java -jar "$jar" tradeoff "$m" --quiet --runs "$runs" --ray-count "$rays" --counted-rays 1000 \
      --variants sah-exact-l0.8 $opts --csv "$out/$name--$id.csv" --chart "$out/$name--$id.png" >/dev/null 2>"$out/$name--$id.err" \
      || { echo "FAILED $name $id" >&2; cat "$out/$name--$id.err" >&2; }
    echo "$(date +%T) $name $id"
  done
done
