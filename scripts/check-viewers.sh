#!/usr/bin/env bash
# Opens a rawlog in MRPT's RawLogViewer and/or a .3Dscene in SceneViewer3D on a virtual X display
# (Xvfb), checks that each viewer is still running after loading the file, and saves a screenshot.
#   scripts/check-viewers.sh [--rawlog FILE.rawlog] [--scene FILE.3Dscene] [--out DIR] [--seconds N]
# Exit 0 when every viewer asked for stayed up; 1 when one exited early (its output is printed).
set -euo pipefail
rawlog="" scene="" out="out/viewer-check" secs=8
while [ $# -gt 0 ]; do
  case "$1" in
    --rawlog) rawlog=$2; shift 2 ;;
    --scene) scene=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --seconds) secs=$2; shift 2 ;;
    -h|--help) sed -n 2,5p "$0"; exit 0 ;;
    *) echo "check-viewers: unknown argument '$1' (try --help)" >&2; exit 2 ;;
  esac
done
[ -n "$rawlog$scene" ] || { echo "check-viewers: give --rawlog and/or --scene" >&2; exit 2; }
for f in $rawlog $scene; do [ -f "$f" ] || { echo "check-viewers: no such file: $f" >&2; exit 2; }; done
for tool in Xvfb xwd; do
  command -v $tool >/dev/null || { echo "check-viewers: $tool missing: run scripts/install-deps.sh" >&2; exit 1; }
done
mkdir -p "$out"
display=":$((90 + RANDOM % 100))"
Xvfb "$display" -screen 0 1280x900x24 >/dev/null 2>&1 &
xvfb_pid=$!
trap 'kill $xvfb_pid 2>/dev/null || true' EXIT
sleep 1

check() {  # name, program, file
  local name=$1 prog=$2 file=$3
  DISPLAY=$display LIBGL_ALWAYS_SOFTWARE=1 "$prog" "$(realpath "$file")" >"$out/$name.log" 2>&1 &
  local pid=$!
  sleep "$secs"
  if ! kill -0 $pid 2>/dev/null; then
    echo "check-viewers: $prog exited while loading $file:" >&2
    cat "$out/$name.log" >&2
    return 1
  fi
  DISPLAY=$display xwd -root -silent > "$out/$name.xwd"
  if [ -x /usr/bin/convert ]; then
    /usr/bin/convert "$out/$name.xwd" "$out/$name.png" && rm -f "$out/$name.xwd"
  fi
  kill $pid 2>/dev/null || true
  wait $pid 2>/dev/null || true
  echo "check-viewers: $prog stayed up with $file; screenshot in $out/$name.png"
}

status=0
[ -n "$rawlog" ] && { check rawlogviewer RawLogViewer "$rawlog" || status=1; }
[ -n "$scene" ] && { check sceneviewer SceneViewer3D "$scene" || status=1; }
exit $status
