#!/usr/bin/env bash
# Installs every Debian 12 package MROLR needs to build, test and run. Idempotent: it asks dpkg-query
# first and calls apt-get only for what is missing, so a second run takes well under a second.
set -euo pipefail

PACKAGES=(
  build-essential cmake make pkg-config git ccache
  libmrpt-dev mrpt-apps mrpt-common
  libeigen3-dev nlohmann-json3-dev
  libopencv-dev libopencv-contrib-dev
  libopengv-dev
  liborocos-kdl-dev
  libgtest-dev libgmock-dev googletest
  libbenchmark-dev
  xvfb xauth x11-apps imagemagick xdotool
  # ROS 1 from Debian (the ros area, docs/ros.md): libmrpt-dev already brings roscpp,
  # rosbag_storage, cv_bridge, tf2 and sensor/geometry/stereo messages; a master on loopback;
  # RViz to watch the robot (scripts/ros-mission.sh --rviz)
  python3-rosmaster rosout rviz
  libnav-msgs-dev libtrajectory-msgs-dev libtf2-ros-dev libvisualization-msgs-dev
)

missing=()
for p in "${PACKAGES[@]}"; do
  status=$(dpkg-query -W -f='${db:Status-Status}' "$p" 2>/dev/null || true)
  [ "$status" = "installed" ] || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PACKAGES[@]} packages present"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: not root and no sudo; install: ${missing[*]}" >&2; exit 1; }
  SUDO="sudo"
fi

echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
echo "install-deps: done"
