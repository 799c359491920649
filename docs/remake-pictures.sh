#!/usr/bin/env bash
# Remake the pictures of docs/ from their scenes, as docs/pictures.txt
# lists them (the one list of which scene makes which picture, also read
# by tests/docs.rs). PNGs are deflated at zlib level 6 (smaller files for
# the repository than the default 3; the same samples).
#
# Usage: docs/remake-pictures.sh [PICTURE...]   (default: every one;
#        e.g. docs/remake-pictures.sh docs/showcase/path-honeycomb-353-sky.png,
#        or every picture under a folder: docs/remake-pictures.sh docs/gallery/)
# Environment: THREADS (default: all cores). `export` pictures need
# Mitsuba 3 (pip install mitsuba) and are skipped, with a note, without it.
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"

cargo build --release --quiet
bin=target/release/hscene
threads=()
if [[ -n "${THREADS:-}" ]]; then threads=(--threads "$THREADS"); fi

wanted() {
    [[ $# -eq 1 ]] && return 0
    local pic=$1; shift
    for w in "$@"; do [[ $pic == "$w" || ( $w == */ && $pic == "$w"* ) ]] && return 0; done
    return 1
}

start=$(date +%s.%N)
count=0
while read -r kind pic scene opts; do
    [[ -z "$kind" || "$kind" == \#* ]] && continue
    wanted "$pic" "$@" || continue
    read -ra options <<< "${opts:-}"
    t0=$(date +%s.%N)
    case "$kind" in
        render)
            level=()
            [[ $pic == *.png ]] && level=(--png-level 6)
            "$bin" render "$scene" -o "$pic" "${options[@]}" "${level[@]}" "${threads[@]}" --force
            ;;
        export)
            if ! python3 -c 'import mitsuba' 2>/dev/null; then
                echo "note: $pic skipped: Mitsuba 3 is not installed" >&2
                continue
            fi
            mesh=$(mktemp --suffix .glb)
            "$bin" export "$scene" -o "$mesh" "${options[@]}" --force
            python3 docs/export/render_outside.py "$mesh" "$pic" --spp 64 --size 480
            rm -f "$mesh"
            ;;
        *) echo "docs/pictures.txt: unknown kind '$kind'" >&2; exit 2 ;;
    esac
    t1=$(date +%s.%N)
    count=$((count + 1))
    printf '%-50s %7.2f s\n' "$pic" "$(echo "$t1 - $t0" | bc)"
done < docs/pictures.txt
end=$(date +%s.%N)
printf '%-50s %7.2f s\n' "total ($count pictures)" "$(echo "$end - $start" | bc)"
