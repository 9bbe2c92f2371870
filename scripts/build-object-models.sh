#!/usr/bin/env bash
# Rebuilds datasets/objects/*.wf from the simulated lab's turntable (issue 6, docs/model.md).
# Usage: scripts/build-object-models.sh [BUILD_DIR]   (default: build)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
bin="${1:-$root/build}/bin"
cd "$root"
for o in alphabet_cube bottle can cup drink_package hole_punch large_cup stapler; do
	dir="$(mktemp -d)/tt_$o"
	"$bin/mrolr-sim" --world maps/lab/world.ini --turntable "$o" --out "$dir" --json >/dev/null
	"$bin/mrolr-model" build --turntable "$dir" --out "datasets/objects/$o.wf" \
		--truth "$dir/${o}_truth.wf" --json
	rm -rf "$(dirname "$dir")"
done
