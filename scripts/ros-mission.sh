#!/usr/bin/env bash
# The default mission across ROS 1 nodes on this machine (docs/ros.md "One command"):
#   a master on 127.0.0.1, mrolr-ros-lab (the simulated lab: devices out, truth kept to itself),
#   mrolr-ros-bag (every topic into a bag with rosbag::Bag) and mrolr-ros-robot (the mission),
#   then everything it started is stopped, the bag closed, and the mission's summary printed.
#
#   scripts/ros-mission.sh [--world W.ini] [--plan P.ini] [--config C.ini] [--out DIR]
#                          [--bag OUT.bag] [--no-bag] [--rviz]
#
# --rviz also opens RViz on config/mrolr.rviz (the estimate with its covariance, the path, the map
# with its 95 % ellipsoids, tf, the recognised object, the left camera) and keeps the nodes up
# until RViz is closed.
# Nothing leaves the machine: ROS_MASTER_URI and ROS_IP are on loopback. Exit status: the robot
# node's (0 success, 3 the mission failed, 1 an error, 130/143 interrupted).
set -euo pipefail

ROOT=$(cd "$(dirname "$0")/.." && pwd)
BIN=${MROLR_BIN:-$ROOT/${BUILD_DIR:-build}/bin}
CONFIG=config/mission_sim.ini
WORLD="" PLAN="" OUT="" BAG="" NO_BAG=0 RVIZ=0

usage() { sed -n '2,15p' "$0" | sed 's/^# \{0,1\}//'; }
die() { echo "ros-mission: $*" >&2; exit 2; }
need_value() { [ $# -ge 2 ] && [ -n "$2" ] || die "$1 needs a value (see --help)"; }

while [ $# -gt 0 ]; do
  case "$1" in
    --world) need_value "$@"; WORLD=$2; shift 2 ;;
    --plan) need_value "$@"; PLAN=$2; shift 2 ;;
    --config) need_value "$@"; CONFIG=$2; shift 2 ;;
    --out) need_value "$@"; OUT=$2; shift 2 ;;
    --bag) need_value "$@"; BAG=$2; shift 2 ;;
    --no-bag) NO_BAG=1; shift ;;
    --rviz) RVIZ=1; shift ;;
    -h|--help) usage; exit 0 ;;
    *) die "unknown argument '$1' (see --help)" ;;
  esac
done

for b in mrolr-ros-lab mrolr-ros-robot mrolr-ros-bag; do
  [ -x "$BIN/$b" ] || die "$BIN/$b is not built (run 'make build'; ROS is found by scripts/install-deps.sh)"
done
[ "$RVIZ" = 0 ] || command -v rviz > /dev/null || die "rviz is not installed (run scripts/install-deps.sh)"
[ -x /usr/bin/rosmaster ] || die "/usr/bin/rosmaster is missing (run scripts/install-deps.sh)"
for f in "$CONFIG" ${WORLD:+"$WORLD"} ${PLAN:+"$PLAN"}; do
  [ -f "$f" ] || [ -f "$ROOT/$f" ] || die "no such file: $f"
done

[ -n "$OUT" ] || OUT="out/ros-mission-$(date -u +%Y%m%d-%H%M%S)"
mkdir -p "$OUT"
[ "$NO_BAG" = 1 ] || [ -n "$BAG" ] || BAG="$OUT/mission.bag"

# a free port on loopback, and everything of ROS kept on it and in the output folder
PORT=$(python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
export ROS_MASTER_URI="http://127.0.0.1:$PORT" ROS_IP=127.0.0.1 ROS_HOSTNAME=127.0.0.1
export ROS_HOME="$OUT/ros_home" ROS_LOG_DIR="$OUT/ros_log"

PIDS=()
stop_all() {
  # the bag last, so it still takes what the others publish while they stop
  for ((i = ${#PIDS[@]} - 1; i >= 0; i--)); do kill -TERM "${PIDS[$i]}" 2>/dev/null || true; done
  for pid in "${PIDS[@]}"; do
    for _ in $(seq 100); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -KILL "$pid" 2>/dev/null || true
    wait "$pid" 2>/dev/null || true
  done
  PIDS=()
}
trap 'stop_all' EXIT
trap 'echo "ros-mission: interrupted: the robot stops its mission, then the nodes stop" >&2' INT
trap 'kill -TERM "${ROBOT_PID:-}" 2>/dev/null || true' TERM

# the master, the lab and the bag in sessions of their own: Ctrl-C reaches the robot alone, which
# stops its mission safely while the devices still answer; then they are stopped here
setsid /usr/bin/rosmaster --core -p "$PORT" > "$OUT/rosmaster.log" 2>&1 &
PIDS+=($!)
for _ in $(seq 100); do
  python3 -c "import socket; socket.create_connection(('127.0.0.1', $PORT), 0.2)" 2>/dev/null && break
  sleep 0.1
done
echo "ros-mission: master on $ROS_MASTER_URI, outputs in $OUT"

WORLD_ARGS=() PLAN_ARGS=()
[ -n "$WORLD" ] && WORLD_ARGS=(--world "$WORLD")
[ -n "$PLAN" ] && PLAN_ARGS=(--plan "$PLAN")

if [ -n "$BAG" ]; then
  setsid "$BIN/mrolr-ros-bag" --out "$BAG" > "$OUT/bag.log" 2>&1 &
  PIDS+=($!)
  BAG_PID=$!
fi
setsid "$BIN/mrolr-ros-lab" --config "$CONFIG" "${WORLD_ARGS[@]}" --truth "$OUT/truth.rawlog" \
  > "$OUT/lab.log" 2>&1 &
PIDS+=($!)
LAB_PID=$!
if [ -n "$BAG" ]; then  # the recorder must be listening before the robot starts
  for _ in $(seq 100); do grep -q "recording into" "$OUT/bag.log" 2>/dev/null && break; sleep 0.1; done
fi

if [ "$RVIZ" = 1 ]; then
  rviz -d "$ROOT/config/mrolr.rviz" > "$OUT/rviz.log" 2>&1 &
  RVIZ_PID=$!
  PIDS+=($RVIZ_PID)
  sleep 5  # RViz subscribes before the robot starts
fi

status=0
"$BIN/mrolr-ros-robot" --config "$CONFIG" "${PLAN_ARGS[@]}" --out "$OUT" &
ROBOT_PID=$!
while :; do  # wait again when a signal interrupted the wait: the robot is still stopping
  wait "$ROBOT_PID" && status=0 || status=$?
  kill -0 "$ROBOT_PID" 2>/dev/null || break
done

if [ "$RVIZ" = 1 ]; then
  echo "ros-mission: the mission is over; close RViz to stop the nodes"
  wait "$RVIZ_PID" 2>/dev/null || true
fi
kill -0 "$LAB_PID" 2>/dev/null || echo "ros-mission: the lab node had stopped (see $OUT/lab.log)" >&2
stop_all
trap - EXIT
tail -n 1 "$OUT/lab.log" || true
if [ -n "$BAG" ]; then
  cat "$OUT/bag.log" | sed -n '/messages on/,$p'
fi
exit "$status"
