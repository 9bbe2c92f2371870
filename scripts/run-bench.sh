#!/usr/bin/env bash
# Runs every Google Benchmark program built from bench/ and writes its JSON next to the binaries.
set -euo pipefail
build=${1:-build}
bindir="$build/bench/bin"
outdir="$build/bench"
mkdir -p "$outdir"
shopt -s nullglob
progs=("$bindir"/*)
if [ ${#progs[@]} -eq 0 ]; then
  echo "run-bench: no benchmark programs in $bindir" >&2
  exit 1
fi
for prog in "${progs[@]}"; do
  [ -x "$prog" ] || continue
  name=$(basename "$prog")
  echo "== $name"
  "$prog" --benchmark_out="$outdir/$name.json" --benchmark_out_format=json
done
echo "run-bench: JSON results in $outdir/"
