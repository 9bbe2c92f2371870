#!/usr/bin/env bash
# Rebuilds datasets/objects/*.wf from the simulated lab's turntable (issue 6, docs/model.md).
# Usage: scripts/build-object-models.sh [BUILD_DIR [OUT_DIR]]
#   (defaults: build, datasets/objects; another OUT_DIR lets the models be checked before they
#   replace the shipped ones, which other work may be reading)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
bin="$(cd "${1:-$root/build}" && pwd)/bin"
out="${2:-$root/datasets/objects}"
mkdir -p "$out"
out="$(cd "$out" && pwd)"
cd "$root"
# The grasp of each model (thesis 6.1(b): chosen by the user when the model is made) as x,y,z (mm,
# O) and yaw,pitch,roll (deg).
declare -A grasp=(
	[alphabet_cube]=0,0,30,0,0,0 [bottle]=0,0,100,0,0,0 [can]=0,0,60,0,0,0 [cup]=0,0,60,90,0,0
	[drink_package]=0,0,60,0,0,0 [hole_punch]=-10,0,40,0,0,0 [large_cup]=0,0,75,90,0,0
	[stapler]=0,0,30,0,0,0)
for o in alphabet_cube bottle can cup drink_package hole_punch large_cup stapler; do
	dir="$(mktemp -d)/tt_$o"
	"$bin/mrolr-sim" --world maps/lab/world.ini --turntable "$o" --out "$dir" --json >/dev/null
	"$bin/mrolr-model" build --turntable "$dir" --out "$out/$o.wf" \
		--truth "$dir/${o}_truth.wf" --json
	"$bin/mrolr-model" edit "$out/$o.wf" --grasp "${grasp[$o]}" >/dev/null
	rm -rf "$(dirname "$dir")"
done
