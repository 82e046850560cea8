#!/usr/bin/env bash
# What the workflow runs on every push (and what you may run yourself): the contract's tests on
# your builder, then the grade of your jar scored by rubric.json. Exits 1 if your builder breaks
# the contract; the log names the fault (the failing case, the method, the node).
# Usage: .github/classroom/grade.sh PATH/TO/kdtree.jar
set -uo pipefail
kdtree=$(realpath "${1:?"usage: $0 PATH/TO/kdtree.jar"}")
mvn=${MVN:-mvn}   # MVN="mvn -o" to build offline
cd "$(dirname "$0")/../.."
echo "== the contract's tests (mvn test)"
$mvn -B test
tests=$?
echo "== your jar"
$mvn -B -q package -DskipTests || { echo "your project does not package: see above"; exit 1; }
echo "== the grade"
# your own code on a runner of your own: graded without a box (a teacher's grade-class boxes it)
java -jar "$kdtree" grade --student-jar target/my-builder-1.0-SNAPSHOT.jar --no-sandbox --rubric rubric.json \
    -o target/grade.md --junit-xml target/grade.xml --quiet
grade=$?
[ "$tests" != 0 ] && echo "FAILED: the contract's tests fail (mvn test, above: each failure names its case)"
[ "$grade" = 1 ] && echo "FAILED: the grade says your builder breaks the contract (the checks marked FAIL above)"
[ "$grade" -gt 1 ] && echo "FAILED: your jar could not be graded (exit code $grade, the error above)"
[ "$tests" = 0 ] && [ "$grade" = 0 ] || exit 1
echo "passed: the contract's tests and the grade (your score above)"
