#!/usr/bin/env bash
# Render the thesis gallery (docs/gallery.md) and the gallery of the 15
# regular honeycombs and of some uniform ones (docs/honeycombs.md): every
# scenes/thesis/fig*.hsc, scenes/honeycomb-p-q-r.hsc and
# scenes/uniform-*.hsc becomes docs/gallery/<same name>.png, at the
# resolution the scene file sets (at most 400 pixels wide), with 4 samples
# per pixel for anti-aliasing, deflated at zlib level 6 (smaller files for
# the repository than the default 3; the same samples).
#
# Usage: docs/gallery/render.sh [SCENE...]   (default: all of them)
# Environment: SAMPLES (default 4), THREADS (default: all cores).
set -euo pipefail

root=$(cd "$(dirname "$0")/../.." && pwd)
cd "$root"

cargo build --release --quiet
bin=target/release/hscene
out=docs/gallery
samples=${SAMPLES:-4}
threads=()
if [[ -n "${THREADS:-}" ]]; then threads=(--threads "$THREADS"); fi

if [[ $# -gt 0 ]]; then
    scenes=("$@")
else
    scenes=(scenes/thesis/fig*.hsc scenes/honeycomb-?-?-?.hsc scenes/uniform-*.hsc)
fi

start=$(date +%s.%N)
for scene in "${scenes[@]}"; do
    name=$(basename "$scene" .hsc)
    t0=$(date +%s.%N)
    "$bin" render "$scene" -o "$out/$name.png" --samples "$samples" --png-level 6 "${threads[@]}"
    t1=$(date +%s.%N)
    printf '%-40s %6.2f s\n' "$name.png" "$(echo "$t1 - $t0" | bc)"
done
end=$(date +%s.%N)
printf '%-40s %6.2f s\n' "total (${#scenes[@]} images)" "$(echo "$end - $start" | bc)"
