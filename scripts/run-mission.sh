#!/usr/bin/env bash
# `make mission`: runs the main job on the embedded simulated lab. Until the mission app exists it
# runs the most complete end-to-end program that does, and says which in one line.
set -euo pipefail
build=${1:-build}
bin="$build/bin"
stamp=$(date +%Y%m%d-%H%M%S)

if [ -x "$bin/mrolr-mission" ]; then
  exec "$bin/mrolr-mission" --config config/mission_sim.ini
elif [ -x "$bin/mrolr-sim" ] && [ -f maps/lab/world.ini ]; then
  echo "mission: the mission app does not exist yet; running the simulated lab recording (mrolr-sim) instead"
  exec "$bin/mrolr-sim" --world maps/lab/world.ini --out "out/sim-$stamp/lab.rawlog"
elif [ -x "$bin/mrolr-ekf-sim" ] && [ -f maps/lab_points/world.ini ]; then
  echo "mission: the mission app does not exist yet; running the EKF-SLAM Monte-Carlo simulator (mrolr-ekf-sim) instead"
  exec "$bin/mrolr-ekf-sim" --world maps/lab_points/world.ini --runs 10 --out "out/ekf-sim-$stamp"
elif [ -x "$bin/mrolr-head" ]; then
  echo "mission: the mission app does not exist yet; running the head model (mrolr-head) on a fixation round trip instead"
  "$bin/mrolr-head" fixate 0.5 -0.2 2
  exec "$bin/mrolr-head" measure 0.5 -0.2 2
else
  echo "mission: no end-to-end program has been built in $bin" >&2
  exit 1
fi
