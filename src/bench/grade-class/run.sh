#!/usr/bin/env bash
# A class graded as a teacher grades it, timed: STUDENTS jars (default 100) made by MakeClass.java
# (five sound builders in ten, four broken ones, one hung or too slow), graded by one grade-class
# command in boxes, as many at once as the cores; then the first ten jars (one of each kind) graded
# one at a time (a class of one, --jobs 1), their rows compared with the class's.
# From the checkout, after mvn package:  src/bench/grade-class/run.sh [STUDENTS] [KDTREE_JAR]
# JAVA= runs another JVM (the grading JVM and, through it, the students').
set -euo pipefail
cd "$(dirname "$0")/../../.."
n=${1:-100}
jar=${2:-target/kdtree.jar}
java=${JAVA:-java}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$java" -cp "$jar" src/bench/grade-class/MakeClass.java "$work/class" "$n"
start=$(date +%s.%N)
"$java" -jar "$jar" grade-class "$work/class" -q --csv "$work/class.csv" --markdown "$work/class.md" | tail -n 3
end=$(date +%s.%N)
grep -m1 -o '^\*\*[0-9]* jars: .*\*\*' "$work/class.md"
awk -v s="$start" -v e="$end" -v n="$n" 'BEGIN { printf "%d jars graded in %.0f s (wall clock, the command as a whole)\n", n, e - s }'

mkdir "$work/alone"
for j in $(ls "$work/class" | head -n 10); do
    mkdir "$work/one" && cp "$work/class/$j" "$work/one/"
    "$java" -jar "$jar" grade-class "$work/one" -q --jobs 1 --csv "$work/one.csv" --markdown "$work/one.md" > /dev/null
    if [ ! -f "$work/alone.csv" ]; then cp "$work/one.csv" "$work/alone.csv"; else tail -n +2 "$work/one.csv" >> "$work/alone.csv"; fi
    rm -rf "$work/one" "$work/one.csv" "$work/one.md"
done
"$java" -cp "$jar" src/bench/grade-class/SameGrades.java "$work/class.csv" "$work/alone.csv"
