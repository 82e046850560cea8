#!/usr/bin/env bash
# Gradescope runs this once, as root, when it builds the autograder's image (Ubuntu): what the
# grader needs besides the files of the zip (kdtree.jar, rubric.json, run_autograder).
# A box for the student's JVM needs bubblewrap and util-linux; where the container cannot make one,
# run_autograder grades without it (see the handout, "Gradescope").
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq openjdk-17-jre-headless bubblewrap util-linux
java -version
