#!/usr/bin/env bash
# Side-by-side SPEC run: Embree 3 (C, Debian's libembree-dev) and this project's `raycast`,
# on one mesh, in one run, with the ratios printed last. Run from the project's root:
#
#   src/bench/compare.sh MESH.obj [--grid 4] [-- RAYCAST_OPTIONS...]
#
# MESH: any OBJ (the figures in docs/performance.md use the Stanford bunny, bunny.obj there).
# Examples:  ... bunny.obj -- --builder sah
#            ... bunny.obj --grid 4 -- --threads 2
# The Embree harness is built once into /tmp/kdtree-embree-bench (installs libembree-dev if
# missing). The project's jar must be built (mvn -q -B -DskipTests package).
# Ratios: build = project / Embree HIGH (and / MEDIUM); P and R = project / Embree (higher is better).
# JAVA (default: java) and JAVA_OPTS choose the JVM and its options for the project's run, e.g.
#   JAVA="$JDK25/bin/java" JAVA_OPTS="--add-modules jdk.incubator.vector" src/bench/compare.sh ...
# Embree's P traced as packets of 16 rays is printed on a '#' line (compare packets with packets).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
mesh=${1:?usage: compare.sh MESH.obj [--grid 4] [-- RAYCAST_OPTIONS...]}; shift
grid=1; extra=()
while [ $# -gt 0 ]; do
  case "$1" in
    --grid) grid=$2; shift 2 ;;
    --) shift; extra=("$@"); break ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
done
bin=/tmp/kdtree-embree-bench
if [ ! -x $bin ]; then
  if ! dpkg -s libembree-dev >/dev/null 2>&1; then
    export DEBIAN_FRONTEND=noninteractive
    apt-get install -y -qq libembree-dev >/dev/null 2>&1 || { apt-get update -qq >/dev/null && apt-get install -y -qq libembree-dev >/dev/null; }
  fi
  OUTBIN=$bin sh "$here/embree/build.sh"
fi
[ -f target/kdtree.jar ] || { echo "no target/kdtree.jar: run mvn -q -B -DskipTests package first" >&2; exit 2; }
emesh=$mesh
if [ "$grid" != 1 ]; then
  emesh=/tmp/kdtree-compare-grid$grid-$(basename "$mesh")
  [ -s "$emesh" ] || python3 "$here/grid_obj.py" "$mesh" "$grid" > "$emesh"
fi
e=$($bin "$emesh" 2>/dev/null)
eh=$(echo "$e" | grep '^embree3-high-1t' | tail -1)
em=$(echo "$e" | grep 'MEDIUM 1t build_ms=' | tail -1 | sed 's/.*build_ms=\([0-9.]*\).*/\1/')
jargs=(raycast "$mesh"); [ "$grid" != 1 ] && jargs+=(--grid "$grid")
k=$(${JAVA:-java} -Xmx12g ${JAVA_OPTS:-} -jar target/kdtree.jar "${jargs[@]}" "${extra[@]}" 2>/dev/null | grep '^kdtree' | tail -1)
[ -n "$eh" ] && [ -n "$k" ] || { echo "a run printed no SPEC line (embree: '${eh}', kdtree: '${k}')" >&2; exit 1; }
echo "$eh"; echo "#  embree MEDIUM 1t build_ms=$em"; echo "$e" | grep "packets of 16" | sed "s/^#  [^:]*:/#  embree/"; echo "$k"
read -r _ _ _ eb _ _ _ _ _ ep _ _ er <<<"$eh"
read -r _ _ _ kb _ _ _ _ _ kp _ _ kr <<<"$k"
python3 -c "print(f'ratios: build {float($kb)/float($eb):.2f} x Embree HIGH, {float($kb)/float($em):.2f} x MEDIUM; P {float($kp)/float($ep):.2f} x; R {float($kr)/float($er):.2f} x')"
